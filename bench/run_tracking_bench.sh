#!/usr/bin/env bash
# Reproduces thesis Tables 5.2-5.5 on our simulated scenarios: for every scenario, frame step
# (All = 1, 1/2 = 2, 1/4 = 4), pyramid levels (3, 2, 1) and ICP initialisation strategy, the
# loop-closure drift, ICP iterations and failures, measured by vicc_reconstruct on the same
# recording. Writes bench/results/tracking_tables.md (and the raw JSON reports in bench/out/).
#   usage: bench/run_tracking_bench.sh [SCENARIO...]   (default: hen hen_duplo office hen_slow)
#   BENCH_INITS="ekf ekf_thesis_noise" runs only those columns (the others keep their reports in
#   bench/out), BENCH_PEER=0 skips the OpenCV peer.
set -euo pipefail
cd "$(dirname "$0")/.."
source bench/common.sh "$@"

for scenario in "${SCENARIOS[@]}"; do
  bag=$OUT/$scenario.bag
  if [ ! -f "$bag" ] || [ "src/vicc_tracking/config/scenarios/$scenario.yaml" -nt "$bag" ]; then
    rosrun vicc_tracking vicc_make_bag "$scenario" --out "$bag" --gt "$OUT/${scenario}_gt.tum" 2>/dev/null
  fi
  for init in "${TRACKING_INITS[@]}"; do
    for step in 1 2 4; do
      for levels in 3 2 1; do
        report=$OUT/${scenario}_${init}_s${step}_l${levels}.json
        echo "bench: $scenario --init $init --frame-step $step --levels $levels" >&2
        # One core: the speed figures are single-threaded. Frame-to-frame tracking alone (the
        # tracking issue's pipeline); bench/run_fusion_bench.sh reruns it frame-to-model.
        # shellcheck disable=SC2046
        taskset -c "$BENCH_CPU" rosrun vicc_fusion vicc_reconstruct "$bag" $(init_args "$init") --frame-step "$step" \
          --levels "$levels" --gt "$OUT/${scenario}_gt.tum" --report "$report" --quiet --no-fusion \
          2>/dev/null || echo "bench: run failed: $report" >&2
      done
    done
  done
  # The peer: OpenCV's cv::rgbd::ICPOdometry, identity initialisation, the same frames.
  [ "$BENCH_PEER" = 1 ] || continue
  for step in 1 2 4; do
    for levels in 3 2 1; do
      echo "bench: $scenario peer cv::rgbd::ICPOdometry --frame-step $step --levels $levels" >&2
      taskset -c "$BENCH_CPU" rosrun vicc_fusion vicc_peer_odometry "$bag" --frame-step "$step" \
        --levels "$levels" --gt "$OUT/${scenario}_gt.tum" \
        --report "$OUT/${scenario}_peer_s${step}_l${levels}.json" 2>/dev/null ||
        echo "bench: peer run failed" >&2
    done
  done
done

/usr/bin/python3 bench/tracking_tables.py "$OUT" "${SCENARIOS[@]}" > bench/results/tracking_tables.md
echo "bench: wrote bench/results/tracking_tables.md" >&2
