#include "vicc_tracking/sim/rig_simulator.hpp"

#include <algorithm>
#include <cmath>
#include <random>

namespace vicc_tracking::sim {
namespace {

/// SplitMix64: decorrelated seeds for (scenario seed, stream, index).
uint64_t mixSeed(uint64_t seed, uint64_t stream, uint64_t index) {
  uint64_t z = seed * 0x9E3779B97F4A7C15ull ^ (stream << 56) ^ (index + 0x632BE59BD9B4E019ull);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

constexpr uint64_t kDepthStream = 1;
constexpr uint64_t kImuStream = 2;
constexpr uint64_t kAmplitudeStream = 3;

std::vector<double> sampleTimes(double rate, double duration) {
  std::vector<double> times;
  for (int k = 0;; ++k) {
    const double t = k / rate;
    if (t > duration + 1e-9) break;
    times.push_back(std::min(t, duration));
  }
  return times;
}

Eigen::Vector3d vee(const Eigen::Matrix3d& skew) {
  return 0.5 * Eigen::Vector3d(skew(2, 1) - skew(1, 2), skew(0, 2) - skew(2, 0),
                               skew(1, 0) - skew(0, 1));
}

}  // namespace

RigSimulator::RigSimulator(const Scenario& scenario)
    : scenario_(scenario), scene_(scenario.scene), trajectory_(scenario.trajectory) {
  scenario_.validate();
  rays_ = scenario_.camera.normalizedRaysForAllPixels();
  depth_times_ = sampleTimes(scenario_.depth_rate_hz, duration());
  imu_times_ = sampleTimes(scenario_.imu.rate_hz, duration());
}

Eigen::Isometry3d RigSimulator::imuPose(double t) const {
  return cameraPose(t) * scenario_.imu_to_camera.inverse();
}

ImuSample RigSimulator::idealImuSample(double t) const {
  // Five-point central differences: O(h^4) truncation, far below the IMU noise.
  const double h = 1e-3;
  Eigen::Isometry3d poses[5];
  for (int i = 0; i < 5; ++i) poses[i] = imuPose(t + (i - 2) * h);
  const Eigen::Matrix3d rotation_rate =
      (poses[0].linear() - 8.0 * poses[1].linear() + 8.0 * poses[3].linear() - poses[4].linear()) /
      (12.0 * h);
  const Eigen::Vector3d acceleration =
      (-poses[0].translation() + 16.0 * poses[1].translation() - 30.0 * poses[2].translation() +
       16.0 * poses[3].translation() - poses[4].translation()) /
      (12.0 * h * h);
  const Eigen::Matrix3d& r = poses[2].linear();
  ImuSample sample;
  sample.stamp = t;
  sample.angular_velocity = vee(r.transpose() * rotation_rate);
  const Eigen::Vector3d gravity(0.0, 0.0, -kGravity);
  sample.linear_acceleration = r.transpose() * (acceleration - gravity);
  return sample;
}

cv::Mat RigSimulator::renderDepthNoiseFree(double t) const { return renderClean(t, nullptr); }

cv::Mat1f RigSimulator::renderClean(double t, cv::Mat1f* amplitude) const {
  const CameraModel& camera = scenario_.camera;
  cv::Mat1f depth(camera.height, camera.width, 0.f);
  if (amplitude) *amplitude = cv::Mat1f(camera.height, camera.width, 0.f);
  const Eigen::Isometry3d pose = cameraPose(t);
  const Eigen::Matrix3d& rotation = pose.linear();
  const Eigen::Vector3d origin = pose.translation();
  const TofNoiseConfig& tof = scenario_.tof;
  for (int v = 0; v < camera.height; ++v) {
    float* row = depth[v];
    for (int u = 0; u < camera.width; ++u) {
      const Eigen::Vector2d& ray = rays_[static_cast<size_t>(v) * camera.width + u];
      // Direction (x, y, 1) in the camera: the ray parameter is the z-depth.
      const Eigen::Vector3d direction = rotation * Eigen::Vector3d(ray.x(), ray.y(), 1.0);
      const auto hit = scene_.raycastHit(origin, direction);
      if (!hit || hit->t < tof.min_range || hit->t > tof.max_range) continue;
      row[u] = static_cast<float>(hit->t);
      if (!amplitude) continue;
      // Lambertian return: albedo * cos(incidence) / range^2 (the ToF illumination is at the
      // camera, so incidence and emergence angles coincide).
      const double length = direction.norm();
      const double range = hit->t * length;
      const double cos_incidence = std::abs(hit->normal.dot(direction)) / length;
      const double albedo = scene_.primitives()[hit->primitive].albedo;
      (*amplitude)(v, u) =
          static_cast<float>(tof.amplitude_scale * albedo * cos_incidence / (range * range));
    }
  }
  return depth;
}

cv::Mat RigSimulator::renderDepth(int frame_index) const {
  return renderNoisy(frame_index, false).depth;
}

RigSimulator::Frame RigSimulator::renderFrame(int frame_index) const {
  return renderNoisy(frame_index, true);
}

RigSimulator::Frame RigSimulator::renderNoisy(int frame_index, bool with_amplitude) const {
  const std::vector<double>& times = depth_times_;
  if (frame_index < 0 || frame_index >= static_cast<int>(times.size())) {
    throw std::out_of_range("depth frame index out of range");
  }
  cv::Mat1f clean_amplitude;
  const cv::Mat1f clean =
      renderClean(times[frame_index], with_amplitude ? &clean_amplitude : nullptr);
  cv::Mat1f noisy = clean.clone();
  std::mt19937_64 rng(mixSeed(scenario_.seed, kDepthStream, static_cast<uint64_t>(frame_index)));
  std::normal_distribution<float> gaussian(0.f, 1.f);
  std::uniform_real_distribution<float> uniform(0.f, 1.f);
  const TofNoiseConfig& tof = scenario_.tof;
  for (int v = 0; v < clean.rows; ++v) {
    for (int u = 0; u < clean.cols; ++u) {
      const float z = clean(v, u);
      if (z <= 0.f) continue;
      if (uniform(rng) < tof.dropout_probability) {
        noisy(v, u) = 0.f;
        continue;
      }
      // Flying pixel: the sensor mixes foreground and background returns at an edge.
      float mixed = z;
      for (const auto& [dv, du] : {std::pair{0, 1}, std::pair{1, 0}, std::pair{0, -1}, std::pair{-1, 0}}) {
        const int nv = v + dv, nu = u + du;
        if (nv < 0 || nu < 0 || nv >= clean.rows || nu >= clean.cols) continue;
        const float other = clean(nv, nu);
        if (other > z + tof.edge_jump && uniform(rng) < tof.flying_pixel_probability) {
          mixed = z + uniform(rng) * (other - z);
          break;
        }
      }
      const float sigma = static_cast<float>(tof.sigma0 + tof.sigma_quadratic * mixed * mixed);
      const float measured = mixed + sigma * gaussian(rng);
      noisy(v, u) = (measured >= tof.min_range && measured <= tof.max_range) ? measured : 0.f;
    }
  }
  Frame frame;
  frame.depth = noisy;
  if (!with_amplitude) return frame;
  // Its own random stream: the depth stays what it was without the amplitude.
  std::mt19937_64 amplitude_rng(
      mixSeed(scenario_.seed, kAmplitudeStream, static_cast<uint64_t>(frame_index)));
  std::normal_distribution<float> amplitude_noise(0.f, 1.f);
  const float sigma = static_cast<float>(tof.amplitude_sigma);
  cv::Mat1w amplitude(clean.rows, clean.cols, static_cast<uint16_t>(0));
  for (int v = 0; v < clean.rows; ++v) {
    for (int u = 0; u < clean.cols; ++u) {
      if (noisy(v, u) <= 0.f) continue;
      const float value = clean_amplitude(v, u) + sigma * amplitude_noise(amplitude_rng);
      amplitude(v, u) = static_cast<uint16_t>(std::lround(std::clamp(value, 0.f, 65535.f)));
    }
  }
  frame.amplitude = amplitude;
  return frame;
}

ImuSample RigSimulator::imuSample(int index) const {
  const std::vector<double>& times = imu_times_;
  if (index < 0 || index >= static_cast<int>(times.size())) {
    throw std::out_of_range("IMU sample index out of range");
  }
  ImuSample sample = idealImuSample(times[index]);
  std::mt19937_64 rng(mixSeed(scenario_.seed, kImuStream, static_cast<uint64_t>(index)));
  std::normal_distribution<double> gaussian(0.0, 1.0);
  const ImuNoiseConfig& imu = scenario_.imu;
  const double gyro_sigma = imu.gyro_noise_density * std::sqrt(imu.rate_hz);
  const double accel_sigma = imu.accel_noise_density * std::sqrt(imu.rate_hz);
  for (int axis = 0; axis < 3; ++axis) {
    sample.angular_velocity[axis] += imu.gyro_bias[axis] + gyro_sigma * gaussian(rng);
    sample.linear_acceleration[axis] += imu.accel_bias[axis] + accel_sigma * gaussian(rng);
  }
  return sample;
}

}  // namespace vicc_tracking::sim
