#pragma once
// checkDesign for a set of designs on a thread of its own, for a server that answers requests
// meanwhile: a design that loads can still fail for some data (design_check.hpp), and the
// operator should learn which at start-up, not when such data arrive at the bedside.

#include <atomic>
#include <functional>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "vicc_glyphs/design/design_check.hpp"

namespace vicc_glyphs::design {

class BackgroundDesignCheck {
 public:
  struct Outcome {
    std::string name;
    DesignCheck check;  ///< empty when `error` is set
    std::string error;  ///< what checkDesign threw (e.g. the icon could not be read)
    double seconds = 0.0;
  };
  using Designs = std::vector<std::pair<std::string, const GlyphDesign*>>;

  /// Checks `designs` (name, design) one after the other at their own sizes on a new thread
  /// (scheduled at a lower priority where the system allows) and calls `report` on that thread
  /// after each. The designs and `model` must outlive this object and not change meanwhile.
  BackgroundDesignCheck(Designs designs, const perception::PerceptionModel& model,
                        std::function<void(const Outcome&)> report);
  /// Stops after the level combination being built (the design being checked is not reported)
  /// and joins the thread.
  ~BackgroundDesignCheck();
  BackgroundDesignCheck(const BackgroundDesignCheck&) = delete;
  BackgroundDesignCheck& operator=(const BackgroundDesignCheck&) = delete;

  /// Blocks until every design has been checked.
  void wait();

 private:
  void run(const Designs& designs, const perception::PerceptionModel& model,
           const std::function<void(const Outcome&)>& report);

  std::atomic<bool> stop_{false};
  std::thread thread_;
};

}  // namespace vicc_glyphs::design
