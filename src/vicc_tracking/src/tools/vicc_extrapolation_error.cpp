// vicc_extrapolation_error: the error of the EKF's virtual measurements (Eq. 5.13-5.15)
// against the simulator's ground truth, per frame step, and the exponent of its growth with
// the frame interval (docs/imu_noise.md).
//   usage: vicc_extrapolation_error SCENARIO... [--steps 1,2,4]
#include <cstdio>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "vicc_common/command_line.hpp"
#include "vicc_tracking/sim/extrapolation_error.hpp"
#include "vicc_tracking/sim/scenario.hpp"

namespace {

namespace cli = vicc_common::cli;

constexpr const char* kUsage = "usage: vicc_extrapolation_error SCENARIO... [--steps 1,2,4]";

std::vector<int> parseSteps(const std::string& text) {
  std::vector<int> steps;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ',')) steps.push_back(cli::parseInteger("steps", item, 1, 1000));
  if (steps.empty()) throw cli::UsageError("--steps needs at least one frame step");
  return steps;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> scenarios;
  std::vector<int> steps = {1, 2, 4};
  try {
    const cli::ParsedArguments parsed = cli::parseArguments(
        std::vector<std::string>(argv + 1, argv + argc), {{"steps", "N,...", ""}});
    scenarios = parsed.positional;
    if (parsed.has("steps")) steps = parseSteps(parsed.value("steps"));
    if (scenarios.empty()) throw cli::UsageError("no scenario given");
  } catch (const cli::UsageError& error) {
    std::cerr << "vicc_extrapolation_error: " << error.what() << "\n" << kUsage << "\n";
    return 2;
  }
  try {
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
    return 1;
  }
  return 0;
}
