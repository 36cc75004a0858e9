// SVG icons to diffusion curves: the document is painted into a planar map of colour regions
// (svg_document.cpp, paint_map.cpp) and every region boundary becomes a closed curve with the
// region's colour on its left and the neighbouring colours on its right (region_curves.cpp).

#include "vicc_glyphs/io/svg_import.hpp"

#include "region_curves.hpp"
#include "svg_document.hpp"
#include "text_file.hpp"

namespace vicc_glyphs {
namespace {

DiffusionCurveImage importFrom(const std::string& text, const std::string& source,
                               const SvgImportOptions& options) {
  const io_detail::SvgPicture picture = io_detail::readSvgPicture(text, source, options);
  if (picture.resolved.regions.empty()) {
    throw FormatError(source, "",
                      picture.resolved.painted
                          ? "everything drawn has the background colour: nothing to show"
                          : "draws nothing: no filled or stroked shape inside the viewBox");
  }
  DiffusionCurveImage image =
      io_detail::regionCurves(picture.resolved, picture.frame, picture.width, picture.height);
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
