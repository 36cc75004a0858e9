#include "svg_shapes.hpp"

#include <algorithm>
#include <stdexcept>

#include "svg_arc.hpp"
#include "svg_number_scanner.hpp"

namespace vicc_glyphs {
namespace io_detail {
namespace {

void arcTo(ContourBuilder& builder, double rx, double ry, bool sweep, const Point2& end) {
  const std::vector<Point2> points = arcToCubics(builder.current(), rx, ry, 0.0, false, sweep, end);
  for (std::size_t i = 0; i + 2 < points.size(); i += 3) {
    builder.cubicTo(points[i], points[i + 1], points[i + 2]);
  }
}

void ellipse(ContourBuilder& builder, double cx, double cy, double rx, double ry) {
  builder.moveTo(Point2(cx + rx, cy));
  arcTo(builder, rx, ry, true, Point2(cx, cy + ry));
  arcTo(builder, rx, ry, true, Point2(cx - rx, cy));
  arcTo(builder, rx, ry, true, Point2(cx, cy - ry));
  arcTo(builder, rx, ry, true, Point2(cx + rx, cy));
  builder.close();
}

// Corner radii follow the SVG rules: one given radius applies to both, each is capped at half
// the side.
void rect(const tinyxml2::XMLElement& e, ContourBuilder& builder) {
  const double x = svgLength(e, "x", 0.0);
  const double y = svgLength(e, "y", 0.0);
  const double w = svgLength(e, "width", 0.0);
  const double h = svgLength(e, "height", 0.0);
  if (w < 0.0 || h < 0.0) throw std::invalid_argument("negative rect size");
  if (w == 0.0 || h == 0.0) return;
  double rx = svgLength(e, "rx", -1.0);
  double ry = svgLength(e, "ry", -1.0);
  if (rx < 0.0) rx = std::max(ry, 0.0);
  if (ry < 0.0) ry = rx;
  rx = std::min(rx, w / 2.0);
  ry = std::min(ry, h / 2.0);
  builder.moveTo(Point2(x + rx, y));
  builder.lineTo(Point2(x + w - rx, y));
  if (rx > 0.0 && ry > 0.0) arcTo(builder, rx, ry, true, Point2(x + w, y + ry));
  builder.lineTo(Point2(x + w, y + h - ry));
  if (rx > 0.0 && ry > 0.0) arcTo(builder, rx, ry, true, Point2(x + w - rx, y + h));
  builder.lineTo(Point2(x + rx, y + h));
  if (rx > 0.0 && ry > 0.0) arcTo(builder, rx, ry, true, Point2(x, y + h - ry));
  builder.lineTo(Point2(x, y + ry));
  if (rx > 0.0 && ry > 0.0) arcTo(builder, rx, ry, true, Point2(x + rx, y));
  builder.close();
}

void polygon(const tinyxml2::XMLElement& e, ContourBuilder& builder, bool closed) {
  const char* points = e.Attribute("points");
  if (!points) throw std::invalid_argument("missing attribute points");
  const std::string text(points);
  SvgNumberScanner scanner(text);
  bool first = true;
  while (scanner.numberAhead()) {
    const double x = scanner.number();
    const Point2 p(x, scanner.number());
    if (first) {
      builder.moveTo(p);
    } else {
      builder.lineTo(p);
    }
    first = false;
  }
  if (!scanner.atEnd()) throw std::invalid_argument("unexpected text in points");
  if (closed) builder.close();
}

void line(const tinyxml2::XMLElement& e, ContourBuilder& builder) {
  builder.moveTo(Point2(svgLength(e, "x1", 0.0), svgLength(e, "y1", 0.0)));
  builder.lineTo(Point2(svgLength(e, "x2", 0.0), svgLength(e, "y2", 0.0)));
}

}  // namespace

double svgLength(const tinyxml2::XMLElement& element, const char* name, double fallback) {
  const char* raw = element.Attribute(name);
  if (!raw) return fallback;
  std::string text(raw);
  const auto unit = text.find("px");
  if (unit != std::string::npos && unit + 2 == text.find_last_not_of(" \t\r\n") + 1) {
    text.erase(unit);
  }
  SvgNumberScanner scanner(text);
  const double value = scanner.number();
  if (!scanner.atEnd()) {
    throw std::invalid_argument(std::string("unsupported length ") + name + "=\"" + raw + "\"");
  }
  return value;
}

bool isBasicShape(const std::string& name) {
  return name == "rect" || name == "circle" || name == "ellipse" || name == "polygon" ||
         name == "polyline" || name == "line";
}

std::vector<Contour> basicShapeContours(const tinyxml2::XMLElement& element, PointBudget& budget) {
  return closedContours(basicShapeSubpaths(element, budget));
}

std::vector<Subpath> basicShapeSubpaths(const tinyxml2::XMLElement& element, PointBudget& budget) {
  ContourBuilder builder(budget);
  const std::string name = element.Name();
  if (name == "rect") {
    rect(element, builder);
  } else if (name == "circle") {
    const double r = svgLength(element, "r", 0.0);
    if (r < 0.0) throw std::invalid_argument("negative radius");
    if (r > 0.0)
      ellipse(builder, svgLength(element, "cx", 0.0), svgLength(element, "cy", 0.0), r, r);
  } else if (name == "ellipse") {
    const double rx = svgLength(element, "rx", 0.0);
    const double ry = svgLength(element, "ry", 0.0);
    if (rx < 0.0 || ry < 0.0) throw std::invalid_argument("negative radius");
    if (rx > 0.0 && ry > 0.0) {
      ellipse(builder, svgLength(element, "cx", 0.0), svgLength(element, "cy", 0.0), rx, ry);
    }
  } else if (name == "polygon" || name == "polyline") {
    polygon(element, builder, name == "polygon");
  } else if (name == "line") {
    line(element, builder);
  } else {
    throw std::invalid_argument("not a basic shape: " + name);
  }
  return builder.finishSubpaths();
}

}  // namespace io_detail
}  // namespace vicc_glyphs
