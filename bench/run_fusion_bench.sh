#!/usr/bin/env bash
# Surfel fusion benchmark (issue "Scanning II"): thesis Tables 5.2-5.5 rerun with frame-to-model
# tracking next to the frame-to-frame runs of run_tracking_bench.sh, reconstruction accuracy and
# completeness against the simulator's true surface, speed of the whole pipeline, and the
# resolution target. Writes bench/results/fusion_tables.md (raw JSON in bench/out/).
#   usage: bench/run_fusion_bench.sh [SCENARIO...]   (default: hen hen_duplo office hen_slow)
set -euo pipefail
cd "$(dirname "$0")/.."
source bench/common.sh "$@"

make_bag() {  # scenario: bag, ground truth and true surface, regenerated when the YAML changes
  local scenario=$1 bag=$OUT/$1.bag
  if [ ! -f "$bag" ] || [ ! -f "$OUT/${scenario}_surface.ply" ] ||
     [ "src/vicc_tracking/config/scenarios/$scenario.yaml" -nt "$bag" ]; then
    rosrun vicc_tracking vicc_make_bag "$scenario" --out "$bag" --gt "$OUT/${scenario}_gt.tum" \
      --surface "$OUT/${scenario}_surface.ply" 2>/dev/null
  fi
}

for scenario in "${SCENARIOS[@]}"; do
  make_bag "$scenario"
  for init in "${INITS[@]}"; do
    for step in 1 2 4; do
      for levels in 3 2 1; do
        report=$OUT/${scenario}_${init}_s${step}_l${levels}_f2m.json
        echo "bench: $scenario frame-to-model --init $init --frame-step $step --levels $levels" >&2
        # shellcheck disable=SC2046
        taskset -c 0 rosrun vicc_fusion vicc_reconstruct "$OUT/$scenario.bag" $(init_args "$init") \
          --frame-step "$step" --levels "$levels" --gt "$OUT/${scenario}_gt.tum" \
          --truth-surface "$OUT/${scenario}_surface.ply" --report "$report" --quiet \
          2>/dev/null || echo "bench: run failed: $report" >&2
      done
    done
  done
done

# Speed: a separate pass at the end, one run at a time on one core, so that the timings of
# the table are not those of runs that overlapped with building or other jobs.
for scenario in "${SCENARIOS[@]}"; do
  for levels in 3 1; do
    taskset -c 0 rosrun vicc_fusion vicc_reconstruct "$OUT/$scenario.bag" --levels "$levels" \
      --report "$OUT/${scenario}_ekf_s1_l${levels}_f2m_speed.json" --quiet 2>/dev/null
  done
done

# The resolution target: which slots the model resolves (thesis Fig. 5.3).
make_bag resolution_target
target=$OUT/resolution_target
taskset -c 0 rosrun vicc_fusion vicc_reconstruct "$target.bag" --gt "${target}_gt.tum" \
  --truth-surface "${target}_surface.ply" --cloud "${target}_cloud.ply" \
  --trajectory "${target}_est.tum" --report "${target}_f2m.json" --quiet 2>/dev/null
/usr/bin/python3 bench/fusion/resolution_target.py \
  src/vicc_tracking/config/scenarios/resolution_target.yaml "${target}_cloud.ply" \
  "${target}_est.tum" "${target}_gt.tum" > "$OUT/resolution_target.md"

/usr/bin/python3 bench/fusion/fusion_tables.py "$OUT" "${SCENARIOS[@]}" > bench/results/fusion_tables.md
echo "bench: wrote bench/results/fusion_tables.md" >&2
