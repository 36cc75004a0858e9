#!/usr/bin/env bash
# `make demo`: simulate a hand-held scan of the Hen scene, track it offline with the thesis's
# EKF initialisation and with the identity (KinectFusion) baseline, then run the live
# simulated rig + tracker (rviz when a display is available; a screenshot under Xvfb otherwise).
set -euo pipefail
cd "$(dirname "$0")/.."
export PATH=/usr/bin:/bin:$PATH
set +u; source devel/setup.bash; set -u

SCENARIO=${SCENARIO:-hen}
OUT=bags/demo
mkdir -p "$OUT"
BAG=bags/${SCENARIO}.bag
if [ ! -f "$BAG" ]; then
  echo "== simulating the '$SCENARIO' recording into $BAG"
  rosrun vicc_tracking vicc_make_bag "$SCENARIO" --out "$BAG" --gt "bags/${SCENARIO}_gt.tum"
fi

echo
echo "== offline tracking, every 2nd frame (the thesis's '1/2'), two pyramid levels"
for init in ekf identity; do
  echo "-- --init $init"
  rosrun vicc_fusion vicc_reconstruct "$BAG" --init "$init" --levels 2 --frame-step 2 \
    --gt "bags/${SCENARIO}_gt.tum" --trajectory "$OUT/${SCENARIO}_${init}.tum" \
    --report "$OUT/${SCENARIO}_${init}.json" --cloud "$OUT/${SCENARIO}_${init}.ply" --quiet || true
done
echo "(reports, trajectories and clouds in $OUT/)"

DEMO_SECONDS=${DEMO_SECONDS:-25}
echo
if [ -n "${DISPLAY:-}" ]; then
  echo "== live: simulated rig + tracker + rviz (Ctrl-C to stop)"
  roslaunch launch/rig_sim.launch scenario:="$SCENARIO"
else
  echo "== live (headless, ${DEMO_SECONDS} s): simulated rig + tracker + rviz under Xvfb"
  bash scripts/rviz_screenshot.sh "$SCENARIO" "$DEMO_SECONDS" docs/tracking_demo.png
fi
