#include "vicc_tracking/ros/tracker_reconfigure.hpp"

namespace vicc_tracking {

IcpTuningConfig toTuning(const IcpConfig& icp) {
  IcpTuningConfig tuning = IcpTuningConfig::__getDefault__();
  tuning.max_correspondence_distance = icp.max_correspondence_distance;
  tuning.max_normal_angle_deg = icp.max_normal_angle_deg;
  tuning.convergence_translation = icp.convergence_translation;
  tuning.convergence_rotation_deg = icp.convergence_rotation_deg;
  tuning.min_inliers = icp.min_inliers;
  tuning.min_inlier_ratio = icp.min_inlier_ratio;
  tuning.max_condition_number = icp.max_condition_number;
  tuning.max_jump_translation = icp.max_jump_translation;
  tuning.max_jump_rotation_deg = icp.max_jump_rotation_deg;
  return tuning;
}

IcpConfig fromTuning(const IcpTuningConfig& tuning, IcpConfig base) {
  base.max_correspondence_distance = tuning.max_correspondence_distance;
  base.max_normal_angle_deg = tuning.max_normal_angle_deg;
  base.convergence_translation = tuning.convergence_translation;
  base.convergence_rotation_deg = tuning.convergence_rotation_deg;
  base.min_inliers = tuning.min_inliers;
  base.min_inlier_ratio = tuning.min_inlier_ratio;
  base.max_condition_number = tuning.max_condition_number;
  base.max_jump_translation = tuning.max_jump_translation;
  base.max_jump_rotation_deg = tuning.max_jump_rotation_deg;
  return base;
}

EkfTuningConfig toTuning(const EkfConfig& ekf) {
  EkfTuningConfig tuning = EkfTuningConfig::__getDefault__();
  tuning.process_noise_rotation = ekf.process_noise_rotation;
  tuning.process_noise_velocity = ekf.process_noise_velocity;
  tuning.process_noise_position = ekf.process_noise_position;
  tuning.process_noise_base = ekf.process_noise_base;
  tuning.measurement_noise_rotation = ekf.measurement_noise_rotation;
  tuning.measurement_noise_velocity = ekf.measurement_noise_velocity;
  tuning.measurement_noise_position = ekf.measurement_noise_position;
  tuning.measurement_noise_base = ekf.measurement_noise_base;
  tuning.measurement_noise_reference_interval = ekf.measurement_noise_reference_interval;
  tuning.measurement_noise_interval_exponent = ekf.measurement_noise_interval_exponent;
  tuning.initial_covariance = ekf.initial_covariance;
  tuning.imu_aided_virtual_velocity = ekf.imu_aided_virtual_velocity;
  return tuning;
}

EkfConfig fromTuning(const EkfTuningConfig& tuning, EkfConfig base) {
  base.process_noise_rotation = tuning.process_noise_rotation;
  base.process_noise_velocity = tuning.process_noise_velocity;
  base.process_noise_position = tuning.process_noise_position;
  base.process_noise_base = tuning.process_noise_base;
  base.measurement_noise_rotation = tuning.measurement_noise_rotation;
  base.measurement_noise_velocity = tuning.measurement_noise_velocity;
  base.measurement_noise_position = tuning.measurement_noise_position;
  base.measurement_noise_base = tuning.measurement_noise_base;
  base.measurement_noise_reference_interval = tuning.measurement_noise_reference_interval;
  base.measurement_noise_interval_exponent = tuning.measurement_noise_interval_exponent;
  base.initial_covariance = tuning.initial_covariance;
  base.imu_aided_virtual_velocity = tuning.imu_aided_virtual_velocity;
  return base;
}

TrackerReconfigure::TrackerReconfigure(const ros::NodeHandle& private_nh,
                                       const TrackerConfig& initial)
    : icp_(ros::NodeHandle(private_nh, "icp"), "tracker: icp", initial.icp),
      ekf_(ros::NodeHandle(private_nh, "ekf"), "tracker: ekf", initial.ekf) {}

void TrackerReconfigure::applyPending(TrackerConfig& config, Tracker* tracker) {
  if (const std::optional<IcpConfig> icp = icp_.takeChange()) {
    if (tracker) tracker->setIcpConfig(*icp);
    config.icp = *icp;
  }
  if (const std::optional<EkfConfig> ekf = ekf_.takeChange()) {
    if (tracker) tracker->setEkfConfig(*ekf);
    config.ekf = *ekf;
  }
}

}  // namespace vicc_tracking
