#include "vicc_avatar_snapshot_environment.hpp"

#include <X11/Xlib.h>
#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <signal.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <sstream>
#include <stdexcept>
#include <thread>

namespace vicc_anatomy_viz::snapshot {
namespace {

using Clock = std::chrono::steady_clock;

int freeTcpPort() {
  const int fd = socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  socklen_t length = sizeof(address);
  int port = -1;
  if (fd >= 0 && bind(fd, reinterpret_cast<sockaddr*>(&address), sizeof(address)) == 0 &&
      getsockname(fd, reinterpret_cast<sockaddr*>(&address), &length) == 0)
    port = ntohs(address.sin_port);
  if (fd >= 0) close(fd);
  if (port <= 0) throw std::runtime_error("no free local TCP port for the private ROS master");
  return port;
}

bool portAnswers(int port) {
  const int fd = socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_port = htons(static_cast<uint16_t>(port));
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  const bool answers =
      fd >= 0 && connect(fd, reinterpret_cast<sockaddr*>(&address), sizeof(address)) == 0;
  if (fd >= 0) close(fd);
  return answers;
}

}  // namespace

ChildProcess::ChildProcess(const std::vector<std::string>& argv, int keep_fd) {
  const std::string path = findOnPath(argv.at(0));
  if (path.empty()) throw std::runtime_error(argv[0] + " is not installed (not on PATH)");
  std::vector<char*> args;
  for (const std::string& arg : argv) args.push_back(const_cast<char*>(arg.c_str()));
  args.push_back(nullptr);
  pid_ = fork();
  if (pid_ < 0) throw std::runtime_error("cannot start " + argv[0]);
  if (pid_ == 0) {
    // Quiet child in its own process group; only `keep_fd` stays open besides stdio.
    setpgid(0, 0);
    for (int fd = 3; fd < 1024; ++fd)
      if (fd != keep_fd) close(fd);
    if (freopen("/dev/null", "w", stdout) == nullptr ||
        freopen("/dev/null", "w", stderr) == nullptr)
      _exit(126);
    execv(path.c_str(), args.data());
    _exit(127);
  }
}

ChildProcess::~ChildProcess() { stop(); }

ChildProcess::ChildProcess(ChildProcess&& other) noexcept : pid_(other.pid_) { other.pid_ = -1; }

ChildProcess& ChildProcess::operator=(ChildProcess&& other) noexcept {
  if (this != &other) {
    stop();
    pid_ = other.pid_;
    other.pid_ = -1;
  }
  return *this;
}

bool ChildProcess::running() {
  if (pid_ <= 0) return false;
  int status = 0;
  if (waitpid(pid_, &status, WNOHANG) == pid_) {
    pid_ = -1;
    return false;
  }
  return true;
}

void ChildProcess::stop() {
  if (pid_ <= 0) return;
  kill(-pid_, SIGTERM);
  const auto deadline = Clock::now() + std::chrono::seconds(3);
  int status = 0;
  while (waitpid(pid_, &status, WNOHANG) == 0) {
    if (Clock::now() > deadline) {
      kill(-pid_, SIGKILL);
      waitpid(pid_, &status, 0);
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  pid_ = -1;
}

std::string findOnPath(const std::string& name) {
  if (name.find('/') != std::string::npos) return access(name.c_str(), X_OK) == 0 ? name : "";
  const char* path = std::getenv("PATH");
  std::istringstream dirs(path ? path : "/usr/bin:/bin");
  std::string dir;
  while (std::getline(dirs, dir, ':')) {
    const std::string candidate = (dir.empty() ? "." : dir) + "/" + name;
    if (access(candidate.c_str(), X_OK) == 0) return candidate;
  }
  return "";
}

bool displayAnswers(const std::string& display) {
  Display* connection = XOpenDisplay(display.c_str());
  if (!connection) return false;
  XCloseDisplay(connection);
  return true;
}

std::string startXvfb(int width, int height, ChildProcess& process) {
  if (findOnPath("Xvfb").empty())
    throw std::runtime_error(
        "no display server: DISPLAY is not set and Xvfb is not installed "
        "(apt-get install xvfb), or set DISPLAY");
  int fds[2];
  if (pipe(fds) != 0) throw std::runtime_error("cannot create a pipe for Xvfb");
  const std::string screen = std::to_string(width + 64) + "x" + std::to_string(height + 64) + "x24";
  process = ChildProcess({"Xvfb", "-displayfd", std::to_string(fds[1]), "-screen", "0", screen,
                          "-nolisten", "tcp", "-noreset"},
                         fds[1]);
  close(fds[1]);
  // Xvfb writes its display number to the descriptor once it accepts clients.
  std::string number;
  pollfd wait{fds[0], POLLIN, 0};
  const auto deadline = Clock::now() + std::chrono::seconds(15);
  char c = 0;
  while (Clock::now() < deadline && poll(&wait, 1, 200) >= 0) {
    if (!(wait.revents & (POLLIN | POLLHUP))) continue;
    if (read(fds[0], &c, 1) != 1 || c == '\n') break;
    number += c;
  }
  close(fds[0]);
  if (number.empty() || !process.running())
    throw std::runtime_error("no display server: Xvfb did not start");
  return ":" + number;
}

std::string startPrivateMaster(ChildProcess& process) {
  const int port = freeTcpPort();
  process = ChildProcess({"rosmaster", "--core", "-p", std::to_string(port), "-w", "1"});
  const auto deadline = Clock::now() + std::chrono::seconds(20);
  while (!portAnswers(port)) {
    if (!process.running() || Clock::now() > deadline)
      throw std::runtime_error("the private ROS master (rosmaster) did not start");
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  return "http://127.0.0.1:" + std::to_string(port) + "/";
}

}  // namespace vicc_anatomy_viz::snapshot
