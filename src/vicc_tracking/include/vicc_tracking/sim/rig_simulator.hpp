#pragma once
// The simulated ToF camera + IMU rig: ground-truth poses, depth images as the pico flexx
// delivers them (distorted, noisy, 0 = invalid) and REP-145 IMU readings. Deterministic:
// frame k / reading k are the same in every process, so the separate depth and IMU
// publisher nodes and vicc_make_bag produce identical data.

#include <string>
#include <vector>

#include <Eigen/Geometry>
#include <opencv2/core.hpp>

#include "vicc_tracking/imu_types.hpp"
#include "vicc_tracking/sim/scenario.hpp"
#include "vicc_tracking/sim/scene.hpp"
#include "vicc_tracking/sim/trajectory.hpp"

namespace vicc_tracking::sim {

constexpr double kGravity = 9.80665;

class RigSimulator {
 public:
  explicit RigSimulator(const Scenario& scenario);

  const Scenario& scenario() const { return scenario_; }
  const Scene& scene() const { return scene_; }
  double duration() const { return trajectory_.duration(); }

  /// Ground truth T_map_camera (optical frame); map z up, gravity -z. t in [0, duration].
  Eigen::Isometry3d cameraPose(double t) const { return trajectory_.cameraPose(t); }
  /// T_map_imu.
  Eigen::Isometry3d imuPose(double t) const;
  /// Exact body angular velocity (rad/s) and specific force (m/s^2) in the IMU frame.
  ImuSample idealImuSample(double t) const;

  const std::vector<double>& depthTimes() const { return depth_times_; }
  const std::vector<double>& imuTimes() const { return imu_times_; }

  /// CV_32FC1 z-depth in metres, 0 = nothing within range; distorted like the real sensor.
  cv::Mat renderDepthNoiseFree(double t) const;
  /// depthTimes()[frame_index] with ToF noise, flying pixels and dropouts.
  cv::Mat renderDepth(int frame_index) const;

  /// One frame of the sensor: the depth of renderDepth and the amplitude (gray) image the
  /// pico flexx delivers with it, CV_16UC1 like its image_mono16, on the same (distorted)
  /// pixels: Lambertian, amplitude_scale * albedo * cos(incidence) / range^2 plus Gaussian
  /// noise (tof.amplitude_sigma), 0 wherever the depth is invalid.
  struct Frame {
    cv::Mat depth;
    cv::Mat amplitude;
  };
  Frame renderFrame(int frame_index) const;
  /// imuTimes()[index] with bias and white noise; stamp = relative time.
  ImuSample imuSample(int index) const;

  std::vector<SurfacePoint> sampleSurface(double spacing) const {
    return scene_.sampleSurface(spacing);
  }

 private:
  /// Noise-free depth; with `amplitude`, also the noise-free amplitude (counts, float).
  cv::Mat1f renderClean(double t, cv::Mat1f* amplitude) const;
  Frame renderNoisy(int frame_index, bool with_amplitude) const;

  Scenario scenario_;
  Scene scene_;
  Trajectory trajectory_;
  std::vector<Eigen::Vector2d> rays_;
  std::vector<double> depth_times_;
  std::vector<double> imu_times_;  ///< normalised ray per pixel (distortion applied)
};

}  // namespace vicc_tracking::sim
