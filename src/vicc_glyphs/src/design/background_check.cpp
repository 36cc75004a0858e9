#include "vicc_glyphs/design/background_check.hpp"

#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <chrono>
#include <exception>

namespace vicc_glyphs::design {
namespace {

// Thrown from checkDesign's progress callback to leave it between two combinations.
struct Stopped {};

// Linux schedules threads by their own nice value: the check yields to requests on a busy
// machine. Where that fails the check runs at the server's priority, which is only slower for
// requests; nothing to report.
void lowerThisThreadsPriority() {
#if defined(__linux__)
  setpriority(PRIO_PROCESS, static_cast<id_t>(syscall(SYS_gettid)), 10);
#endif
}

}  // namespace

BackgroundDesignCheck::BackgroundDesignCheck(Designs designs,
                                             const perception::PerceptionModel& model,
                                             std::function<void(const Outcome&)> report)
    : thread_([this, designs = std::move(designs), &model, report = std::move(report)] {
        run(designs, model, report);
      }) {}

BackgroundDesignCheck::~BackgroundDesignCheck() {
  stop_ = true;
  wait();
}

void BackgroundDesignCheck::wait() {
  if (thread_.joinable()) thread_.join();
}

void BackgroundDesignCheck::run(const Designs& designs, const perception::PerceptionModel& model,
                                const std::function<void(const Outcome&)>& report) {
  lowerThisThreadsPriority();
  const auto stopCheck = [this](int, int) {
    if (stop_) throw Stopped{};
  };
  for (const auto& [name, design] : designs) {
    if (stop_) return;
    Outcome outcome;
    outcome.name = name;
    const auto start = std::chrono::steady_clock::now();
    try {
      outcome.check = checkDesign(*design, model, 0, stopCheck);
    } catch (const Stopped&) {
      return;
    } catch (const std::exception& e) {
      outcome.error = e.what();
    }
    outcome.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    try {
      report(outcome);
    } catch (const std::exception&) {
      // Escaping this thread, it would end the server that answers requests; the report is
      // only the log of a check.
    }
  }
}

}  // namespace vicc_glyphs::design
