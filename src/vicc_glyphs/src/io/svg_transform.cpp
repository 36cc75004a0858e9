#include "svg_transform.hpp"

#include <cctype>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "svg_number_scanner.hpp"

namespace vicc_glyphs {
namespace io_detail {
namespace {

constexpr double kDegree = M_PI / 180.0;

std::vector<double> arguments(SvgNumberScanner& scanner) {
  if (scanner.peek() != '(') throw std::invalid_argument("expected '(' in transform");
  scanner.advance();
  std::vector<double> values;
  while (scanner.numberAhead() && values.size() < 6) values.push_back(scanner.number());
  if (scanner.peek() != ')') throw std::invalid_argument("expected ')' in transform");
  scanner.advance();
  return values;
}

void requireCount(const std::string& name, std::size_t count, std::size_t low, std::size_t high) {
  if (count < low || count > high) {
    throw std::invalid_argument(name + "() with " + std::to_string(count) + " arguments");
  }
}

Affine2 single(const std::string& name, const std::vector<double>& a) {
  Affine2 t = Affine2::Identity();
  if (name == "matrix") {
    requireCount(name, a.size(), 6, 6);
    t.matrix() << a[0], a[2], a[4], a[1], a[3], a[5], 0, 0, 1;
  } else if (name == "translate") {
    requireCount(name, a.size(), 1, 2);
    t.translate(Eigen::Vector2d(a[0], a.size() > 1 ? a[1] : 0.0));
  } else if (name == "scale") {
    requireCount(name, a.size(), 1, 2);
    t.scale(Eigen::Vector2d(a[0], a.size() > 1 ? a[1] : a[0]));
  } else if (name == "rotate") {
    if (a.size() != 1 && a.size() != 3) requireCount(name, a.size(), 1, 1);
    const Eigen::Vector2d centre =
        a.size() == 3 ? Eigen::Vector2d(a[1], a[2]) : Eigen::Vector2d(0, 0);
    t.translate(centre).rotate(a[0] * kDegree).translate(-centre);
  } else if (name == "skewX") {
    requireCount(name, a.size(), 1, 1);
    t.matrix()(0, 1) = std::tan(a[0] * kDegree);
  } else if (name == "skewY") {
    requireCount(name, a.size(), 1, 1);
    t.matrix()(1, 0) = std::tan(a[0] * kDegree);
  } else {
    throw std::invalid_argument("unknown transform '" + name + "'");
  }
  return t;
}

}  // namespace

Affine2 parseSvgTransform(const std::string& text) {
  SvgNumberScanner scanner(text);
  Affine2 total = Affine2::Identity();
  while (!scanner.atEnd()) {
    std::string name;
    while (std::isalpha(static_cast<unsigned char>(scanner.peek()))) {
      name += scanner.peek();
      scanner.advance();
    }
    if (name.empty()) throw std::invalid_argument("expected a transform name");
    total = total * single(name, arguments(scanner));
    scanner.skipSeparators();
  }
  const double determinant = total.linear().determinant();
  if (!std::isfinite(determinant) || std::abs(determinant) < 1e-12 || !total.matrix().allFinite()) {
    throw std::invalid_argument("transform is degenerate or not finite");
  }
  return total;
}

}  // namespace io_detail
}  // namespace vicc_glyphs
