#include <gtest/gtest.h>

#include <cmath>

#include "vicc_tracking/sim/rig_simulator.hpp"

using namespace vicc_tracking;
using namespace vicc_tracking::sim;

namespace {

class RigSimulatorTest : public ::testing::Test {
 protected:
  RigSimulatorTest() : rig_(loadScenario("short_test")) {}
  RigSimulator rig_;
};

double rotationDegrees(const Eigen::Matrix3d& a, const Eigen::Matrix3d& b) {
  return Eigen::AngleAxisd(a.transpose() * b).angle() * 180.0 / M_PI;
}

TEST_F(RigSimulatorTest, StillPhaseReadsGravityAndNoRotation) {
  for (const double t : {0.0, 0.5, 1.9}) {
    const ImuSample ideal = rig_.idealImuSample(t);
    EXPECT_LT(ideal.angular_velocity.norm(), 1e-9);
    EXPECT_NEAR(ideal.linear_acceleration.norm(), kGravity, 1e-6);
    // Specific force points up: rotated into the map it is +z.
    const Eigen::Vector3d up = rig_.imuPose(t).linear() * ideal.linear_acceleration;
    EXPECT_NEAR(up.z(), kGravity, 1e-6);
  }
  // The noisy reading carries the configured bias.
  Eigen::Vector3d mean_gyro = Eigen::Vector3d::Zero();
  const int n = 300;  // 1.5 s of still phase at 200 Hz
  for (int i = 0; i < n; ++i) mean_gyro += rig_.imuSample(i).angular_velocity / n;
  EXPECT_LT((mean_gyro - rig_.scenario().imu.gyro_bias).norm(), 5e-4);
}

TEST_F(RigSimulatorTest, NoiseFreeImuIntegrationReproducesTheTrajectory) {
  const double dt = 1e-3;
  Eigen::Isometry3d pose = rig_.imuPose(0.0);
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();
  const Eigen::Vector3d gravity(0, 0, -kGravity);
  for (double t = 0.0; t < rig_.duration() - 1e-9; t += dt) {
    const ImuSample mid = rig_.idealImuSample(t + 0.5 * dt);
    const Eigen::Matrix3d rotation_mid =
        pose.linear() * Eigen::AngleAxisd(0.5 * dt * mid.angular_velocity.norm(),
                                          mid.angular_velocity.normalized())
                            .toRotationMatrix();
    const Eigen::Vector3d acceleration = rotation_mid * mid.linear_acceleration + gravity;
    pose.translation() += velocity * dt + 0.5 * acceleration * dt * dt;
    velocity += acceleration * dt;
    if (mid.angular_velocity.norm() > 0.0) {
      pose.linear() = pose.linear() * Eigen::AngleAxisd(dt * mid.angular_velocity.norm(),
                                                        mid.angular_velocity.normalized())
                                          .toRotationMatrix();
    }
  }
  const Eigen::Isometry3d truth = rig_.imuPose(rig_.duration());
  EXPECT_LT((pose.translation() - truth.translation()).norm(), 1e-3);
  EXPECT_LT(rotationDegrees(pose.linear(), truth.linear()), 0.1);
  EXPECT_LT(velocity.norm(), 1e-3);  // the loop ends at rest
}

TEST_F(RigSimulatorTest, DepthIsZDepthOfTheDistortedRay) {
  const double t = 3.0;
  const cv::Mat1f depth = rig_.renderDepthNoiseFree(t);
  const Eigen::Isometry3d pose = rig_.cameraPose(t);
  const CameraModel& camera = rig_.scenario().camera;
  int on_table = 0, valid = 0;
  for (int v = 0; v < depth.rows; v += 3) {
    for (int u = 0; u < depth.cols; u += 3) {
      const float z = depth(v, u);
      if (z <= 0.f) continue;
      ++valid;
      const Eigen::Vector2d ray = camera.unprojectToNormalized(Eigen::Vector2d(u, v));
      const Eigen::Vector3d point_camera(ray.x() * z, ray.y() * z, z);
      // Distortion consistency: projecting the 3D point gives back its pixel.
      EXPECT_LT((camera.project(point_camera) - Eigen::Vector2d(u, v)).norm(), 1e-2);
      const Eigen::Vector3d point_map = pose * point_camera;
      if (std::abs(point_map.z()) < 1e-5 && point_map.head<2>().norm() > 0.3) ++on_table;
    }
  }
  EXPECT_GT(valid, depth.rows * depth.cols / 9 * 6 / 10);  // the table fills most of the view
  EXPECT_GT(on_table, 200) << "the table top at z = 0 must appear at its exact depth";
}

TEST_F(RigSimulatorTest, NoisyDepthIsDeterministicWithTheConfiguredSigma) {
  const cv::Mat1f a = rig_.renderDepth(40);
  const cv::Mat1f b = rig_.renderDepth(40);
  EXPECT_EQ(cv::norm(a, b, cv::NORM_INF), 0.0);
  EXPECT_GT(cv::norm(a, rig_.renderDepth(41), cv::NORM_INF), 0.0);
  const cv::Mat1f clean = rig_.renderDepthNoiseFree(rig_.depthTimes()[40]);
  double sum_squares = 0.0, expected = 0.0;
  int n = 0, dropouts = 0, valid = 0;
  for (int v = 1; v < clean.rows - 1; ++v) {
    for (int u = 1; u < clean.cols - 1; ++u) {
      const float z = clean(v, u);
      if (z <= 0.f) continue;
      ++valid;
      if (a(v, u) == 0.f) {
        ++dropouts;
        continue;
      }
      const bool edge = std::abs(clean(v, u + 1) - z) > 0.01 || std::abs(clean(v + 1, u) - z) > 0.01 ||
                        std::abs(clean(v, u - 1) - z) > 0.01 || std::abs(clean(v - 1, u) - z) > 0.01;
      if (edge) continue;
      const double sigma = 0.001 + 0.0015 * z * z;
      sum_squares += std::pow((a(v, u) - z) / sigma, 2);
      expected += 1.0;
      ++n;
    }
  }
  ASSERT_GT(n, 5000);
  EXPECT_NEAR(std::sqrt(sum_squares / expected), 1.0, 0.1);  // normalised noise has unit std
  EXPECT_NEAR(static_cast<double>(dropouts) / valid, 0.01, 0.005);
}

TEST_F(RigSimulatorTest, AmplitudeIsLambertianWithTheObjectsAlbedoAndZeroWithoutDepth) {
  Scenario scenario = rig_.scenario();
  scenario.tof.amplitude_sigma = 0.0;
  scenario.tof.flying_pixel_probability = 0.0;
  scenario.scene.front().albedo = 0.5;
  const RigSimulator rig(scenario);
  const int frame_index = 40;
  const RigSimulator::Frame frame = rig.renderFrame(frame_index);
  ASSERT_EQ(frame.amplitude.type(), CV_16UC1);
  // The depth is the one renderDepth gives: the amplitude has its own noise stream.
  EXPECT_EQ(cv::norm(frame.depth, rig.renderDepth(frame_index), cv::NORM_INF), 0.0);
  const cv::Mat1f depth = frame.depth;
  const cv::Mat1w amplitude = frame.amplitude;
  const Eigen::Isometry3d pose = rig.cameraPose(rig.depthTimes()[frame_index]);
  const CameraModel& camera = scenario.camera;
  int checked = 0, first_object = 0;
  for (int v = 0; v < depth.rows; ++v) {
    for (int u = 0; u < depth.cols; ++u) {
      if (depth(v, u) <= 0.f) {
        EXPECT_EQ(amplitude(v, u), 0) << u << "," << v;
        continue;
      }
      if ((u + v) % 5 != 0) continue;
      const Eigen::Vector2d ray = camera.unprojectToNormalized(Eigen::Vector2d(u, v));
      const Eigen::Vector3d direction = pose.linear() * Eigen::Vector3d(ray.x(), ray.y(), 1.0);
      const auto hit = rig.scene().raycastHit(pose.translation(), direction);
      ASSERT_TRUE(hit.has_value());
      const double range = hit->t * direction.norm();
      const double cos_incidence = std::abs(hit->normal.dot(direction.normalized()));
      const double albedo = hit->primitive == 0 ? 0.5 : 1.0;
      const double expected = std::min(
          65535.0, scenario.tof.amplitude_scale * albedo * cos_incidence / (range * range));
      EXPECT_NEAR(amplitude(v, u), expected, 0.5 + 1e-3 * expected) << u << "," << v;
      ++checked;
      if (hit->primitive == 0) ++first_object;
    }
  }
  EXPECT_GT(checked, 3000);
  EXPECT_GT(first_object, 100);
}

TEST_F(RigSimulatorTest, AmplitudeNoiseIsDeterministicWithTheConfiguredSigma) {
  const RigSimulator::Frame a = rig_.renderFrame(40);
  const RigSimulator::Frame b = rig_.renderFrame(40);
  EXPECT_EQ(cv::norm(a.amplitude, b.amplitude, cv::NORM_INF), 0.0);
  Scenario quiet = rig_.scenario();
  quiet.tof.amplitude_sigma = 0.0;
  const cv::Mat1w clean = RigSimulator(quiet).renderFrame(40).amplitude;
  const cv::Mat1w noisy = a.amplitude;
  double sum_squares = 0.0;
  int n = 0;
  for (int v = 0; v < clean.rows; ++v) {
    for (int u = 0; u < clean.cols; ++u) {
      if (clean(v, u) < 100 || clean(v, u) > 60000) continue;
      sum_squares += std::pow(static_cast<double>(noisy(v, u)) - clean(v, u), 2);
      ++n;
    }
  }
  ASSERT_GT(n, 5000);
  EXPECT_NEAR(std::sqrt(sum_squares / n), rig_.scenario().tof.amplitude_sigma, 0.5);
}

TEST_F(RigSimulatorTest, TimesCoverTheRunAtTheConfiguredRates) {
  EXPECT_DOUBLE_EQ(rig_.depthTimes().front(), 0.0);
  EXPECT_NEAR(rig_.depthTimes()[1], 1.0 / 15.0, 1e-12);
  EXPECT_LE(rig_.imuTimes().back(), rig_.duration());
  EXPECT_EQ(rig_.imuTimes().size(), static_cast<size_t>(std::floor(rig_.duration() * 200.0 + 1e-9)) + 1);
  EXPECT_THROW(rig_.renderDepth(-1), std::out_of_range);
  EXPECT_THROW(rig_.imuSample(static_cast<int>(rig_.imuTimes().size())), std::out_of_range);
}

}  // namespace
