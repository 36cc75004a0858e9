#pragma once
// A simulated recording, described in one YAML file: scene, camera, trajectory, noise.

#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "vicc_tracking/camera_model.hpp"
#include "vicc_tracking/sim/scene.hpp"
#include "vicc_tracking/sim/trajectory.hpp"

namespace vicc_tracking::sim {

/// ToF depth noise: sigma(z) = sigma0 + sigma_quadratic * z^2 (metres), flying pixels at
/// depth edges, random dropouts, range limits.
struct TofNoiseConfig {
  double sigma0 = 0.001;
  double sigma_quadratic = 0.0015;
  double flying_pixel_probability = 0.5;  ///< per pixel at a depth discontinuity
  double edge_jump = 0.03;                ///< m between neighbours = a discontinuity
  double dropout_probability = 0.01;
  double min_range = 0.1;
  double max_range = 4.0;
  /// Amplitude image (mono16 counts): a white (albedo 1) surface facing the camera at 1 m
  /// returns amplitude_scale; Gaussian noise of amplitude_sigma counts.
  double amplitude_scale = 1000.0;
  double amplitude_sigma = 5.0;
  void validate() const;
};

/// MEMS IMU: constant bias + white noise on gyro and accelerometer.
struct ImuNoiseConfig {
  double rate_hz = 200.0;
  Eigen::Vector3d gyro_bias{0.004, -0.003, 0.002};  ///< rad/s
  Eigen::Vector3d accel_bias{0.03, -0.02, 0.04};    ///< m/s^2
  double gyro_noise_density = 0.0003;               ///< rad/s/sqrt(Hz)
  double accel_noise_density = 0.003;               ///< m/s^2/sqrt(Hz)
  void validate() const;
};

struct Scenario {
  std::string name;
  std::string description;
  CameraModel camera;
  double depth_rate_hz = 15.0;
  /// T_imu_camera: the optical frame in imu_link (IMU x forward, y left, z up).
  Eigen::Isometry3d imu_to_camera = Eigen::Isometry3d::Identity();
  std::string frame_map = "map";
  std::string frame_imu = "imu_link";
  std::string frame_camera = "pico_flexx_optical_frame";
  TofNoiseConfig tof;
  ImuNoiseConfig imu;
  unsigned seed = 1;
  std::vector<Primitive> scene;
  TrajectoryConfig trajectory;
  void validate() const;
};

/// The named scenarios: share/vicc_tracking/config/scenarios of the devel or install space
/// that holds this library. Throws std::runtime_error listing where it looked.
std::string scenarioDirectory();

/// "hen" loads scenarioDirectory()/hen.yaml; a path ending in .yaml loads that file. Throws
/// std::runtime_error naming the file and the missing or invalid key.
Scenario loadScenario(const std::string& name_or_path);
std::vector<std::string> availableScenarios();

/// The pico flexx as the scenarios use it: 224x171, wide FOV, plumb_bob distortion.
CameraModel picoFlexxCamera();
/// The rig's mounting: optical z = IMU x, optical x = -IMU y, optical y = -IMU z, plus a
/// small tilt and offset, so the extrinsic is a real rotation.
Eigen::Isometry3d defaultImuToCamera();

}  // namespace vicc_tracking::sim
