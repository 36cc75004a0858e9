#pragma once
// Shared by the rostests that run a launch file as a child process (replay.launch with
// exit_at_end): start roslaunch, spin while it runs, and learn whether it ended in time.

#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <string>
#include <vector>

#include <ros/ros.h>

namespace vicc_test {

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

/// Runs roslaunch (`arguments[0]` looked up on PATH) as a child process; its pid, 0 if it
/// could not be started.
inline pid_t startRoslaunch(const std::vector<std::string>& arguments) {
  std::vector<char*> argv;
  for (const std::string& argument : arguments) argv.push_back(const_cast<char*>(argument.c_str()));
  argv.push_back(nullptr);
  pid_t pid = 0;
  if (posix_spawnp(&pid, argv[0], nullptr, nullptr, argv.data(), environ) != 0) return 0;
  return pid;
}

/// Spins until the child ends or `limit` passes; a child still running then is stopped with
/// SIGINT. True if it ended by itself; `wait_status` as waitpid reports it.
inline bool waitForChildExit(pid_t child, ros::WallDuration limit, int& wait_status) {
  wait_status = 0;
  const bool ended =
      spinUntil([&] { return waitpid(child, &wait_status, WNOHANG) == child; }, limit);
  if (!ended) {
    kill(child, SIGINT);
    waitpid(child, &wait_status, 0);
  }
  return ended;
}

}  // namespace vicc_test
