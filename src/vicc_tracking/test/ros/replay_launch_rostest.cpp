// rostest: launch/replay.launch plays a recording into the tracker. By default the graph
// stays up after the bag ends (the model can still be saved); with exit_at_end:=true the
// launch ends by itself when the player does.
//
//   StaysUpAfterTheRecordingEnds: replay.launch is included by the .test file.
//   EndsWithThePlayer: this program runs `roslaunch replay.launch ... exit_at_end:=true`
//     itself (arguments: the launch file, the bag), as a rostest would be torn down too.
#include <gtest/gtest.h>

#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>

#include <algorithm>
#include <string>
#include <vector>

#include <ros/ros.h>
#include <vicc_msgs/TrackingStatus.h>

#include "wait_for_recording_end.hpp"

extern char** environ;

namespace {

std::vector<std::string> g_program_args;  // after gtest and ros::init removed theirs

bool nodeIsRegistered(const std::string& name) {
  std::vector<std::string> nodes;
  if (!ros::master::getNodes(nodes)) return false;
  return std::find(nodes.begin(), nodes.end(), name) != nodes.end();
}

/// Spins until `done` holds or `limit` (wall time) has passed. `done` is called once per
/// round, so it may have side effects (waitpid reports an exit only once).
template <typename Condition>
bool spinUntil(Condition done, ros::WallDuration limit) {
  const ros::WallTime deadline = ros::WallTime::now() + limit;
  while (ros::ok() && ros::WallTime::now() < deadline) {
    if (done()) return true;
    ros::spinOnce();
    ros::WallDuration(0.05).sleep();
  }
  return false;
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
  ASSERT_TRUE(spinUntil([] { return !nodeIsRegistered("/player"); }, ros::WallDuration(30.0)))
      << "the player did not finish the recording";
  // A required player would have ended the whole launch (and this test) by now.
  ros::WallDuration(3.0).sleep();
  EXPECT_TRUE(nodeIsRegistered("/tracker")) << "the tracker ended with the recording";
}

/// Runs roslaunch as a child process; returns its pid (0 if it could not be started).
pid_t startRoslaunch(const std::vector<std::string>& arguments) {
  std::vector<char*> argv;
  for (const std::string& argument : arguments) argv.push_back(const_cast<char*>(argument.c_str()));
  argv.push_back(nullptr);
  pid_t pid = 0;
  if (posix_spawnp(&pid, argv[0], nullptr, nullptr, argv.data(), environ) != 0) return 0;
  return pid;
}

TEST_F(ReplayLaunch, EndsWithThePlayer) {
  ASSERT_EQ(g_program_args.size(), 2u) << "usage: replay_launch_rostest LAUNCH_FILE BAG";
  const pid_t roslaunch =
      startRoslaunch({"roslaunch", g_program_args[0], "bag:=" + g_program_args[1], "rviz:=false",
                      "exit_at_end:=true"});
  ASSERT_NE(roslaunch, 0) << "roslaunch could not be started";

  int wait_status = 0;
  const bool ended =
      spinUntil([&] { return waitpid(roslaunch, &wait_status, WNOHANG) == roslaunch; },
                ros::WallDuration(120.0));
  if (!ended) {
    kill(roslaunch, SIGINT);
    waitpid(roslaunch, &wait_status, 0);
  }
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
