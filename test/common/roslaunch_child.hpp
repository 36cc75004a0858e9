#pragma once
// Shared by the rostests that run a launch file as a child process (replay.launch with
// exit_at_end, SIGINT): start roslaunch, spin while it runs, and learn whether and how it ended.

#include <fcntl.h>
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

/// Runs `arguments[0]` (looked up on PATH: roslaunch, rosrun) as a child process; its pid, 0
/// if it could not be started. With `output_file`, the child's stdout and stderr go there (the
/// test reads what it printed).
inline pid_t startProcess(const std::vector<std::string>& arguments,
                          const std::string& output_file = "") {
  std::vector<char*> argv;
  for (const std::string& argument : arguments) argv.push_back(const_cast<char*>(argument.c_str()));
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  if (!output_file.empty()) {
    posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, output_file.c_str(),
                                     O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
  }
  pid_t pid = 0;
  const int result = posix_spawnp(&pid, argv[0], &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  return result == 0 ? pid : 0;
}

inline pid_t startRoslaunch(const std::vector<std::string>& arguments,
                            const std::string& output_file = "") {
  return startProcess(arguments, output_file);
}

/// Sends SIGINT (Ctrl-C) to the child and waits up to `limit` for it to exit; true if it did.
/// A child still running then is killed, so no test leaves a graph behind.
inline bool interruptChild(pid_t child, ros::WallDuration limit, int& wait_status) {
  kill(child, SIGINT);
  const ros::WallTime deadline = ros::WallTime::now() + limit;
  while (ros::WallTime::now() < deadline) {
    if (waitpid(child, &wait_status, WNOHANG) == child) return true;
    ros::WallDuration(0.05).sleep();
  }
  kill(child, SIGKILL);
  waitpid(child, &wait_status, 0);
  return false;
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
