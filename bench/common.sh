# Sourced by the benchmark scripts (after `cd` to the workspace root) with the script's
# arguments: Debian's python and the built workspace, the scenarios (arguments, or the four
# of the thesis tables), the benchmark columns and where the reports go.
export PATH=/usr/bin:/bin:$PATH
set +u; source devel/setup.bash; set -u

SCENARIOS=("$@")
[ ${#SCENARIOS[@]} -eq 0 ] && SCENARIOS=(hen hen_duplo office hen_slow)
# shellcheck disable=SC2034  # used by the scripts that source this file
# The tracking benchmark's columns; the fusion benchmark (bench/fusion/fusion_tables.py) reruns
# its own five, INITS.
TRACKING_INITS=(identity ekf_thesis_noise ekf_imu_noise ekf ekf_imu_datasheet constant_velocity imu)
INITS=(identity ekf constant_velocity imu ekf_imu_noise)
# A subset of the columns, e.g. BENCH_INITS="ekf ekf_thesis_noise"; BENCH_PEER=0 skips the peer;
# BENCH_CPU=1 pins the runs to core 1 (two scenario sets can run side by side).
if [ -n "${BENCH_INITS:-}" ]; then read -r -a TRACKING_INITS <<< "$BENCH_INITS"; fi
BENCH_PEER=${BENCH_PEER:-1}
BENCH_CPU=${BENCH_CPU:-0}  # the one core every run is pinned to
OUT=bench/out
mkdir -p "$OUT" bench/results

# vicc_reconstruct arguments for a benchmark column (src/vicc_tracking/config/...):
#   ekf               the thesis's EKF with the default noise: Q from the simulated IMU's noise,
#                     R measured against ground truth and scaled with the frame interval
#                     (tracker.yaml, docs/imu_noise.md)
#   ekf_thesis_noise  the thesis's noise values, one fixed R (tracker_thesis.yaml): Tables 5.2-5.5
#   ekf_imu_noise     the hand-tuned IMU-derived values with one fixed R (tracker_imu_trusting.yaml)
#   ekf_imu_datasheet the default with Q derived from the IMU's figures in Kalibr's layout
#                     (imu/simulated_rig.yaml, vicc_reconstruct --imu-noise)
init_args() {
  local config=src/vicc_tracking/config
  case "$1" in
    ekf_thesis_noise) echo "--init ekf --config $config/tracker_thesis.yaml" ;;
    ekf_imu_noise) echo "--init ekf --config $config/tracker_imu_trusting.yaml" ;;
    ekf_imu_datasheet) echo "--init ekf --imu-noise $config/imu/simulated_rig.yaml" ;;
    *) echo "--init $1" ;;
  esac
}
