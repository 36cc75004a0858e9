#!/usr/bin/env bash
# FPS of rviz drawing the avatar while orbiting it: Xvfb + Mesa llvmpipe on one core
# (LP_NUM_THREADS=1, taskset), 1280x800, transparency on and off, SDH-046 pre-op and a full
# status. usage: bench/avatar/run_avatar_fps.sh [FRAMES]   (from the workspace root)
set -euo pipefail
cd "$(dirname "$0")/../../../.."
export PATH=/usr/bin:/bin:$PATH
set +u; source devel/setup.bash; set -u
FRAMES=${1:-360}
DIR=$(mktemp -d); chmod 700 "$DIR"
trap 'rm -rf "$DIR"' EXIT
devel/lib/vicc_anatomy_viz/vicc_patient import src/vicc_anatomy_viz/data/samples/fig4_6_patient.json \
  --db "$DIR/p.db" > /dev/null
unset DISPLAY
CORE=$(( $(nproc) - 1 ))
for aa in "" "--no-aa"; do
  for full in "" "--full"; do
    echo "== SDH-046 2023-03-06 ${full:-(its own status)} ${aa:-(rviz default 4x MSAA)}, one core (cpu $CORE), LP_NUM_THREADS=1"
    LP_NUM_THREADS=1 taskset -c "$CORE" devel/lib/vicc_anatomy_viz/vicc_avatar_fps --db "$DIR/p.db" \
      --patient SDH-046 --date 2023-03-06 --size 1280x800 --frames "$FRAMES" $full $aa 2>&1 \
      | grep -E "^(status|transparency|display off)"
  done
done
uptime
