#include "svg_geometry.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace vicc_glyphs {
namespace io_detail {

void PointBudget::spend(std::size_t points) {
  used_ += points;
  if (used_ > limit_) {
    throw std::length_error("more than " + std::to_string(limit_) +
                            " control points (limit per file)");
  }
}

std::vector<Contour> closedContours(std::vector<Subpath> subpaths) {
  std::vector<Contour> contours;
  for (Subpath& subpath : subpaths) {
    Contour& c = subpath.points;
    if (c.back() != c.front()) {
      const Point2 from = c.back();
      const Point2 to = c.front();
      c.insert(c.end(), {from + (to - from) / 3.0, from + 2.0 * (to - from) / 3.0, to});
    }
    contours.push_back(std::move(c));
  }
  return contours;
}

void ContourBuilder::moveTo(const Point2& p) {
  endSubpath(false);
  start_ = current_ = p;
}

void ContourBuilder::lineTo(const Point2& p) {
  const Point2 from = current_;
  cubicTo(from + (p - from) / 3.0, from + 2.0 * (p - from) / 3.0, p);
}

void ContourBuilder::cubicTo(const Point2& c1, const Point2& c2, const Point2& p) {
  if (open_.empty()) {
    budget_.spend(1);
    open_.push_back(current_);
  }
  budget_.spend(3);
  open_.insert(open_.end(), {c1, c2, p});
  current_ = p;
}

void ContourBuilder::close() {
  if (open_.empty()) return;
  if (open_.back() != start_) lineTo(start_);
  endSubpath(true);
}

void ContourBuilder::endSubpath(bool closed) {
  if (open_.empty()) return;
  // A subpath that never leaves its start point has no inside and no normal: drop it.
  const bool degenerate = std::all_of(open_.begin(), open_.end(), [&](const Point2& q) {
    return (q - open_.front()).norm() < 1e-12;
  });
  if (!degenerate) subpaths_.push_back({std::move(open_), closed});
  open_.clear();
  current_ = start_;
}

std::vector<Subpath> ContourBuilder::finishSubpaths() {
  endSubpath(false);
  return std::move(subpaths_);
}

std::vector<Contour> ContourBuilder::finish() { return closedContours(finishSubpaths()); }

}  // namespace io_detail
}  // namespace vicc_glyphs
