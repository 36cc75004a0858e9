#pragma once
// Imports filled SVG icons as diffusion curves: one closed curve per contour of every filled
// shape (path, rect, circle, ellipse, polygon), with the fill colour on the inside side and the
// background (or the colour of the enclosing fill) on the outside side. Inside is decided per
// contour with the shape's fill rule (nonzero / evenodd) applied to the whole shape, so holes
// get the surrounding colour on their inside.

#include <string>

#include "vicc_glyphs/dci/diffusion_curve.hpp"
#include "vicc_glyphs/io/format_error.hpp"

namespace vicc_glyphs {

struct SvgImportOptions {
  Color background{1, 1, 1};  ///< colour outside every shape
  int size = 0;               ///< 0 = keep the viewBox size, else scale to this width in pixels
};

/// Reads an SVG file. Throws FormatError.
DiffusionCurveImage importSvg(const std::string& path, const SvgImportOptions& options = {});
/// Parses SVG text. Throws FormatError (source "<string>").
DiffusionCurveImage parseSvg(const std::string& text, const SvgImportOptions& options = {});

}  // namespace vicc_glyphs
