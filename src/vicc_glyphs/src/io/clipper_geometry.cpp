#include "clipper_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace vicc_glyphs {
namespace io_detail {
namespace {

constexpr double kUnitsPerImage = 4194304.0;  // 2^22
constexpr double kMaxUnits = 1073741823.0;    // Clipper's loRange: 32-bit products suffice
constexpr int kMaxPiecesPerBezier = 4096;

Point2 bezier(const Point2* b, double t) {
  const double u = 1.0 - t;
  return u * u * u * b[0] + 3.0 * u * u * t * b[1] + 3.0 * u * t * t * b[2] + t * t * t * b[3];
}

// |B''| <= 6 max(|b0 - 2 b1 + b2|, |b1 - 2 b2 + b3|); n even pieces deviate at most
// |B''| / (8 n^2) from the curve.
int piecesFor(const Point2* b, double tolerance) {
  const double second =
      6.0 * std::max((b[0] - 2.0 * b[1] + b[2]).norm(), (b[1] - 2.0 * b[2] + b[3]).norm());
  const double wanted = std::ceil(std::sqrt(second / (8.0 * tolerance)));
  if (!(wanted >= 1.0)) return 1;
  return wanted > kMaxPiecesPerBezier ? kMaxPiecesPerBezier : static_cast<int>(wanted);
}

Paths clipperOp(ClipperLib::ClipType type, const Paths& subject, const Paths& clip,
                ClipperLib::PolyFillType rule = ClipperLib::pftNonZero) {
  ClipperLib::Clipper clipper;
  clipper.AddPaths(subject, ClipperLib::ptSubject, true);
  clipper.AddPaths(clip, ClipperLib::ptClip, true);
  Paths result;
  clipper.Execute(type, result, rule, rule);
  return result;
}

}  // namespace

IntegerFrame::IntegerFrame(int width, int height)
    : units_per_pixel_(kUnitsPerImage / std::max(std::max(width, height), 1)),
      width_(width),
      height_(height) {}

IntPoint IntegerFrame::toInt(const Point2& pixel) const {
  auto convert = [&](double v) {
    const double units = std::clamp(v * units_per_pixel_, -kMaxUnits, kMaxUnits);
    return static_cast<ClipperLib::cInt>(std::llround(std::isfinite(units) ? units : 0.0));
  };
  return IntPoint(convert(pixel.x()), convert(pixel.y()));
}

Point2 IntegerFrame::toPixel(const IntPoint& point) const {
  return Point2(static_cast<double>(point.X), static_cast<double>(point.Y)) / units_per_pixel_;
}

Eigen::AlignedBox2d IntegerFrame::safeBox() const {
  const double limit = 0.99 * kMaxUnits / units_per_pixel_;
  return Eigen::AlignedBox2d(Point2(-limit, -limit), Point2(limit, limit));
}

void VertexBudget::spend(std::size_t vertices) {
  used_ += vertices;
  if (used_ > limit_) {
    throw std::length_error("more than " + std::to_string(limit_) +
                            " polygon vertices after flattening the curves (limit per file)");
  }
}

void checkShapeVertices(std::size_t vertices) {
  if (vertices > kMaxVerticesPerShape) {
    throw std::length_error("shape with " + std::to_string(vertices) +
                            " polygon vertices after flattening: more than " +
                            std::to_string(kMaxVerticesPerShape) + " per shape (limit)");
  }
}

void flattenChain(const Contour& chain, double tolerance, VertexBudget& budget,
                  std::vector<Point2>& out) {
  if (chain.empty()) return;
  if (out.empty() || out.back() != chain.front()) {
    budget.spend(1);
    out.push_back(chain.front());
  }
  for (std::size_t k = 0; k + 3 < chain.size(); k += 3) {
    const Point2* b = &chain[k];
    const int pieces = piecesFor(b, tolerance);
    budget.spend(pieces);
    for (int i = 1; i <= pieces; ++i) out.push_back(bezier(b, static_cast<double>(i) / pieces));
  }
}

std::vector<Point2> clipPolygonToBox(const std::vector<Point2>& polygon,
                                     const Eigen::AlignedBox2d& box) {
  if (std::all_of(polygon.begin(), polygon.end(),
                  [&](const Point2& p) { return box.contains(p); })) {
    return polygon;
  }
  std::vector<Point2> current = polygon;
  for (int axis = 0; axis < 2; ++axis) {
    for (int upper = 0; upper < 2; ++upper) {
      const double limit = upper ? box.max()[axis] : box.min()[axis];
      auto inside = [&](const Point2& p) { return upper ? p[axis] <= limit : p[axis] >= limit; };
      std::vector<Point2> next;
      for (std::size_t i = 0; i < current.size(); ++i) {
        const Point2& a = current[i];
        const Point2& b = current[(i + 1) % current.size()];
        if (inside(a)) next.push_back(a);
        if (inside(a) != inside(b)) {
          const double t = (limit - a[axis]) / (b[axis] - a[axis]);
          Point2 cut = a + t * (b - a);
          cut[axis] = limit;
          next.push_back(cut);
        }
      }
      current = std::move(next);
      if (current.empty()) return current;
    }
  }
  return current;
}

Paths fillArea(const std::vector<Subpath>& subpaths, FillRule rule, const IntegerFrame& frame,
               double tolerance, VertexBudget& budget) {
  Paths paths;
  std::size_t vertices = 0;
  for (const Subpath& subpath : subpaths) {
    std::vector<Point2> polyline;
    flattenChain(subpath.points, tolerance, budget, polyline);
    checkShapeVertices(vertices += polyline.size());
    // Non-finite points (overflowing transforms) cannot be placed; the clip drops them.
    polyline.erase(std::remove_if(polyline.begin(), polyline.end(),
                                  [](const Point2& p) { return !p.allFinite(); }),
                   polyline.end());
    if (polyline.size() < 3) continue;
    Path path;
    for (const Point2& p : clipPolygonToBox(polyline, frame.safeBox())) {
      path.push_back(frame.toInt(p));
    }
    if (path.size() >= 3) paths.push_back(std::move(path));
  }
  return simplified(paths, rule);
}

Paths simplified(const Paths& paths, FillRule rule) {
  Paths result;
  ClipperLib::SimplifyPolygons(
      paths, result, rule == FillRule::kEvenOdd ? ClipperLib::pftEvenOdd : ClipperLib::pftNonZero);
  return result;
}

namespace {

// Whether the boundary runs out to `b` and back (coming from a, going on to c): it turns back by
// more than 90 degrees and either returns to within `width` of a or b lies within `width` of
// the line through a and c; or an edge has no length. Symmetric in a and c, so both directions
// of a boundary that two regions share agree.
bool isSpike(const IntPoint& a, const IntPoint& b, const IntPoint& c, double width) {
  const double ux = static_cast<double>(b.X - a.X), uy = static_cast<double>(b.Y - a.Y);
  const double vx = static_cast<double>(c.X - b.X), vy = static_cast<double>(c.Y - b.Y);
  if ((ux == 0.0 && uy == 0.0) || (vx == 0.0 && vy == 0.0)) return true;
  if (ux * vx + uy * vy >= 0.0) return false;
  const double wx = ux + vx, wy = uy + vy;  // c - a
  const double base = std::hypot(wx, wy);
  // Back to within `width` of where it left, or back along the line it came.
  return base <= width || std::abs(wx * uy - wy * ux) <= width * base;
}

Path withoutSpikes(Path path, double width) {
  bool removed = true;
  while (removed && path.size() >= 3) {
    removed = false;
    for (std::size_t i = 0; i < path.size() && path.size() >= 3; ++i) {
      const std::size_t n = path.size();
      if (isSpike(path[(i + n - 1) % n], path[i], path[(i + 1) % n], width)) {
        path.erase(path.begin() + static_cast<long>(i));
        removed = true;
      }
    }
  }
  return path;
}

}  // namespace

Paths withoutSpikes(const Paths& paths, double width) {
  Paths result;
  for (const Path& path : paths) {
    Path clean = withoutSpikes(path, width);
    if (clean.size() >= 3) result.push_back(std::move(clean));
  }
  return result;
}

Paths offsetInSteps(const Paths& area, std::initializer_list<double> steps, double miter_limit) {
  Paths current = area;
  for (const double step : steps) {
    ClipperLib::ClipperOffset offset(miter_limit);
    offset.AddPaths(current, ClipperLib::jtMiter, ClipperLib::etClosedPolygon);
    Paths next;
    offset.Execute(next, step);
    current = std::move(next);
  }
  return current;
}

Paths withoutSubpixelDetail(const Paths& area, const IntegerFrame& frame, double radius) {
  constexpr double kMiterLimit = 64.0;  // keeps all but needle-sharp corners exact
  const double delta = radius * frame.unitsPerPixel();
  return offsetInSteps(area, {delta, -2.0 * delta, delta}, kMiterLimit);
}

Paths unite(const Paths& a, const Paths& b) { return clipperOp(ClipperLib::ctUnion, a, b); }
Paths intersect(const Paths& a, const Paths& b) {
  return clipperOp(ClipperLib::ctIntersection, a, b);
}
Paths subtract(const Paths& a, const Paths& b) { return clipperOp(ClipperLib::ctDifference, a, b); }

IntRect boundsOf(const Paths& paths) {
  ClipperLib::Clipper clipper;
  clipper.AddPaths(paths, ClipperLib::ptSubject, true);
  return clipper.GetBounds();
}

bool boxesOverlap(const IntRect& a, const IntRect& b) {
  return a.left <= b.right && b.left <= a.right && a.top <= b.bottom && b.top <= a.bottom;
}

Path rectangle(const IntegerFrame& frame, double x0, double y0, double x1, double y1) {
  return {frame.toInt(Point2(x0, y0)), frame.toInt(Point2(x1, y0)), frame.toInt(Point2(x1, y1)),
          frame.toInt(Point2(x0, y1))};
}

}  // namespace io_detail
}  // namespace vicc_glyphs
