// rostest: launch/replay.launch plays a recording into the tracker. By default the graph
// stays up after the bag ends (the model can still be saved); with exit_at_end:=true the
// launch ends by itself when the player does.
//
//   StaysUpAfterTheRecordingEnds: replay.launch is included by the .test file.
//   EndsWithThePlayer: this program runs `roslaunch replay.launch ... exit_at_end:=true`
//     itself (arguments: the launch file, the bag), as a rostest would be torn down too.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include <ros/ros.h>
#include <vicc_msgs/TrackingStatus.h>

#include "roslaunch_child.hpp"
#include "wait_for_recording_end.hpp"

extern char** environ;

namespace {

std::vector<std::string> g_program_args;  // after gtest and ros::init removed theirs

bool nodeIsRegistered(const std::string& name) {
  std::vector<std::string> nodes;
  if (!ros::master::getNodes(nodes)) return false;
  return std::find(nodes.begin(), nodes.end(), name) != nodes.end();
}

class ReplayLaunch : public ::testing::Test {
 protected:
  ReplayLaunch() {
    status_sub_ = nh_.subscribe("/tracker/status", 1000, &ReplayLaunch::onStatus, this);
  }
  void onStatus(const vicc_msgs::TrackingStatus& status) {
    ++statuses_;
    if (status.state == vicc_msgs::TrackingStatus::STATE_OK) ++tracked_;
    if (status.state == vicc_msgs::TrackingStatus::STATE_LOST) ++lost_;
  }

  ros::NodeHandle nh_;
  ros::Subscriber status_sub_;
  std::size_t statuses_ = 0;
  std::size_t tracked_ = 0;
  std::size_t lost_ = 0;
};

TEST_F(ReplayLaunch, StaysUpAfterTheRecordingEnds) {
  vicc_test::waitForRecordingEnd([this] { return statuses_; });
  // short_test: 2 s still phase (initializing), then ~4 s of motion at 15 Hz, all tracked.
  EXPECT_GT(tracked_, 40u) << "the tracker did not track the replayed recording";
  EXPECT_EQ(lost_, 0u);
  ASSERT_TRUE(
      vicc_test::spinUntil([] { return !nodeIsRegistered("/player"); }, ros::WallDuration(30.0)))
      << "the player did not finish the recording";
  // A required player would have ended the whole launch (and this test) by now.
  ros::WallDuration(3.0).sleep();
  EXPECT_TRUE(nodeIsRegistered("/tracker")) << "the tracker ended with the recording";
}

TEST_F(ReplayLaunch, EndsWithThePlayer) {
  ASSERT_EQ(g_program_args.size(), 2u) << "usage: replay_launch_rostest LAUNCH_FILE BAG";
  const pid_t roslaunch =
      vicc_test::startRoslaunch({"roslaunch", g_program_args[0], "bag:=" + g_program_args[1],
                                 "rviz:=false", "exit_at_end:=true"});
  ASSERT_NE(roslaunch, 0) << "roslaunch could not be started";

  int wait_status = 0;
  const bool ended = vicc_test::waitForChildExit(roslaunch, ros::WallDuration(120.0), wait_status);
  ASSERT_TRUE(ended) << "the launch did not end with the recording";
  EXPECT_TRUE(WIFEXITED(wait_status) && WEXITSTATUS(wait_status) == 0)
      << "roslaunch failed, wait status " << wait_status;
  EXPECT_GT(tracked_, 40u) << "the tracker did not track the replayed recording";
  EXPECT_FALSE(nodeIsRegistered("/tracker")) << "the tracker outlived the launch";
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "replay_launch_rostest");
  g_program_args.assign(argv + 1, argv + argc);
  return RUN_ALL_TESTS();
}
