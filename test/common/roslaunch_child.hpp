#pragma once
// Shared by the rostests that run a launch file or a tool as a child process (replay.launch
// with exit_at_end, roslaunch --nodes, SIGINT, vicc_patient): start it, spin while it runs,
// learn whether and how it ended and what it printed.

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
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

/// The whole text of a file ("" if it cannot be read): what a child printed there.
inline std::string readTextFile(const std::string& path) {
  std::ifstream file(path);
  std::stringstream text;
  text << file.rdbuf();
  return text.str();
}

/// How a child run to its end went.
struct ChildRun {
  bool started = false;
  bool ended = false;   ///< by itself within the limit (else it was stopped with SIGINT)
  int wait_status = 0;  ///< as waitpid reports it
  std::string printed;  ///< stdout and stderr, when an output file was given

  /// The exit code; -1 if it did not end by itself or not normally.
  int exitCode() const { return ended && WIFEXITED(wait_status) ? WEXITSTATUS(wait_status) : -1; }
};

/// Runs `arguments` (as startProcess) and spins until it ends or `limit` has passed; a child
/// still running then is stopped with SIGINT. With `output_file`, `printed` is what it printed.
inline ChildRun runToEnd(const std::vector<std::string>& arguments, ros::WallDuration limit,
                         const std::string& output_file = "") {
  ChildRun run;
  const pid_t child = startProcess(arguments, output_file);
  run.started = child != 0;
  if (run.started) run.ended = waitForChildExit(child, limit, run.wait_status);
  if (!output_file.empty()) run.printed = readTextFile(output_file);
  return run;
}

/// roslaunch's own log of the process `roslaunch` in this run's log directory (ROS_LOG_DIR,
/// else ROS_HOME/log, else ~/.ros/log; then the run id): each node's stop with its time, which
/// tells what held up a slow stop. Without the line that lists the environment (not for test
/// output); "" if it is not there.
inline std::string roslaunchOwnLog(pid_t roslaunch) {
  std::string run_id;
  if (!ros::param::get("/run_id", run_id)) return "";
  std::filesystem::path dir;
  if (const char* log_dir = std::getenv("ROS_LOG_DIR")) {
    dir = log_dir;
  } else if (const char* ros_home = std::getenv("ROS_HOME")) {
    dir = std::filesystem::path(ros_home) / "log";
  } else if (const char* home = std::getenv("HOME")) {
    dir = std::filesystem::path(home) / ".ros" / "log";
  } else {
    return "";
  }
  char host[256] = {};
  gethostname(host, sizeof(host) - 1);
  const std::string name =
      "roslaunch-" + std::string(host) + "-" + std::to_string(roslaunch) + ".log";
  std::ifstream file(dir / run_id / name);
  std::string text, line;
  while (std::getline(file, line)) {
    if (line.find("roslaunch env is") == std::string::npos) text += line + "\n";
  }
  return text;
}

/// Ctrl-C to a running roslaunch, and the checks of a clean stop: it ends within `limit` with
/// exit code 0, and no node had to be escalated to SIGTERM (roslaunch waits 15 s per node
/// before it does) or died. `output_file` holds what roslaunch printed.
inline void expectCleanSigintStop(pid_t roslaunch, const std::string& output_file,
                                  ros::WallDuration limit = ros::WallDuration(10.0)) {
  int wait_status = 0;
  const bool ended = interruptChild(roslaunch, limit, wait_status);
  const std::string printed = readTextFile(output_file);
  EXPECT_TRUE(ended) << "roslaunch did not end within " << limit.toSec() << " s of SIGINT:\n"
                     << printed << "\nroslaunch's own log:\n"
                     << roslaunchOwnLog(roslaunch);
  EXPECT_TRUE(WIFEXITED(wait_status) && WEXITSTATUS(wait_status) == 0)
      << "wait status " << wait_status << "\n"
      << printed;
  EXPECT_EQ(printed.find("escalating"), std::string::npos) << printed;
  EXPECT_EQ(printed.find("has died"), std::string::npos) << printed;
}

}  // namespace vicc_test
