#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>

#include "vicc_tracking/trajectory_error.hpp"
#include "vicc_tracking/tum_trajectory.hpp"

using namespace vicc_tracking;

namespace {

Eigen::Isometry3d pose(double x, double yaw_deg) {
  Eigen::Isometry3d result = Eigen::Isometry3d::Identity();
  result.linear() =
      Eigen::AngleAxisd(yaw_deg * M_PI / 180.0, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  result.translation() = Eigen::Vector3d(x, 0.5 * x, 0.1);
  return result;
}

TEST(TrajectoryErrorTest, AFixedOffsetIsAlignedAway) {
  std::vector<TimedPose> truth, estimate;
  Eigen::Isometry3d offset = pose(3.0, 40.0);
  for (int i = 0; i < 20; ++i) {
    truth.push_back({100.0 + i * 0.1, pose(i * 0.05, i * 2.0)});
    estimate.push_back({100.0 + i * 0.1, offset * pose(i * 0.05, i * 2.0)});
  }
  const TrajectoryError error = compareTrajectories(estimate, truth);
  EXPECT_EQ(error.matched, 20u);
  EXPECT_LT(error.max_position, 1e-9);
  EXPECT_LT(error.max_rotation_deg, 1e-6);
}

TEST(TrajectoryErrorTest, MeasuresDriftAndSkipsUnmatchedStamps) {
  std::vector<TimedPose> truth, estimate;
  for (int i = 0; i < 10; ++i) {
    truth.push_back({double(i), pose(i * 0.1, 0.0)});
    Eigen::Isometry3d drifted = pose(i * 0.1, 0.0);
    drifted.translation().x() += 0.001 * i;  // 1 mm per frame
    estimate.push_back({double(i), drifted});
  }
  estimate.push_back({42.5, pose(0.0, 0.0)});  // no ground truth there
  const TrajectoryError error = compareTrajectories(estimate, truth);
  EXPECT_EQ(error.matched, 10u);
  EXPECT_NEAR(error.final_position, 0.009, 1e-9);
  EXPECT_NEAR(error.max_position, 0.009, 1e-9);
  EXPECT_GT(error.rmse_position, 0.004);
  EXPECT_LT(error.rmse_position, 0.009);
}

TEST(TumTrajectoryTest, WriteReadRoundTrip) {
  const std::string path = ::testing::TempDir() + "vicc_tum_test.tum";
  std::vector<TimedPose> poses{{1700000000.123456789, pose(0.25, 30.0)},
                               {1700000000.2, pose(-1.0, -170.0)}};
  writeTumTrajectory(path, poses);
  const auto back = readTumTrajectory(path);
  ASSERT_EQ(back.size(), 2u);
  EXPECT_NEAR(back[0].stamp, poses[0].stamp, 1e-6);
  EXPECT_LT((back[1].pose.matrix() - poses[1].pose.matrix()).norm(), 1e-5);
  std::remove(path.c_str());
}

TEST(TumTrajectoryTest, MalformedLineNamesFileAndLine) {
  const std::string path = ::testing::TempDir() + "vicc_tum_bad.tum";
  {
    std::ofstream out(path);
    out << "# comment\n1 0 0 0 0 0 0 1\n2 0 0 nan 0 0 0 1\n";
  }
  try {
    readTumTrajectory(path);
    FAIL() << "no exception";
  } catch (const std::runtime_error& error) {
    EXPECT_NE(std::string(error.what()).find(":3:"), std::string::npos) << error.what();
  }
  std::remove(path.c_str());
}

}  // namespace
