#include "svg_path_data.hpp"

#include <cctype>
#include <stdexcept>

#include "svg_arc.hpp"
#include "svg_number_scanner.hpp"

namespace vicc_glyphs {
namespace io_detail {
namespace {

class PathDataParser {
 public:
  PathDataParser(const std::string& d, PointBudget& budget) : scanner_(d), builder_(budget) {}

  std::vector<Subpath> parse() {
    char command = 0;
    while (!scanner_.atEnd()) {
      const char next = scanner_.peek();
      if (std::isalpha(static_cast<unsigned char>(next))) {
        command = next;
        scanner_.advance();
      } else if (command == 0 || command == 'Z' || command == 'z') {
        fail(std::string("expected a path command, found '") + next + "'");
      }
      // A number without a new command repeats the last one (M/m repeat as L/l).
      const std::size_t before = scanner_.position();
      execute(command);
      if (command == 'M') command = 'L';
      if (command == 'm') command = 'l';
      if (command != 'Z' && command != 'z' && scanner_.position() == before) {
        fail("no progress parsing path");
      }
    }
    return builder_.finishSubpaths();
  }

 private:
  [[noreturn]] void fail(const std::string& what) const {
    throw std::invalid_argument(what + " at offset " + std::to_string(scanner_.position()));
  }

  Point2 point(bool relative) {
    const double x = scanner_.number();
    const double y = scanner_.number();
    return relative ? Point2(builder_.current() + Point2(x, y)) : Point2(x, y);
  }

  void execute(char command) {
    const bool relative = std::islower(static_cast<unsigned char>(command));
    const Point2 current = builder_.current();
    Point2 reflected_cubic = current;
    Point2 reflected_quad = current;
    if (last_ == 'C' || last_ == 'S') reflected_cubic = 2.0 * current - last_cubic_control_;
    if (last_ == 'Q' || last_ == 'T') reflected_quad = 2.0 * current - last_quad_control_;
    const char upper = static_cast<char>(std::toupper(static_cast<unsigned char>(command)));
    switch (upper) {
      case 'M':
        builder_.moveTo(point(relative));
        break;
      case 'L':
        builder_.lineTo(point(relative));
        break;
      case 'H': {
        const double x = scanner_.number();
        builder_.lineTo(Point2(relative ? current.x() + x : x, current.y()));
        break;
      }
      case 'V': {
        const double y = scanner_.number();
        builder_.lineTo(Point2(current.x(), relative ? current.y() + y : y));
        break;
      }
      case 'C': {
        const Point2 c1 = point(relative);
        const Point2 c2 = point(relative);
        cubic(c1, c2, point(relative));
        break;
      }
      case 'S': {
        const Point2 c2 = point(relative);
        cubic(reflected_cubic, c2, point(relative));
        break;
      }
      case 'Q': {
        const Point2 control = point(relative);
        quadratic(control, point(relative));
        break;
      }
      case 'T':
        quadratic(reflected_quad, point(relative));
        break;
      case 'A':
        arc(relative);
        break;
      case 'Z':
        builder_.close();
        break;
      default:
        fail(std::string("unknown path command '") + command + "'");
    }
    last_ = upper;
  }

  void cubic(const Point2& c1, const Point2& c2, const Point2& end) {
    builder_.cubicTo(c1, c2, end);
    last_cubic_control_ = c2;
  }

  // Degree elevation: a quadratic is exactly a cubic with controls 2/3 of the way to its control.
  void quadratic(const Point2& control, const Point2& end) {
    const Point2 start = builder_.current();
    builder_.cubicTo(start + 2.0 / 3.0 * (control - start), end + 2.0 / 3.0 * (control - end), end);
    last_quad_control_ = control;
  }

  void arc(bool relative) {
    const double rx = scanner_.number();
    const double ry = scanner_.number();
    const double rotation = scanner_.number();
    const bool large_arc = scanner_.flag();
    const bool sweep = scanner_.flag();
    const Point2 end = point(relative);
    const std::vector<Point2> points =
        arcToCubics(builder_.current(), rx, ry, rotation, large_arc, sweep, end);
    for (std::size_t i = 0; i + 2 < points.size(); i += 3) {
      builder_.cubicTo(points[i], points[i + 1], points[i + 2]);
    }
  }

  SvgNumberScanner scanner_;
  ContourBuilder builder_;
  char last_ = 0;
  Point2 last_cubic_control_ = Point2::Zero();
  Point2 last_quad_control_ = Point2::Zero();
};

}  // namespace

std::vector<Contour> parseSvgPathData(const std::string& d, PointBudget& budget) {
  return closedContours(PathDataParser(d, budget).parse());
}

std::vector<Subpath> parseSvgPathSubpaths(const std::string& d, PointBudget& budget) {
  return PathDataParser(d, budget).parse();
}

}  // namespace io_detail
}  // namespace vicc_glyphs
