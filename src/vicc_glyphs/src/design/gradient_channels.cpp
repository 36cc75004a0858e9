#include "gradient_channels.hpp"

#include <algorithm>
#include <optional>
#include <stdexcept>

#include "vicc_glyphs/pacemod/dashes.hpp"
#include "vicc_glyphs/pacemod/offset_contour.hpp"
#include "vicc_glyphs/pacemod/polyline.hpp"

namespace vicc_glyphs::design {
namespace {

// The colour of a contour's enclosed side: the one that covered most of it (the thesis assumes
// homogeneous regions, 6.2.3.1; a mean would mix in a neighbour's colour the side recorded).
Color insideColor(const DiffusionCurve& contour, bool left_inside, int index) {
  const std::optional<Color> color =
      dominantColor(left_inside ? contour.left_colors : contour.right_colors);
  if (!color || !(left_inside ? contour.left_emits : contour.right_emits)) {
    throw std::invalid_argument("curve " + std::to_string(index) +
                                " has no colour on its inside for a band or a dashed centre");
  }
  return *color;
}

std::vector<ColorPoint> constantColor(const Color& rgb, double end) {
  return {{0.0, rgb}, {end, rgb}};
}

// HSV value and saturation scaled, hue kept; results clamped to [0, 1].
Color scaledValueAndSaturation(const Color& rgb, double value_factor, double saturation_factor) {
  const double max = rgb.maxCoeff(), min = rgb.minCoeff();
  const double value = std::clamp(max * value_factor, 0.0, 1.0);
  const double saturation =
      std::clamp((max > 0.0 ? (max - min) / max : 0.0) * saturation_factor, 0.0, 1.0);
  Color result;
  for (int c = 0; c < 3; ++c) {
    // Position of the channel between min and max, kept (this keeps the hue).
    const double t = max > min ? (rgb[c] - min) / (max - min) : 1.0;
    const double low = value * (1.0 - saturation);
    result[c] = low + t * (value - low);
  }
  return result;
}

}  // namespace

DiffusionCurve ContourInsets::inset(const DiffusionCurveImage& image, int index, double offset_mm) {
  auto contour = contours_.find(index);
  if (contour == contours_.end()) {
    contour =
        contours_.emplace(index, pacemod::sampleCurve(image.curves.at(static_cast<size_t>(index))))
            .first;
  }
  const double pixels_per_mm = image.width / glyph_size_mm_;
  const pacemod::Polyline line =
      pacemod::offsetIsoline(contour->second, -offset_mm * pixels_per_mm);
  if (line.size() < 4) {
    throw std::invalid_argument("curve " + std::to_string(index) + ": nothing is left " +
                                std::to_string(offset_mm) + " mm inside it");
  }
  DiffusionCurve inset;
  inset.control_points = pacemod::closedBezierFit(line);
  return inset;
}

bool enclosedSideIsLeft(const DiffusionCurve& curve) {
  // Positive shoelace area = clockwise on screen (y down): the enclosed region is on the right.
  return pacemod::polylineArea(pacemod::sampleCurve(curve)) < 0.0;
}

void addContourBand(DiffusionCurveImage& image, int index, ContourInsets& insets, double band_mm,
                    double value_factor, double saturation_factor) {
  if (value_factor == 1.0 && saturation_factor == 1.0) return;
  DiffusionCurve band_edge = insets.inset(image, index, band_mm);
  DiffusionCurve& contour = image.curves[static_cast<size_t>(index)];
  const bool left_inside = enclosedSideIsLeft(contour);
  std::vector<ColorPoint>& contour_inside =
      left_inside ? contour.left_colors : contour.right_colors;
  const Color inner = insideColor(contour, left_inside, index);
  const Color band = scaledValueAndSaturation(inner, value_factor, saturation_factor);
  contour_inside = constantColor(band, contour.segmentCount());
  const double end = band_edge.segmentCount();
  // Same orientation: the isoline's enclosed side faces the glyph's inside, the other the band.
  (left_inside ? band_edge.left_colors : band_edge.right_colors) = constantColor(inner, end);
  (left_inside ? band_edge.right_colors : band_edge.left_colors) = constantColor(band, end);
  image.curves.push_back(band_edge);
}

void addDashedCentre(DiffusionCurveImage& image, int index, ContourInsets& insets, double inset_mm,
                     int dashes, const Color& color, double glyph_size_mm) {
  DiffusionCurve centre = insets.inset(image, index, inset_mm);
  const DiffusionCurve& contour = image.curves[static_cast<size_t>(index)];
  const Color inner = insideColor(contour, enclosedSideIsLeft(contour), index);
  const double end = centre.segmentCount();
  centre.left_colors = constantColor(inner, end);
  centre.right_colors = constantColor(inner, end);
  image.curves.push_back(centre);
  if (dashes == 0) return;
  pacemod::DashSpec spec;
  spec.count = dashes;
  spec.color = color;
  pacemod::applyDashes(image, {static_cast<int>(image.curves.size()) - 1}, spec, glyph_size_mm);
}

}  // namespace vicc_glyphs::design
