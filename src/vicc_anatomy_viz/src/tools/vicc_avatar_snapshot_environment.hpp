#pragma once
// What vicc_avatar_snapshot needs around rviz: an X display (Xvfb started when there is none)
// and a private ROS master (so no roscore is needed), both ended with the process.

#include <sys/types.h>

#include <string>
#include <vector>

namespace vicc_anatomy_viz::snapshot {

/// A child process killed (SIGTERM, then SIGKILL) and reaped on destruction.
class ChildProcess {
 public:
  ChildProcess() = default;
  /// Starts argv[0] found on PATH; throws std::runtime_error when it cannot.
  explicit ChildProcess(const std::vector<std::string>& argv, int keep_fd = -1);
  ~ChildProcess();
  ChildProcess(ChildProcess&& other) noexcept;
  ChildProcess& operator=(ChildProcess&& other) noexcept;
  bool running();

 private:
  void stop();
  pid_t pid_ = -1;
};

/// An executable's path on PATH, "" when there is none.
std::string findOnPath(const std::string& name);

/// Whether an X server answers at `display` (e.g. ":0").
bool displayAnswers(const std::string& display);

/// Starts Xvfb with a screen of at least width x height and returns its display name;
/// throws std::runtime_error (Xvfb missing or not starting).
std::string startXvfb(int width, int height, ChildProcess& process);

/// Starts `rosmaster --core` on a free local port and waits until it answers; returns its
/// URI. Throws std::runtime_error.
std::string startPrivateMaster(ChildProcess& process);

}  // namespace vicc_anatomy_viz::snapshot
