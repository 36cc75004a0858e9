// SVG icons to diffusion curves: every contour of every filled shape becomes one closed curve,
// oriented so that its own shape's filled side is on the left, with the colours actually seen
// on either side (its fill, the background, or a shape below or above it).

#include "vicc_glyphs/io/svg_import.hpp"

#include <algorithm>
#include <cmath>

#include "side_colors.hpp"
#include "svg_document.hpp"
#include "text_file.hpp"

namespace vicc_glyphs {
namespace {

using io_detail::FilledShape;
using io_detail::SideSample;

constexpr std::size_t kMaxSamplesPerCurve = 64;

// Small against the picture and against the local flattening step (1/32 of a Bezier at most),
// so the offset point stays beside the curve, on the side it is meant for.
double sampleOffset(double speed, double diagonal) {
  return std::min(1e-3 * diagonal, speed / 128.0);
}

// True if the shape's own fill lies mostly on the right of the curve.
bool fillOnRight(const FilledShape& shape, const std::vector<SideSample>& samples) {
  int right_votes = 0;
  for (const SideSample& sample : samples) {
    const bool left = shape.contains(sample.left);
    const bool right = shape.contains(sample.right);
    if (left != right) right_votes += right ? 1 : -1;
  }
  return right_votes > 0;
}

DiffusionCurveImage toCurves(const io_detail::SvgPicture& picture, const Color& background) {
  DiffusionCurveImage image;
  image.width = picture.width;
  image.height = picture.height;
  const double diagonal = std::hypot(picture.width, picture.height);
  auto offset = [diagonal](double speed) { return sampleOffset(speed, diagonal); };
  auto color_at = [&](const Point2& p) { return picture.scene.colorAt(p); };
  for (const FilledShape& shape : picture.scene.shapes()) {
    for (const io_detail::Contour& contour : shape.contours) {
      DiffusionCurve curve;
      curve.control_points = contour;
      auto samples = io_detail::sideSamples(curve, 1, kMaxSamplesPerCurve, offset);
      if (fillOnRight(shape, samples)) {
        std::reverse(curve.control_points.begin(), curve.control_points.end());
        samples = io_detail::sideSamples(curve, 1, kMaxSamplesPerCurve, offset);
      }
      io_detail::assignSideColors(curve, samples, color_at, background);
      image.curves.push_back(std::move(curve));
    }
  }
  return image;
}

DiffusionCurveImage importFrom(const std::string& text, const std::string& source,
                               const SvgImportOptions& options) {
  const io_detail::SvgPicture picture = io_detail::readSvgPicture(text, source, options);
  DiffusionCurveImage image = toCurves(picture, options.background);
  const std::string problem = validate(image);
  if (!problem.empty()) throw FormatError(source, "", problem);
  return image;
}

}  // namespace

DiffusionCurveImage parseSvg(const std::string& text, const SvgImportOptions& options) {
  return importFrom(text, "<string>", options);
}

DiffusionCurveImage importSvg(const std::string& path, const SvgImportOptions& options) {
  return importFrom(io_detail::readTextFile(path), path, options);
}

}  // namespace vicc_glyphs
