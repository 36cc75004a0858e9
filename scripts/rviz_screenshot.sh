#!/usr/bin/env bash
# Runs the simulated rig + tracker + rviz under a virtual display for N seconds and saves a
# screenshot: usage rviz_screenshot.sh SCENARIO SECONDS OUT.png
set -euo pipefail
cd "$(dirname "$0")/.."
export PATH=/usr/bin:/bin:$PATH
SCENARIO=${1:-hen}
SECONDS_TO_RUN=${2:-25}
PNG=${3:-docs/tracking_demo.png}
mkdir -p "$(dirname "$PNG")"
LOG=$(mktemp -d)/roslaunch.log

xvfb-run -a -s "-screen 0 1280x800x24" bash -c "
  set +u; source devel/setup.bash; set -u
  export ROS_MASTER_URI=http://localhost:\$((11400 + RANDOM % 500))
  roslaunch -p \${ROS_MASTER_URI##*:} launch/rig_sim.launch scenario:=$SCENARIO > $LOG 2>&1 &
  LAUNCH=\$!
  sleep $SECONDS_TO_RUN
  import -window root '$PNG'
  kill -INT \$LAUNCH; wait \$LAUNCH || true
"
echo "screenshot: $PNG (roslaunch log: $LOG)"
grep -E "tracker: (tracking|ready)|fusion:|lost|ERROR|FATAL" "$LOG" | head -20 || true
