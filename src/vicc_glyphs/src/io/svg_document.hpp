#pragma once
// Walks an SVG document: the viewport (viewBox or width/height, scaled to the requested
// width), groups with their transforms and inherited styles, and every filled path or basic
// shape, collected in painting order as contours in pixel coordinates.

#include <string>

#include "fill_regions.hpp"
#include "vicc_glyphs/io/svg_import.hpp"

namespace vicc_glyphs {
namespace io_detail {

struct SvgPicture {
  int width = 0;
  int height = 0;
  PaintedScene scene{Color(1, 1, 1)};
};

/// Parses SVG text; throws FormatError naming `source` and the offending element.
SvgPicture readSvgPicture(const std::string& text, const std::string& source,
                          const SvgImportOptions& options);

}  // namespace io_detail
}  // namespace vicc_glyphs
