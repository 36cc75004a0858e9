#include <gtest/gtest.h>

#include "vicc_tracking/sim/trajectory.hpp"

using namespace vicc_tracking::sim;

namespace {

TrajectoryConfig loop() {
  TrajectoryConfig config;
  config.target = Eigen::Vector3d(0, 0, 0.1);
  config.keyframes = {{0, 0, 30, 0.6, 0}, {1.0, 40, 40, 0.5, 10}, {2.0, 0, 30, 0.6, 0}};
  return config;
}

TEST(TrajectoryTest, StillAtStartAndEndAndClosesTheLoop) {
  const Trajectory trajectory(loop());
  EXPECT_DOUBLE_EQ(trajectory.duration(), 2.0 + 2.0 + 1.0);
  const Eigen::Isometry3d start = trajectory.cameraPose(0.0);
  EXPECT_LT((trajectory.cameraPose(1.99).matrix() - start.matrix()).norm(), 1e-12);
  EXPECT_LT((trajectory.cameraPose(trajectory.duration()).matrix() - start.matrix()).norm(), 1e-12);
  EXPECT_GT((trajectory.cameraPose(3.0).matrix() - start.matrix()).norm(), 0.1);
}

TEST(TrajectoryTest, CameraLooksAtTheTargetWithRightHandedOpticalAxes) {
  const Trajectory trajectory(loop());
  for (const double t : {0.0, 2.3, 2.9, 3.5}) {
    const Eigen::Isometry3d pose = trajectory.cameraPose(t);
    const Eigen::Vector3d to_target = (Eigen::Vector3d(0, 0, 0.1) - pose.translation()).normalized();
    EXPECT_NEAR(pose.linear().col(2).dot(to_target), 1.0, 1e-12);
    EXPECT_NEAR(pose.linear().determinant(), 1.0, 1e-12);
  }
  // Without roll, image y (down) points downwards in the map.
  EXPECT_LT(trajectory.cameraPose(0.0).linear().col(1).z(), 0.0);
}

TEST(TrajectoryTest, InvalidConfigurationsAreRejected) {
  TrajectoryConfig open = loop();
  open.keyframes.back().azimuth_deg = 10;
  EXPECT_THROW(Trajectory{open}, std::invalid_argument);
  TrajectoryConfig unordered = loop();
  unordered.keyframes[1].time = 3.0;
  EXPECT_THROW(Trajectory{unordered}, std::invalid_argument);
  TrajectoryConfig overhead = loop();
  overhead.keyframes[1].elevation_deg = 90;
  EXPECT_THROW(Trajectory{overhead}, std::invalid_argument);
}

}  // namespace
