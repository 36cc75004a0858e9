#pragma once
// Walks an SVG document: the viewport (viewBox or width/height, scaled to the requested
// width), <style> sheets, groups with their transforms and inherited styles, <use>
// references, every filled or stroked path or basic shape, opacity and clip-path layers,
// painted in document order into a planar map of colour regions.

#include <string>

#include "paint_map.hpp"
#include "vicc_glyphs/io/svg_import.hpp"

namespace vicc_glyphs {
namespace io_detail {

struct SvgPicture {
  int width = 0;
  int height = 0;
  IntegerFrame frame;
  ResolvedPicture resolved;  ///< the colour regions over options.background
};

/// Parses SVG text; throws FormatError naming `source` and the offending element.
SvgPicture readSvgPicture(const std::string& text, const std::string& source,
                          const SvgImportOptions& options);

}  // namespace io_detail
}  // namespace vicc_glyphs
