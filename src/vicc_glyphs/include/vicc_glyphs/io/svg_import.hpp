#pragma once
// Imports SVG icons as diffusion curves. The document is painted as SVG paints it (document
// order, source-over): fills (nonzero / evenodd), strokes turned into filled outlines (width,
// caps, joins, miter limit, dashes), currentColor, fill/stroke/group opacity blended over the
// background, <use>, <style> rules with simple selectors, and clip-path by boolean
// intersection. The resulting colour regions (shapes of one colour merged) give one closed
// curve per boundary polygon, the region's colour on its left and the colour across on its
// right. Anything else that would change the picture (text, images, masks, filters, markers,
// gradients and patterns, ...) is a FormatError naming it, or with `lenient` a warning.
// Details: docs/import.md.

#include <functional>
#include <string>

#include "vicc_glyphs/dci/diffusion_curve.hpp"
#include "vicc_glyphs/io/format_error.hpp"

namespace vicc_glyphs {

/// Largest image an SVG may produce (width x height in pixels at the requested size), so that
/// a thin viewBox scaled to a width or a huge viewBox fails cleanly instead of exhausting
/// memory in the renderer.
constexpr double kMaxSvgPixels = 4096.0 * 4096.0;

/// How strokes become filled outlines: Clipper's offsetting of the flattened path, or offset
/// curves of the Beziers themselves (docs/import.md, bench/fidelity/README.md session 18).
enum class StrokeOutliner { kClipper, kCurves };

struct SvgImportOptions {
  Color background{1, 1, 1};     ///< colour outside every shape
  int size = 0;                  ///< 0 = keep the viewBox size, else scale to this width in pixels
  Color current_color{0, 0, 0};  ///< currentColor where no `color` property sets it
  bool lenient = false;          ///< unsupported features: warning and left out, not an error
  std::function<void(const std::string&)> warn;  ///< receives lenient warnings (may be empty)
  StrokeOutliner stroke_outliner = StrokeOutliner::kClipper;  ///< stroke outlines (see above)
};

/// Reads an SVG file. Throws FormatError, also when the picture shows nothing.
DiffusionCurveImage importSvg(const std::string& path, const SvgImportOptions& options = {});
/// Parses SVG text. Throws FormatError (source "<string>").
DiffusionCurveImage parseSvg(const std::string& text, const SvgImportOptions& options = {});

}  // namespace vicc_glyphs
