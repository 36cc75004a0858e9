#pragma once
// Visual variables A and their ranges of distinguishable values (thesis 4.3.2.2): hue (the
// category variable a^c), the composite saturation-brightness, textures and transparency.

#include <string>
#include <vector>

namespace vicc_anatomy_viz {

/// What a visual variable changes on the rendered structure. Two properties of one category
/// must use different channels, since a structure shows one intensity and one texture.
enum class Channel { kSaturationBrightness, kTexture, kTransparency };

std::string toString(Channel channel);
Channel channelFromString(const std::string& text);  ///< throws ConfigError

struct NamedHue {
  std::string name;
  double degrees = 0.0;
};

struct TextureLevel {
  double frequency = 0.0;
  double amplitude = 0.0;
};

struct VisualVariable {
  std::string id;
  Channel channel = Channel::kSaturationBrightness;
  /// Saturation-brightness and transparency: number of distinguishable levels.
  int range = 0;
  double saturation_weak = 0.3, saturation_strong = 1.0;
  double brightness_weak = 1.0, brightness_strong = 0.6;
  double unindicated_saturation = 0.12, unindicated_brightness = 1.0;
  double alpha_weak = 0.85, alpha_strong = 0.35;
  /// Texture: one frequency/amplitude pair per distinguishable level.
  std::vector<TextureLevel> texture_levels;

  /// |a.range|: how many values of this variable can be told apart.
  int distinguishableValues() const;
  /// Position in [0, 1] of level `level` (1..level_count) spread over the variable's range,
  /// so that few levels use the most distinct values.
  static double spread(int level, int level_count);
  void validate() const;  ///< throws ConfigError naming the variable
};

struct Rgba {
  float r = 0.f, g = 0.f, b = 0.f, a = 1.f;
};

/// HSV (hue in degrees, saturation and value in [0, 1]) to RGB.
Rgba hsvToRgba(double hue_degrees, double saturation, double value, double alpha = 1.0);

}  // namespace vicc_anatomy_viz
