#!/usr/bin/env bash
# FPS of rviz drawing the avatar while orbiting it: Xvfb + Mesa llvmpipe on one core
# (LP_NUM_THREADS=1, taskset), 1280x800, transparency on and off: SDH-046 pre-op, SDH-101
# (the pain trigger's relief on its L4 band) with the relief shader and pre-shaded, a full
# status in noise and a full status in relief (shader and pre-shaded).
# usage: bench/avatar/run_avatar_fps.sh [FRAMES]   (from the workspace root)
set -euo pipefail
cd "$(dirname "$0")/../../../.."
export PATH=/usr/bin:/bin:$PATH
set +u; source devel/setup.bash; set -u
FRAMES=${1:-360}
DIR=$(mktemp -d); chmod 700 "$DIR"
trap 'rm -rf "$DIR"' EXIT
for sample in fig4_6_patient.json cases.json; do
  devel/lib/vicc_anatomy_viz/vicc_patient import "src/vicc_anatomy_viz/data/samples/$sample" \
    --db "$DIR/p.db" > /dev/null
done
unset DISPLAY
CORE=$(( $(nproc) - 1 ))
for aa in "" "--no-aa"; do
  for run in "SDH-046 2023-03-06" "SDH-101 2023-05-02" "SDH-101 2023-05-02 --pre-shaded" \
             "SDH-046 2023-03-06 --full" "SDH-046 2023-03-06 --full --relief" \
             "SDH-046 2023-03-06 --full --relief --pre-shaded"; do
    set -- $run
    patient=$1 date=$2; shift 2
    echo "== $patient $date ${*:-(its own status)} ${aa:-(rviz default 4x MSAA)}, one core (cpu $CORE), LP_NUM_THREADS=1"
    LP_NUM_THREADS=1 taskset -c "$CORE" devel/lib/vicc_anatomy_viz/vicc_avatar_fps --db "$DIR/p.db" \
      --patient "$patient" --date "$date" --size 1280x800 --frames "$FRAMES" "$@" $aa 2>&1 \
      | grep -E "^(status|transparency|display off)"
  done
done
uptime
