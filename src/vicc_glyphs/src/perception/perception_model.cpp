#include "vicc_glyphs/perception/perception_model.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <tuple>

namespace vicc_glyphs::perception {
namespace {

// Guards the level count against dv dividing the range exactly up to rounding.
constexpr double kCountTolerance = 1e-9;

std::string number(double value) {
  std::ostringstream text;
  text << value;
  return text.str();
}

bool isGeometric(VisualVariable variable) {
  return variable == VisualVariable::GeometricAmplitude ||
         variable == VisualVariable::GeometricFrequency;
}

// Physical range [low, high] of the variable after the size-transfer rules of 6.1.5.
std::pair<double, double> transferredRange(const VariableModel& model, const SizeTransfer& rules,
                                           double scale) {
  double low = model.scale.physicalLow();
  double high = model.scale.physicalHigh();
  if (model.scales_with_size && scale < 1.0) {
    low *= std::max(scale, std::min(1.0, rules.min_scale));
    high *= std::min(1.0, scale + rules.epsilon);
  }
  return {low, high};
}

}  // namespace

const VariableModel& PerceptionModel::variable(VisualVariable which) const {
  const auto found = variables.find(which);
  if (found == variables.end()) {
    throw std::out_of_range("perception model has no entry for " + toString(which));
  }
  return found->second;
}

VariableLevels PerceptionModel::levels(VisualVariable which, double size_mm,
                                       Waveform waveform) const {
  if (!std::isfinite(size_mm) || !(size_mm > 0.0)) {
    throw std::invalid_argument("glyph size must be a positive number of mm, got " +
                                number(size_mm));
  }
  const VariableModel& model = variable(which);
  VariableLevels result;
  result.variable = which;
  result.size_mm = size_mm;
  std::tie(result.range_low, result.range_high) =
      transferredRange(model, size_transfer, size_mm / reference_size_mm);
  const double adu_a = model.scale.adu(result.range_low);
  const double adu_b = model.scale.adu(result.range_high);
  const double adu_low = std::min(adu_a, adu_b);
  const double adu_high = std::max(adu_a, adu_b);
  if (!(result.range_high > result.range_low) || !(adu_low > 0.0)) {
    throw std::domain_error(toString(which) + ": a glyph of " + number(size_mm) +
                            " mm leaves no usable stimulus range (" + number(result.range_low) +
                            " .. " + number(result.range_high) + ")");
  }
  result.perceived_low = model.stevens.perceived(adu_low);
  result.perceived_high = model.stevens.perceived(adu_high);
  const int count = static_cast<int>(std::floor((result.perceived_high - result.perceived_low) /
                                                    model.quantization_step +
                                                kCountTolerance)) +
                    1;
  const auto calibration = model.calibrations.find(waveform);
  const bool calibrate = isGeometric(which) && calibration != model.calibrations.end();
  for (int i = 0; i < count; ++i) {
    StimulusLevel level;
    level.index = i;
    level.perceived_adu = result.perceived_low + i * model.quantization_step;
    level.stimulus_adu = model.stevens.stimulusFor(level.perceived_adu);
    if (calibrate) level.stimulus_adu = calibration->second.apply(level.stimulus_adu);
    level.stimulus = model.scale.physical(level.stimulus_adu);
    result.levels.push_back(level);
  }
  return result;
}

int PerceptionModel::levelCount(VisualVariable which, double size_mm) const {
  return static_cast<int>(levels(which, size_mm).levels.size());
}

StimulusLevel PerceptionModel::stimulus(VisualVariable which, int level, double size_mm,
                                        Waveform waveform) const {
  const VariableLevels all = levels(which, size_mm, waveform);
  if (level < 0 || level >= static_cast<int>(all.levels.size())) {
    throw std::out_of_range(toString(which) + " has " + std::to_string(all.levels.size()) +
                            " levels at " + number(size_mm) + " mm; level " +
                            std::to_string(level) + " does not exist");
  }
  return all.levels[static_cast<size_t>(level)];
}

std::string PerceptionModel::problem() const {
  if (!std::isfinite(reference_size_mm) || !(reference_size_mm > 0.0)) {
    return "reference_size_mm must be > 0";
  }
  if (!(size_transfer.min_scale > 0.0) || !(size_transfer.min_scale <= 1.0)) {
    return "size_transfer.min_scale must be in (0, 1]";
  }
  if (!std::isfinite(size_transfer.epsilon) || !(size_transfer.epsilon >= 0.0)) {
    return "size_transfer.epsilon must be >= 0";
  }
  for (const auto& [which, model] : variables) {
    const std::string name = "variables." + toString(which);
    if (const std::string p = model.scale.problem(); !p.empty()) return name + ".stimulus: " + p;
    if (const std::string p = model.stevens.problem(); !p.empty()) return name + ".stevens: " + p;
    if (!std::isfinite(model.quantization_step) || !(model.quantization_step > 0.0)) {
      return name + ".quantization_step must be > 0";
    }
    for (const auto& [waveform, h] : model.calibrations) {
      if (!std::isfinite(h.k) || !std::isfinite(h.l) || !(h.k > 0.0)) {
        return name + ".waveform_calibration." + toString(waveform) + ": needs finite k > 0, l";
      }
    }
  }
  return "";
}

int levelForValue(double value, double lower, double upper, int level_count,
                  const std::string& name) {
  if (level_count < 1) throw std::invalid_argument(name + ": level count must be >= 1");
  if (!std::isfinite(lower) || !std::isfinite(upper) || !(upper > lower)) {
    throw std::invalid_argument(name + ": data domain [" + number(lower) + ", " + number(upper) +
                                "] is empty");
  }
  if (std::isnan(value)) throw std::domain_error(name + " is NaN");
  if (value < lower || value > upper) {
    throw std::domain_error(name + " = " + number(value) + " is outside its domain [" +
                            number(lower) + ", " + number(upper) + "]");
  }
  const int bin = static_cast<int>(std::floor((value - lower) / (upper - lower) * level_count));
  return std::min(bin, level_count - 1);
}

}  // namespace vicc_glyphs::perception
