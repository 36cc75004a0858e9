#include <gtest/gtest.h>

#include "vicc_tracking/icp.hpp"
#include "vicc_tracking/sim/rig_simulator.hpp"
#include "vicc_tracking/tracker.hpp"

using namespace vicc_tracking;

namespace {

/// Two noise-free views of the Hen scene with a known relative motion.
class IcpTest : public ::testing::TestWithParam<int> {
 protected:
  IcpTest() : rig_(sim::loadScenario("short_test")) {}

  DepthPyramid render(double t, int levels) const {
    PreprocessingConfig config;
    config.pyramid_levels = levels;
    DepthPreprocessor preprocessor(config);
    preprocessor.setCamera(rig_.scenario().camera);
    return preprocessor.process(rig_.renderDepthNoiseFree(t));
  }

  sim::RigSimulator rig_;
};

TEST_P(IcpTest, RecoversAKnownRigidMotionFromIdentity) {
  const int levels = GetParam();
  // short_test moves fastest mid-way: about 2 cm and 2 degrees between these views.
  const double t0 = 3.0, t1 = 3.0 + 2.0 / 15.0;
  const Eigen::Isometry3d truth = rig_.cameraPose(t0).inverse() * rig_.cameraPose(t1);
  ASSERT_GT(truth.translation().norm(), 0.01);
  const ProjectiveIcp icp{IcpConfig{}};
  const IcpResult result = icp.align(render(t1, levels), render(t0, levels), Eigen::Isometry3d::Identity());
  ASSERT_TRUE(result.ok) << result.failure_reason;
  const PoseDifference error = poseDifference(truth, result.pose);
  EXPECT_LT(error.translation, 1e-3);
  EXPECT_LT(error.rotation_deg, 0.1);
  EXPECT_GT(result.iterations, 0);
  EXPECT_EQ(static_cast<int>(result.iterations_per_level.size()), levels);
  EXPECT_GT(result.inlier_ratio, 0.8);
  EXPECT_LT(result.residual_rms, 5e-4);
  EXPECT_GT(result.condition_number, 1.0);
}

INSTANTIATE_TEST_SUITE_P(PyramidLevels, IcpTest, ::testing::Values(1, 2, 3));

TEST(IcpFailureTest, SinglePlaneIsReportedIllConditioned) {
  // A wall seen head-on constrains only 3 of 6 degrees of freedom.
  DepthLevel level;
  level.intrinsics = {64, 48, 50.f, 50.f, 31.5f, 23.5f};
  for (int v = 0; v < 48; ++v) {
    for (int u = 0; u < 64; ++u) {
      level.vertices.emplace_back((u - 31.5f) / 50.f, (v - 23.5f) / 50.f, 1.f);
      level.normals.emplace_back(0.f, 0.f, -1.f);
      level.radii.push_back(0.01f);
    }
  }
  level.valid_vertices = level.valid_normals = 64 * 48;
  IcpConfig config;
  config.min_inliers = 100;
  const IcpResult result = ProjectiveIcp(config).align({level}, {level}, Eigen::Isometry3d::Identity());
  EXPECT_FALSE(result.ok);
  EXPECT_NE(result.failure_reason.find("ill-conditioned"), std::string::npos) << result.failure_reason;
}

TEST(IcpFailureTest, EmptyFrameHasTooFewCorrespondences) {
  DepthLevel empty;
  empty.intrinsics = {64, 48, 50.f, 50.f, 31.5f, 23.5f};
  empty.vertices.assign(64 * 48, Eigen::Vector3f::Zero());
  empty.normals.assign(64 * 48, Eigen::Vector3f::Zero());
  empty.radii.assign(64 * 48, 0.f);
  const IcpResult result =
      ProjectiveIcp(IcpConfig{}).align({empty}, {empty}, Eigen::Isometry3d::Identity());
  EXPECT_FALSE(result.ok);
  EXPECT_NE(result.failure_reason.find("too few correspondences"), std::string::npos);
}

TEST_F(IcpTest, FarAwayGuessIsAFailureNotAGarbagePose) {
  Eigen::Isometry3d far = Eigen::Isometry3d::Identity();
  far.translation() = Eigen::Vector3d(0.0, 0.0, 0.5);  // half a metre into the scene
  const IcpResult result = ProjectiveIcp(IcpConfig{}).align(render(3.0, 1), render(3.0, 1), far);
  EXPECT_FALSE(result.ok);
}

TEST(IcpConfigTest, RejectsInvalidSettings) {
  IcpConfig config;
  config.iterations_per_level = {};
  EXPECT_THROW(config.validate(), std::invalid_argument);
  config = IcpConfig{};
  config.max_normal_angle_deg = 120.0;
  EXPECT_THROW(config.validate(), std::invalid_argument);
}

}  // namespace
