// vicc_extrapolation_error: the error of the EKF's virtual measurements (Eq. 5.13-5.15)
// against the simulator's ground truth, per frame step, and the exponent of its growth with
// the frame interval (docs/imu_noise.md).
//   usage: vicc_extrapolation_error SCENARIO... [--steps 1,2,4]
#include <cstdio>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "vicc_tracking/sim/extrapolation_error.hpp"
#include "vicc_tracking/sim/scenario.hpp"

namespace {

std::vector<int> parseSteps(const std::string& text) {
  std::vector<int> steps;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ',')) {
    size_t used = 0;
    const int step = std::stoi(item, &used);
    if (used != item.size() || step < 1) throw std::invalid_argument("bad --steps entry " + item);
    steps.push_back(step);
  }
  return steps;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> scenarios;
  std::vector<int> steps = {1, 2, 4};
  try {
    for (int i = 1; i < argc; ++i) {
      const std::string arg = argv[i];
      if (arg == "--steps" && i + 1 < argc) {
        steps = parseSteps(argv[++i]);
      } else if (arg.empty() || arg[0] == '-') {
        throw std::invalid_argument("usage: vicc_extrapolation_error SCENARIO... [--steps 1,2,4]");
      } else {
        scenarios.push_back(arg);
      }
    }
    if (scenarios.empty()) throw std::invalid_argument("no scenario given");
    std::printf("| scenario | step | interval s | R_q | R_v | R_p |\n|---|---|---|---|---|---|\n");
    for (const std::string& name : scenarios) {
      const vicc_tracking::sim::RigSimulator rig(vicc_tracking::sim::loadScenario(name));
      std::vector<vicc_tracking::sim::ExtrapolationError> errors;
      for (int step : steps) {
        errors.push_back(vicc_tracking::sim::measureExtrapolationError(rig, step));
        const auto& e = errors.back();
        std::printf("| %s | %d | %.4f | %.3g | %.3g | %.3g |\n", name.c_str(), step, e.interval,
                    e.rotation, e.velocity, e.position);
      }
      if (errors.size() >= 2) {
        const auto k = vicc_tracking::sim::fitIntervalExponents(errors);
        std::printf("| %s | exponent k | | %.2f | %.2f | %.2f |\n", name.c_str(), k.rotation,
                    k.velocity, k.position);
      }
    }
  } catch (const std::exception& error) {
    std::cerr << "vicc_extrapolation_error: " << error.what() << "\n";
    return 2;
  }
  return 0;
}
