#pragma once
// Glyph designs as data (thesis 6.2.5): a YAML file names a base icon (SVG or Orzan XML, no
// raster import) and, per data variable, its domain, the bin edges that make data levels, and
// the encodings that each level drives: perception-model visual variables (geometric frequency
// and amplitude as PACEMOD waves, colour frequency as dashes) or explicit per-level channels
// (inflate, fill colour, glyph scale, hidden curves). The file format is described in
// docs/glyphs/README.md; designs/*.yaml are the shipped designs.

#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "vicc_glyphs/dci/diffusion_curve.hpp"
#include "vicc_glyphs/pacemod/curve_selection.hpp"
#include "vicc_glyphs/perception/perception_model.hpp"

namespace vicc_glyphs::design {

/// A design file that is malformed or inconsistent; the message names the file and key.
struct DesignError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// A data value a design cannot show (unknown name, missing, NaN, outside the domain); the
/// message names the variable.
struct DesignValueError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

enum class Channel {
  GeometricFrequency,  ///< waves per mm from the perception level (period), fixed amplitude
  GeometricAmplitude,  ///< wave amplitude from the perception level, fixed frequency
  ColourFrequency,     ///< dashes: count = round(arc length / colour period of the level)
  /// HSV value V of the level (Table 6.1: 0.425-0.85) for the dashes of the colour_frequency
  /// encodings on the same curves (their dash colour keeps its hue and saturation)
  ColourAmplitude,
  Inflate,       ///< offsets_mm per data level
  FillColor,     ///< colours per data level, replacing the icon colour `replace`
  GlyphScale,    ///< scale about the image centre per data level
  Hide,          ///< per data level, the channel's curves that are hidden
  Band,          ///< gradient glyph: contour band, value/saturation factors per level
  CentreDashes,  ///< gradient glyph: dashed central region, dash count + colour per level
};

struct Encoding {
  Channel channel = Channel::Inflate;
  pacemod::CurveSelection curves;
  /// Perception channels: the model level of each data level (-1: no modification).
  std::vector<int> model_levels;
  perception::Waveform waveform = perception::Waveform::Sine;
  double amplitude_mm = 0.5;               ///< GeometricFrequency: fixed amplitude
  double waves_per_10mm = 3.0;             ///< GeometricAmplitude: fixed frequency
  Color dash_color{1, 1, 1};               ///< ColourFrequency
  std::vector<double> numbers;             ///< Inflate: offsets in mm; GlyphScale: factors
  std::vector<Color> colors;               ///< FillColor
  Color replace{0, 0, 0};                  ///< FillColor: the icon colour that is replaced
  std::vector<std::vector<int>> hidden;    ///< Hide: curve indices hidden per data level
  double band_mm = 1.0;                    ///< Band: width
  std::vector<double> value_factors;       ///< Band: HSV value factor per data level
  std::vector<double> saturation_factors;  ///< Band: HSV saturation factor per data level
  double inset_mm = 2.0;                   ///< CentreDashes: the region's distance inside
  std::vector<int> dash_counts;            ///< CentreDashes: per data level (0: none)
};

struct DesignVariable {
  std::string name;
  double lower = 0.0, upper = 1.0;  ///< domain (inclusive)
  /// Increasing inner bin edges, edges.size() + 1 levels: a value equal to edge i goes to the
  /// upper bin ([a, b[ bins) unless edge_belongs_below[i] (]a, b] bins).
  std::vector<double> edges;
  std::vector<bool> edge_belongs_below;  ///< one per edge
  std::vector<Encoding> encodings;
  int levelCount() const { return static_cast<int>(edges.size()) + 1; }
};

/// Glyph widths in pixels that designs, `vicc_glyph modify` and the glyph server accept: below
/// 16 px a glyph's waves, dashes and levels cannot be told apart (a wave period of the
/// perception model's range would be a fraction of a pixel).
constexpr int kMinGlyphPixels = 16;
constexpr int kMaxGlyphPixels = 4096;

struct GlyphDesign {
  std::string name;
  std::string description;
  std::string icon_path;  ///< resolved against the design file's directory
  double size_mm = 50.0;  ///< physical glyph width for the perception model
  int size_px = 256;      ///< default raster width
  Color background{1, 1, 1};
  std::vector<DesignVariable> variables;

  /// Data level of every variable, in `variables` order. Throws DesignValueError for an
  /// unknown name, a missing variable, NaN or a value outside the domain.
  std::vector<int> levelsFor(const std::map<std::string, double>& values) const;
};

/// Parses a design; `base_dir` resolves the icon path. Validates against `model`: every
/// perception level exists at the design's size, per-level lists have one entry per data
/// level. Throws DesignError naming the key.
GlyphDesign parseDesign(const std::string& yaml_text, const std::string& base_dir,
                        const perception::PerceptionModel& model);
GlyphDesign loadDesign(const std::string& path, const perception::PerceptionModel& model);

}  // namespace vicc_glyphs::design
