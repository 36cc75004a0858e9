#include "svg_viewport.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "svg_number_scanner.hpp"
#include "svg_shapes.hpp"
#include "vicc_glyphs/io/svg_import.hpp"

namespace vicc_glyphs {
namespace io_detail {

SvgViewport svgViewport(const tinyxml2::XMLElement& root, int size) {
  double x = 0.0, y = 0.0, w = 0.0, h = 0.0;
  if (const char* view_box = root.Attribute("viewBox")) {
    const std::string text(view_box);
    SvgNumberScanner scanner(text);
    x = scanner.number();
    y = scanner.number();
    w = scanner.number();
    h = scanner.number();
    if (!scanner.atEnd()) throw std::invalid_argument("viewBox needs exactly 4 numbers");
  } else {
    w = svgLength(root, "width", 0.0);
    h = svgLength(root, "height", 0.0);
  }
  if (!(w > 0.0) || !(h > 0.0)) {
    throw std::invalid_argument("no positive size: need viewBox or width and height");
  }
  const double scale = size > 0 ? size / w : 1.0;
  const double width = std::ceil(w * scale - 1e-9);
  const double height = std::ceil(h * scale - 1e-9);
  if (!(width >= 1.0) || !(height >= 1.0) || !(width * height <= kMaxSvgPixels)) {
    std::ostringstream message;
    message.precision(12);
    message << "image of " << width << " x " << height << " pixels (viewBox " << w << " x " << h
            << (size > 0 ? " at width " + std::to_string(size) : std::string()) << "): "
            << "outside 1 .. " << kMaxSvgPixels << " pixels (the limit)";
    throw std::invalid_argument(message.str());
  }
  SvgViewport viewport;
  viewport.width = static_cast<int>(width);
  viewport.height = static_cast<int>(height);
  viewport.user_to_pixels.scale(scale).translate(Eigen::Vector2d(-x, -y));
  return viewport;
}

}  // namespace io_detail
}  // namespace vicc_glyphs
