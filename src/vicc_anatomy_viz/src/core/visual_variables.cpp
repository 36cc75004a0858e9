#include "vicc_anatomy_viz/visual_variables.hpp"

#include <algorithm>
#include <cmath>

#include "vicc_anatomy_viz/errors.hpp"

namespace vicc_anatomy_viz {

std::string toString(Channel channel) {
  switch (channel) {
    case Channel::kSaturationBrightness:
      return "saturation_brightness";
    case Channel::kTexture:
      return "texture";
    case Channel::kTransparency:
      return "transparency";
  }
  return "?";
}

Channel channelFromString(const std::string& text) {
  if (text == "saturation_brightness") return Channel::kSaturationBrightness;
  if (text == "texture") return Channel::kTexture;
  if (text == "transparency") return Channel::kTransparency;
  if (text == "hue") {
    throw ConfigError("hue is the category variable a^c and cannot encode a property");
  }
  throw ConfigError("unknown channel '" + text +
                    "' (expected saturation_brightness, texture or transparency)");
}

int VisualVariable::distinguishableValues() const {
  return channel == Channel::kTexture ? static_cast<int>(texture_levels.size()) : range;
}

double VisualVariable::spread(int level, int level_count) {
  if (level_count <= 1) return 1.0;  // a single level uses the strongest value
  return static_cast<double>(level - 1) / static_cast<double>(level_count - 1);
}

void VisualVariable::validate() const {
  const std::string where = "visual variable '" + id + "'";
  if (id.empty()) throw ConfigError("a visual variable has no id");
  if (distinguishableValues() < 1) {
    throw ConfigError(where + ": needs at least one distinguishable value");
  }
  auto unit = [&](double value, const char* name) {
    if (!(value >= 0.0 && value <= 1.0)) {
      throw ConfigError(where + ": " + name + " must be within [0, 1]");
    }
  };
  unit(saturation_weak, "saturation");
  unit(saturation_strong, "saturation");
  unit(brightness_weak, "brightness");
  unit(brightness_strong, "brightness");
  unit(unindicated_saturation, "unindicated_saturation");
  unit(unindicated_brightness, "unindicated_brightness");
  unit(alpha_weak, "alpha");
  unit(alpha_strong, "alpha");
  for (const auto& level : texture_levels) {
    if (!(level.frequency > 0.0) || !(level.amplitude > 0.0) || !std::isfinite(level.frequency) ||
        !std::isfinite(level.amplitude)) {
      throw ConfigError(where + ": texture levels need positive frequency and amplitude");
    }
  }
}

Rgba hsvToRgba(double hue_degrees, double saturation, double value, double alpha) {
  double h = std::fmod(hue_degrees, 360.0);
  if (h < 0.0) h += 360.0;
  const double s = std::clamp(saturation, 0.0, 1.0);
  const double v = std::clamp(value, 0.0, 1.0);
  const double c = v * s;
  const double x = c * (1.0 - std::fabs(std::fmod(h / 60.0, 2.0) - 1.0));
  const double m = v - c;
  double r = 0, g = 0, b = 0;
  if (h < 60) {
    r = c, g = x;
  } else if (h < 120) {
    r = x, g = c;
  } else if (h < 180) {
    g = c, b = x;
  } else if (h < 240) {
    g = x, b = c;
  } else if (h < 300) {
    r = x, b = c;
  } else {
    r = c, b = x;
  }
  return Rgba{static_cast<float>(r + m), static_cast<float>(g + m), static_cast<float>(b + m),
              static_cast<float>(std::clamp(alpha, 0.0, 1.0))};
}

}  // namespace vicc_anatomy_viz
