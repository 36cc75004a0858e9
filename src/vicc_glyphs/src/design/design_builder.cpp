#include "vicc_glyphs/design/design_builder.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <set>
#include <string>
#include <utility>

#include "gradient_channels.hpp"
#include "vicc_glyphs/io/format_error.hpp"
#include "vicc_glyphs/io/orzan_xml.hpp"
#include "vicc_glyphs/io/svg_import.hpp"
#include "vicc_glyphs/pacemod/dashes.hpp"
#include "vicc_glyphs/pacemod/image_frame.hpp"
#include "vicc_glyphs/pacemod/inflate.hpp"
#include "vicc_glyphs/pacemod/periodic_waves.hpp"
#include "vicc_glyphs/pacemod/skipped_curves.hpp"

namespace vicc_glyphs::design {
namespace {

using perception::VisualVariable;

// An encoding with the data level it is driven by.
struct Active {
  const Encoding* encoding;
  int level;
  const std::string* variable;  ///< the name of the variable that drives it (for errors)
};

// Colours that match the one a design replaces (8-bit colours / 255 from the importers).
constexpr double kColorTolerance = kSameColorTolerance;

double pixelsPerMm(const DiffusionCurveImage& image, const GlyphDesign& design) {
  return image.width / design.size_mm;
}

// Returns how many colour points it replaced.
int replaceColor(std::vector<ColorPoint>& points, const Color& from, const Color& to) {
  int replaced = 0;
  for (ColorPoint& point : points) {
    if ((point.rgb - from).cwiseAbs().maxCoeff() <= kColorTolerance) {
      point.rgb = to;
      ++replaced;
    }
  }
  return replaced;
}

// The importer records, on each side of a boundary that two shapes share, the neighbour's
// colour. A region that a level hides or shrinks loses those contacts: its neighbours' records
// of its colour take its surroundings' colour (the dominant colour outside it), and a shrunk
// region's outside becomes that colour all round. Otherwise the stale colours would diffuse
// into the gap as a haze.
void releaseNeighbourColors(DiffusionCurveImage& image, const std::set<int>& released) {
  for (int index : released) {
    if (index < 0 || index >= static_cast<int>(image.curves.size())) continue;
    DiffusionCurve& curve = image.curves[static_cast<size_t>(index)];
    const bool left_inside = enclosedSideIsLeft(curve);
    std::vector<ColorPoint>& outer = left_inside ? curve.right_colors : curve.left_colors;
    const auto inside = dominantColor(left_inside ? curve.left_colors : curve.right_colors);
    const auto outside = dominantColor(outer);
    if (!inside || !outside) continue;
    for (ColorPoint& point : outer) point.rgb = *outside;
    // Only the other curves' outer sides: a region of the same colour keeps its own fill.
    for (size_t other = 0; other < image.curves.size(); ++other) {
      if (released.count(static_cast<int>(other))) continue;
      DiffusionCurve& neighbour = image.curves[other];
      replaceColor(enclosedSideIsLeft(neighbour) ? neighbour.right_colors : neighbour.left_colors,
                   *inside, *outside);
    }
  }
}

// A fill-colour change: the selected curves on both sides, the others' outer sides, where
// they recorded the recoloured region as their neighbour (a region of the same colour that is
// not selected keeps its own fill). A colour to replace that the selected curves do not have
// would leave every level looking the same: an error naming the encoding's key.
void recolorRegion(DiffusionCurveImage& image, const std::vector<int>& curves, const Color& from,
                   const Color& to, const std::string& where) {
  int selected_points = 0;
  for (size_t index = 0; index < image.curves.size(); ++index) {
    DiffusionCurve& curve = image.curves[index];
    const bool selected =
        std::find(curves.begin(), curves.end(), static_cast<int>(index)) != curves.end();
    const bool left_inside = enclosedSideIsLeft(curve);
    int replaced = 0;
    if (selected || !left_inside) replaced += replaceColor(curve.left_colors, from, to);
    if (selected || left_inside) replaced += replaceColor(curve.right_colors, from, to);
    if (selected) selected_points += replaced;
  }
  if (selected_points == 0) {
    char hex[8];
    std::snprintf(hex, sizeof hex, "%02x%02x%02x", static_cast<int>(std::lround(from[0] * 255)),
                  static_cast<int>(std::lround(from[1] * 255)),
                  static_cast<int>(std::lround(from[2] * 255)));
    throw DesignError(where + ": the colour to replace, " + hex +
                      ", is not on the selected curves of the icon, so every level would look "
                      "the same");
  }
}

void scaleAboutCentre(DiffusionCurveImage& image, const std::vector<int>& curves, double factor) {
  const Point2 centre(0.5 * image.width, 0.5 * image.height);
  for (int index : curves) {
    DiffusionCurve& curve = image.curves[static_cast<size_t>(index)];
    for (Point2& p : curve.control_points) p = centre + factor * (p - centre);
    for (BlurPoint& b : curve.blur_points) b.sigma *= factor;
  }
}

int modelLevel(const Active& active) {
  return active.encoding->model_levels[static_cast<size_t>(active.level)];
}

double stimulusOf(const Active& active, VisualVariable variable, const GlyphDesign& design,
                  const perception::PerceptionModel& model) {
  return model.stimulus(variable, modelLevel(active), design.size_mm, active.encoding->waveform)
      .stimulus;
}

pacemod::Waveform pacemodWaveform(perception::Waveform waveform) {
  return *pacemod::parseWaveform(perception::toString(waveform));
}

// A value no selected curve can show would pass for another level (a glyph without waves reads
// as the lowest frequency): the design's modification must land on at least one curve.
template <class Reports>
void requireShown(const Reports& reports, const std::string& what) {
  const std::string reason = pacemod::nothingModifiedReason(reports);
  if (!reason.empty()) {
    throw std::invalid_argument(what + " cannot be drawn on any selected curve (" + reason + ")");
  }
}

// Geometric frequency and amplitude on the same curves form one wave; alone, the other wave
// parameter is the encoding's fixed value.
void applyWaveEncodings(DiffusionCurveImage& image, const std::vector<Active>& active,
                        const GlyphDesign& design, const perception::PerceptionModel& model) {
  std::set<size_t> used;
  for (size_t i = 0; i < active.size(); ++i) {
    const Channel channel = active[i].encoding->channel;
    if (used.count(i) ||
        (channel != Channel::GeometricFrequency && channel != Channel::GeometricAmplitude)) {
      continue;
    }
    const std::vector<int> curves = pacemod::selectCurves(image, active[i].encoding->curves);
    pacemod::WaveSpec spec;
    bool unmodified = false;  // a model level of -1 on either parameter: no wave
    spec.waveform = pacemodWaveform(active[i].encoding->waveform);
    spec.amplitude_mm = active[i].encoding->amplitude_mm;
    spec.waves_per_mm = active[i].encoding->waves_per_10mm / 10.0;
    for (size_t j = i; j < active.size(); ++j) {
      const Channel other = active[j].encoding->channel;
      if (pacemod::selectCurves(image, active[j].encoding->curves) != curves) continue;
      if ((other == Channel::GeometricFrequency || other == Channel::GeometricAmplitude) &&
          modelLevel(active[j]) < 0) {
        unmodified = true;
        used.insert(j);
      } else if (other == Channel::GeometricFrequency) {
        spec.waves_per_mm =
            1.0 / stimulusOf(active[j], VisualVariable::GeometricFrequency, design, model);
        used.insert(j);
      } else if (other == Channel::GeometricAmplitude) {
        spec.amplitude_mm =
            stimulusOf(active[j], VisualVariable::GeometricAmplitude, design, model);
        used.insert(j);
      }
    }
    if (!unmodified) {
      requireShown(pacemod::applyWaves(image, curves, spec, design.size_mm),
                   "design " + design.name + ": the waves");
    }
  }
}

// `rgb` with its HSV value set to `value`; hue and saturation kept.
Color withValue(const Color& rgb, double value) {
  const double max = rgb.maxCoeff();
  if (!(max > 0.0)) return Color::Constant(value);  // black: a grey of that value
  return rgb * (value / max);
}

// The dash colour: the encoding's, with the HSV value of a colour_amplitude encoding on the same
// curves (the value contrast of the dashes, Table 6.1), if there is one with a level >= 0.
Color dashColor(const DiffusionCurveImage& image, const Active& dashes,
                const std::vector<Active>& active, const GlyphDesign& design,
                const perception::PerceptionModel& model) {
  Color color = dashes.encoding->dash_color;
  const std::vector<int> curves = pacemod::selectCurves(image, dashes.encoding->curves);
  for (const Active& a : active) {
    if (a.encoding->channel != Channel::ColourAmplitude || modelLevel(a) < 0 ||
        pacemod::selectCurves(image, a.encoding->curves) != curves) {
      continue;
    }
    color = withValue(color, stimulusOf(a, VisualVariable::ColourAmplitude, design, model));
  }
  return color;
}

// Dashes of model level `level` on a contour of `length_mm`: round(length / the level's colour
// period), at least 1; on a short contour neighbouring levels can round to the same count, so
// each of the encoding's levels (increasing frequency) gets at least one more dash than the
// level below it: every data level stays apart on every contour.
int dashCount(double length_mm, const Active& active, int level, const GlyphDesign& design,
              const perception::PerceptionModel& model) {
  std::vector<int> used;
  for (int l : active.encoding->model_levels) {
    if (l >= 0) used.push_back(l);
  }
  std::sort(used.begin(), used.end());
  used.erase(std::unique(used.begin(), used.end()), used.end());
  int count = 0;
  for (int l : used) {
    const double period_mm =
        model
            .stimulus(VisualVariable::ColourFrequency, l, design.size_mm, active.encoding->waveform)
            .stimulus;
    count = std::max({1, static_cast<int>(std::lround(length_mm / period_mm)), count + 1});
    if (l == level) break;
  }
  return count;
}

void applyDashEncoding(DiffusionCurveImage& image, const Active& active,
                       const std::vector<int>& curves, const Color& color,
                       const GlyphDesign& design, const perception::PerceptionModel& model) {
  if (modelLevel(active) < 0) return;
  std::vector<pacemod::CurveDashReport> reports;
  for (int index : curves) {
    const pacemod::ChainArcLength arc(image.curves[static_cast<size_t>(index)]);
    const double length_mm = arc.totalLength() / pixelsPerMm(image, design);
    pacemod::DashSpec spec;
    spec.color = color;
    spec.count = dashCount(length_mm, active, modelLevel(active), design, model);
    for (const pacemod::CurveDashReport& report :
         pacemod::applyDashes(image, {index}, spec, design.size_mm)) {
      reports.push_back(report);
    }
  }
  requireShown(reports, "design " + design.name + ": the dashes");
}

std::vector<int> without(const std::vector<int>& curves, const std::set<int>& hidden) {
  std::vector<int> kept;
  for (int c : curves) {
    if (!hidden.count(c)) kept.push_back(c);
  }
  return kept;
}

// Band and centre region of the gradient glyph, on the (possibly waved) contours.
void applyGradientEncodings(DiffusionCurveImage& image, const std::vector<Active>& active,
                            const std::set<int>& hidden, const GlyphDesign& design) {
  ContourInsets insets(design.size_mm);  // the band and the centre share a sampled contour
  for (const Active& a : active) {
    const Encoding& e = *a.encoding;
    if (e.channel != Channel::Band && e.channel != Channel::CentreDashes) continue;
    const size_t level = static_cast<size_t>(a.level);
    for (int index : without(pacemod::selectCurves(image, e.curves), hidden)) {
      if (e.channel == Channel::Band) {
        addContourBand(image, index, insets, e.band_mm, e.value_factors[level],
                       e.saturation_factors[level]);
      } else {
        addDashedCentre(image, index, insets, e.inset_mm, e.dash_counts[level], e.colors[level],
                        design.size_mm);
      }
    }
  }
}

std::vector<int> allCurves(size_t count) {
  std::vector<int> curves(count);
  for (size_t i = 0; i < count; ++i) curves[i] = static_cast<int>(i);
  return curves;
}

// A level whose modification reaches beyond the glyph (an inflation, waves or a scale near the
// limits) would be clipped by the renderer: part of the encoding cut off, another level shown.
void requireInsideFrame(const DiffusionCurveImage& before, const DiffusionCurveImage& after,
                        const std::vector<int>& curves, const GlyphDesign& design,
                        const std::vector<int>& levels) {
  const std::optional<int> out = pacemod::curveCarriedOutOfFrame(before, after, curves);
  if (!out) return;
  std::string level_list;
  for (int level : levels) level_list += (level_list.empty() ? "" : ",") + std::to_string(level);
  throw std::invalid_argument("design " + design.name + ": the glyph of levels " + level_list +
                              " carries curve " + std::to_string(*out) + " out of the " +
                              std::to_string(after.width) + " x " + std::to_string(after.height) +
                              " px frame, where it would be clipped");
}

// The encodings of `design` with the data levels that drive them; throws DesignValueError for
// a wrong number of levels or one out of range.
std::vector<Active> activeEncodings(const GlyphDesign& design, const std::vector<int>& levels) {
  if (levels.size() != design.variables.size()) {
    throw DesignValueError("design " + design.name + " needs " +
                           std::to_string(design.variables.size()) + " levels");
  }
  std::vector<Active> active;
  for (size_t v = 0; v < levels.size(); ++v) {
    const DesignVariable& variable = design.variables[v];
    if (levels[v] < 0 || levels[v] >= variable.levelCount()) {
      throw DesignValueError(variable.name + ": level " + std::to_string(levels[v]) +
                             " out of range");
    }
    for (const Encoding& encoding : variable.encodings) {
      active.push_back({&encoding, levels[v], &variable.name});
    }
  }
  return active;
}

}  // namespace

DiffusionCurveImage loadIcon(const GlyphDesign& design, int size_px) {
  const int size = size_px > 0 ? size_px : design.size_px;
  std::string extension = std::filesystem::path(design.icon_path).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(), ::tolower);
  if (extension == ".svg") {
    SvgImportOptions options;
    options.background = design.background;
    options.size = size;
    return importSvg(design.icon_path, options);
  }
  if (extension == ".xml") return scaledToWidth(readOrzanXml(design.icon_path), size);
  throw FormatError(design.icon_path + ": design icons must be .svg or .xml (no raster import)");
}

DiffusionCurveImage buildGlyph(const GlyphDesign& design, const std::vector<int>& levels,
                               const perception::PerceptionModel& model, int size_px) {
  activeEncodings(design, levels);  // a level out of range fails before the import
  return buildGlyph(design, levels, model, loadIcon(design, size_px));
}

DiffusionCurveImage buildGlyph(const GlyphDesign& design, const std::vector<int>& levels,
                               const perception::PerceptionModel& model, DiffusionCurveImage icon) {
  const std::vector<Active> active = activeEncodings(design, levels);
  const DiffusionCurveImage original = icon;
  DiffusionCurveImage image = std::move(icon);
  const size_t icon_curves = image.curves.size();
  std::set<int> hidden;
  for (const Active& a : active) {
    if (a.encoding->channel != Channel::Hide) continue;
    const auto& curves = a.encoding->hidden[static_cast<size_t>(a.level)];
    hidden.insert(curves.begin(), curves.end());
  }
  std::set<int> released = hidden;
  for (const Active& a : active) {
    if (a.encoding->channel != Channel::Inflate || a.encoding->numbers[a.level] >= 0.0) continue;
    for (int index : pacemod::selectCurves(image, a.encoding->curves)) released.insert(index);
  }
  releaseNeighbourColors(image, released);
  for (const Active& a : active) {
    const std::vector<int> curves = pacemod::selectCurves(image, a.encoding->curves);
    const size_t level = static_cast<size_t>(a.level);
    if (a.encoding->channel == Channel::FillColor) {
      recolorRegion(image, curves, a.encoding->replace, a.encoding->colors[level],
                    "variable " + *a.variable + ", fill_color encoding (replace)");
    } else if (a.encoding->channel == Channel::GlyphScale) {
      scaleAboutCentre(image, curves, a.encoding->numbers[level]);
    }
  }
  for (const Active& a : active) {
    if (a.encoding->channel != Channel::Inflate) continue;
    const double offset = a.encoding->numbers[static_cast<size_t>(a.level)];
    const std::vector<int> curves =
        without(pacemod::selectCurves(image, a.encoding->curves), hidden);
    if (offset != 0.0) {
      requireShown(pacemod::inflateCurves(image, curves, offset, design.size_mm),
                   "design " + design.name + ": the inflation");
    }
  }
  applyWaveEncodings(image, active, design, model);
  applyGradientEncodings(image, active, hidden, design);
  for (const Active& a : active) {
    if (a.encoding->channel != Channel::ColourFrequency) continue;
    applyDashEncoding(image, a, without(pacemod::selectCurves(image, a.encoding->curves), hidden),
                      dashColor(image, a, active, design, model), design, model);
  }
  requireInsideFrame(original, image, without(allCurves(icon_curves), hidden), design, levels);
  for (auto it = hidden.rbegin(); it != hidden.rend(); ++it) {
    if (*it < 0 || *it >= static_cast<int>(icon_curves)) {
      throw std::invalid_argument("design " + design.name + ": hidden curve " +
                                  std::to_string(*it) + " is not a curve of the icon");
    }
    image.curves.erase(image.curves.begin() + *it);
  }
  return image;
}

}  // namespace vicc_glyphs::design
