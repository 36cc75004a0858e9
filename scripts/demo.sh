#!/usr/bin/env bash
# `make demo` (after `make build`, which installs the dependencies and builds): the whole graph
# headless on the committed recording bags/short_test.bag and the sample patient SDH-046
# (thesis Fig. 4.6). Leaves in out/ (OUT=DIR to change):
#   trajectory.tum, model.ply, reconstruction_report.json  offline reconstruction
#   rviz_demo.png                    rviz (launch/demo.rviz) on the live replayed graph
#   avatar_preoperative.png, avatar_postoperative.png      vicc_avatar_snapshot
#   glyphs/icp_*.png                 the intracranial-pressure glyph for three readings
#   patients.db, demo_roslaunch.log
# and prints a summary. With a display it then opens the graph in rviz (Ctrl-C ends it).
set -euo pipefail
cd "$(dirname "$0")/.."
export PATH=/usr/bin:/bin:$PATH
set +u; source devel/setup.bash; set -u

OUT=${OUT:-out}
BAG=${BAG:-bags/short_test.bag}
TRUTH=${BAG%.bag}_gt.tum
SAMPLE=src/vicc_anatomy_viz/data/samples/fig4_6_patient.json
# out/ holds the sample patient's database and pictures of their status: private (0700 / 0600),
# as vicc_patient demands of a patient database's directory.
umask 077
mkdir -p "$OUT/glyphs"
chmod 700 "$OUT"
STEP=0
step() { STEP=$((STEP + 1)); echo; echo "== [$STEP/6] $*"; }
# Prints a dot every second while the command in the background ($1 = pid) runs.
progress() { while kill -0 "$1" 2>/dev/null; do printf '.'; sleep 1; done; echo; }

step "offline reconstruction of $BAG (vicc_reconstruct: tracking + surfel fusion)"
rosrun vicc_fusion vicc_reconstruct "$BAG" --gt "$TRUTH" --trajectory "$OUT/trajectory.tum" \
  --cloud "$OUT/model.ply" --report "$OUT/reconstruction_report.json" --quiet &
RECONSTRUCT=$!
progress $RECONSTRUCT
wait $RECONSTRUCT

step "sample patient database from $SAMPLE"
rm -f "$OUT/patients.db" "$OUT/patients.db-wal" "$OUT/patients.db-shm"
rosrun vicc_anatomy_viz vicc_patient import "$SAMPLE" --db "$OUT/patients.db" > /dev/null

step "avatar snapshots (vicc_avatar_snapshot, pre- and post-operative status)"
for when in preoperative:2023-03-06T09:15:00Z postoperative:; do
  name=${when%%:*} date=${when#*:}
  xvfb-run -a -s "-screen 0 1280x1024x24" rosrun vicc_anatomy_viz vicc_avatar_snapshot \
    --db "$OUT/patients.db" --patient SDH-046 ${date:+--date "$date"} --size 600x900 \
    --out "$OUT/avatar_$name.png"
done

step "glyph figures (vicc_glyph design: intracranial pressure normal / elevated / pathological)"
DESIGN=src/vicc_glyphs/designs/intracranial_pressure.yaml
for reading in normal:10:0 elevated:18:1 pathological:30:2; do
  IFS=: read -r name pressure category <<< "$reading"
  rosrun vicc_glyphs vicc_glyph design "$DESIGN" --values "pressure=$pressure,category=$category" \
    --out "$OUT/glyphs/icp_$name.png" > /dev/null
done

step "live graph headless: launch/demo.launch (replay + fusion, patient and glyph servers, rviz)"
LOG=$OUT/demo_roslaunch.log
PORT=$((11400 + RANDOM % 500))
xvfb-run -a -s "-screen 0 1280x800x24" bash -c "
  export ROS_MASTER_URI=http://localhost:$PORT
  roslaunch -p $PORT launch/demo.launch bag:=\$PWD/$BAG db:=\$PWD/$OUT/patients.db > $LOG 2>&1 &
  LAUNCH=\$!
  # until the player has played the whole recording (the graph stays up)
  sleep 8
  while rosnode list 2>/dev/null | grep -qx /player || ! rosnode list 2>/dev/null | grep -qx /rviz; do
    sleep 1
    kill -0 \$LAUNCH 2>/dev/null || break
  done
  # rviz (slow to start on a busy machine) must have subscribed to the model: the fusion node
  # then sends it the final model within ~1 s of the last frame; give rviz time to draw it.
  for _ in \$(seq 60); do
    rostopic info /fusion/model 2>/dev/null | grep -q '/rviz' && break
    sleep 1
  done
  sleep 5
  import -window root '$OUT/rviz_demo.png'
  kill -INT \$LAUNCH; wait \$LAUNCH
" &
LIVE=$!
progress $LIVE
wait $LIVE

step "summary"
python3 - "$OUT" "$SECONDS" <<'EOF'
import json, os, sys
out, seconds = sys.argv[1], float(sys.argv[2])
report = json.load(open(os.path.join(out, "reconstruction_report.json")))
error = report.get("ground_truth_error", {})
surfels = report.get("surfels", {}).get("stable", "?")
frames = report.get("frames", {})
print(f"reconstruction: ATE RMSE {1000 * error.get('rmse_position_m', float('nan')):.2f} mm "
      f"vs the ground truth, {surfels} stable surfels, "
      f"{report.get('frames_per_second', 0):.1f} frames/s ({report.get('wall_time_s', 0):.1f} s); "
      f"the demo took {seconds:.0f} s")
print(f"  frames: {frames}")
files = [("trajectory (TUM)", "trajectory.tum"), ("model (PLY)", "model.ply"),
         ("reconstruction report", "reconstruction_report.json"),
         ("rviz: reconstruction + avatar", "rviz_demo.png"),
         ("avatar, pre-operative", "avatar_preoperative.png"),
         ("avatar, post-operative", "avatar_postoperative.png"),
         ("glyph: ICP normal", "glyphs/icp_normal.png"),
         ("glyph: ICP elevated", "glyphs/icp_elevated.png"),
         ("glyph: ICP pathological", "glyphs/icp_pathological.png"),
         ("sample patient database", "patients.db"), ("live graph log", "demo_roslaunch.log")]
missing = 0
for what, name in files:
    path = os.path.join(out, name)
    there = os.path.isfile(path) and os.path.getsize(path) > 0
    missing += not there
    print(f"  {what:32s} {path}" + ("" if there else "   MISSING"))
sys.exit(1 if missing else 0)
EOF

if [ -n "${DISPLAY:-}" ]; then
  echo
  echo "== the graph in rviz (Ctrl-C to stop)"
  roslaunch launch/demo.launch bag:="$PWD/$BAG" db:="$PWD/$OUT/patients.db"
fi
