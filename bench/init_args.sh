# Sourced by the benchmark scripts: vicc_reconstruct arguments for a benchmark column.
# ekf_imu_noise = the thesis's EKF with noise values derived from the IMU and the measured
# extrapolation error (src/vicc_tracking/config/tracker_imu_trusting.yaml) instead of the
# thesis's values (the defaults).
init_args() {
  case "$1" in
    ekf_imu_noise) echo "--init ekf --config src/vicc_tracking/config/tracker_imu_trusting.yaml" ;;
    *) echo "--init $1" ;;
  esac
}
