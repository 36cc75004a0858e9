#include "vicc_glyphs/io/load.hpp"

#include <algorithm>
#include <cctype>

#include "text_file.hpp"
#include "vicc_glyphs/io/orzan_xml.hpp"
#include "vicc_glyphs/io/raster_import.hpp"
#include "vicc_glyphs/io/svg_import.hpp"
#include "vicc_glyphs/io/usvg_scene_xml.hpp"

namespace vicc_glyphs {
namespace {

std::string lowerExtension(const std::string& path) {
  const auto dot = path.find_last_of('.');
  const auto slash = path.find_last_of("/\\");
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return {};
  std::string extension = path.substr(dot + 1);
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension;
}

// Both XML formats share the .xml extension; the root element tells them apart
// (<scene>: small-usvg SceneXML, otherwise Orzan's <curve_set>).
DiffusionCurveImage loadXml(const std::string& path) {
  const std::string text = io_detail::readTextFile(path);
  if (hasUsvgSceneRoot(text)) return parseUsvgSceneXml(text, path);
  return readOrzanXml(path);
}

DiffusionCurveImage loadByExtension(const std::string& path, int size,
                                    const SvgImportOptions& svg) {
  const std::string extension = lowerExtension(path);
  if (extension == "xml") return loadXml(path);
  if (extension == "svg") {
    SvgImportOptions options = svg;
    options.size = size;
    return importSvg(path, options);
  }
  if (extension == "png") return importRaster(path);
  throw FormatError(path, "",
                    "unknown extension '" + extension + "' (expected .xml, .svg or .png)");
}

}  // namespace

DiffusionCurveImage loadDiffusionCurves(const std::string& path, int size) {
  return loadDiffusionCurves(path, size, SvgImportOptions{});
}

DiffusionCurveImage loadDiffusionCurves(const std::string& path, int size,
                                        const SvgImportOptions& svg) {
  if (size < 0) throw FormatError(path, "", "negative target size");
  DiffusionCurveImage image = loadByExtension(path, size, svg);
  const std::string extension = lowerExtension(path);
  if (size > 0 && extension != "svg") image = scaledToWidth(image, size);
  const std::string problem = validate(image);
  if (!problem.empty()) throw FormatError(path, "", problem);
  return image;
}

}  // namespace vicc_glyphs
