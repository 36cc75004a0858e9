# Sourced by the benchmark scripts (after `cd` to the workspace root) with the script's
# arguments: Debian's python and the built workspace, the scenarios (arguments, or the four
# of the thesis tables), the benchmark columns and where the reports go.
export PATH=/usr/bin:/bin:$PATH
set +u; source devel/setup.bash; set -u

SCENARIOS=("$@")
[ ${#SCENARIOS[@]} -eq 0 ] && SCENARIOS=(hen hen_duplo office hen_slow)
# shellcheck disable=SC2034  # used by the scripts that source this file
INITS=(identity ekf constant_velocity imu ekf_imu_noise)
OUT=bench/out
mkdir -p "$OUT" bench/results

# vicc_reconstruct arguments for a benchmark column. ekf_imu_noise = the thesis's EKF with noise
# values derived from the IMU and the measured extrapolation error
# (src/vicc_tracking/config/tracker_imu_trusting.yaml) instead of the thesis's values (the
# defaults).
init_args() {
  case "$1" in
    ekf_imu_noise) echo "--init ekf --config src/vicc_tracking/config/tracker_imu_trusting.yaml" ;;
    *) echo "--init $1" ;;
  esac
}
