#include "svg_stroke.hpp"

#include <cmath>
#include <numeric>
#include <stdexcept>

namespace vicc_glyphs {
namespace io_detail {
namespace {

ClipperLib::JoinType joinType(LineJoin join) {
  switch (join) {
    case LineJoin::kRound:
      return ClipperLib::jtRound;
    case LineJoin::kBevel:
      return ClipperLib::jtSquare;
    case LineJoin::kMiter:
      break;
  }
  return ClipperLib::jtMiter;
}

ClipperLib::EndType endType(LineCap cap) {
  switch (cap) {
    case LineCap::kRound:
      return ClipperLib::etOpenRound;
    case LineCap::kSquare:
      return ClipperLib::etOpenSquare;
    case LineCap::kButt:
      break;
  }
  return ClipperLib::etOpenButt;
}

// Integer points of a user-space polyline; throws when Clipper cannot hold them.
Path toUserIntegers(const std::vector<Point2>& polyline, double units_per_user) {
  constexpr double kMaxUnits = 4.0e18;  // Clipper's hiRange
  Path path;
  for (const Point2& p : polyline) {
    const Point2 units = p * units_per_user;
    if (!units.allFinite() || units.cwiseAbs().maxCoeff() > kMaxUnits) {
      throw std::invalid_argument("stroke coordinates out of range");
    }
    path.emplace_back(std::llround(units.x()), std::llround(units.y()));
  }
  return path;
}

}  // namespace

std::vector<std::vector<Point2>> dashPolyline(const std::vector<Point2>& polyline,
                                              const std::vector<double>& dashes, double offset) {
  const double period = std::accumulate(dashes.begin(), dashes.end(), 0.0);
  if (dashes.empty() || !(period > 0.0)) return {polyline};
  // Position in the pattern: which dash or gap, and how much of it is left.
  double phase = std::fmod(offset, period);
  if (phase < 0.0) phase += period;
  std::size_t index = 0;
  while (phase >= dashes[index]) {
    phase -= dashes[index];
    index = (index + 1) % dashes.size();
  }
  double left = dashes[index] - phase;
  std::vector<std::vector<Point2>> pieces;
  std::vector<Point2> current;
  if (index % 2 == 0) current.push_back(polyline.front());
  for (std::size_t i = 0; i + 1 < polyline.size(); ++i) {
    Point2 a = polyline[i];
    const Point2 b = polyline[i + 1];
    double length = (b - a).norm();
    while (length > left) {
      a += (b - a) * (left / length);
      length -= left;
      if (index % 2 == 0) {
        current.push_back(a);
        pieces.push_back(std::move(current));
        current.clear();
      } else {
        current = {a};
      }
      index = (index + 1) % dashes.size();
      left = dashes[index];
    }
    left -= length;
    if (index % 2 == 0) current.push_back(b);
  }
  if (current.size() >= 2) pieces.push_back(std::move(current));
  return pieces;
}

Paths strokeArea(const std::vector<Subpath>& subpaths, const Affine2& user_to_pixels,
                 const StrokeGeometry& stroke, const IntegerFrame& frame, double tolerance,
                 VertexBudget& budget) {
  if (!(stroke.width > 0.0)) return {};
  const double pixels_per_user = std::sqrt(std::abs(user_to_pixels.linear().determinant()));
  if (!(pixels_per_user > 0.0) || !std::isfinite(pixels_per_user)) return {};
  const double units_per_user = frame.unitsPerPixel() * pixels_per_user;
  ClipperLib::ClipperOffset offset(std::max(stroke.miter_limit, 1.0),
                                   0.25 * tolerance * frame.unitsPerPixel());
  std::size_t vertices = 0;
  for (const Subpath& subpath : subpaths) {
    std::vector<Point2> polyline;
    flattenChain(subpath.points, tolerance / pixels_per_user, budget, polyline);
    checkShapeVertices(vertices += polyline.size());
    if (stroke.dashes.empty()) {
      offset.AddPath(toUserIntegers(polyline, units_per_user), joinType(stroke.join),
                     subpath.closed ? ClipperLib::etClosedLine : endType(stroke.cap));
      continue;
    }
    for (const auto& dash : dashPolyline(polyline, stroke.dashes, stroke.dash_offset)) {
      budget.spend(dash.size());
      offset.AddPath(toUserIntegers(dash, units_per_user), joinType(stroke.join),
                     endType(stroke.cap));
    }
  }
  Paths user_area;
  offset.Execute(user_area, 0.5 * stroke.width * units_per_user);
  Paths pixel_area;
  for (const Path& path : user_area) {
    Path mapped;
    for (const IntPoint& q : path) {
      const Point2 user(static_cast<double>(q.X) / units_per_user,
                        static_cast<double>(q.Y) / units_per_user);
      mapped.push_back(frame.toInt(user_to_pixels * user));
    }
    pixel_area.push_back(std::move(mapped));
  }
  // A mirroring transform reverses the orientation; normalising restores it.
  return simplified(pixel_area, FillRule::kNonZero);
}

}  // namespace io_detail
}  // namespace vicc_glyphs
