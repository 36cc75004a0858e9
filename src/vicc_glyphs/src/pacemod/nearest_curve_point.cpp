#include "vicc_glyphs/pacemod/nearest_curve_point.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

#include "vicc_glyphs/render/pixel_buffer.hpp"

namespace vicc_glyphs {
namespace pacemod {

namespace {

// One spare set of buffers per thread: consecutive glyphs (a bench, a server, a design with
// several modified parts) reuse pages that are already mapped instead of faulting in new ones.
std::unique_ptr<FieldBuffers>& spareBuffers() {
  thread_local std::unique_ptr<FieldBuffers> spare;
  return spare;
}

std::unique_ptr<FieldBuffers> takeBuffers() {
  std::unique_ptr<FieldBuffers> buffers = std::move(spareBuffers());
  return buffers ? std::move(buffers) : std::make_unique<FieldBuffers>();
}

// Sizes a reused vector; the first time, with huge-page advice (one fault per 2 MiB).
template <class T>
void assignReused(std::vector<T>& vector, std::size_t n, const T& value) {
  render_detail::reserveWithHugePages(vector, n);
  vector.assign(n, value);
}

// Whether the segment a b has a point in the box [lo, hi] (Liang-Barsky clipping).
bool segmentMeetsBox(const Point2& a, const Point2& b, const Point2& lo, const Point2& hi) {
  if (!a.allFinite() || !b.allFinite()) return false;
  double enter = 0.0, leave = 1.0;
  const Point2 d = b - a;
  for (int axis = 0; axis < 2; ++axis) {
    if (d[axis] == 0.0) {
      if (a[axis] < lo[axis] || a[axis] > hi[axis]) return false;
      continue;
    }
    double t0 = (lo[axis] - a[axis]) / d[axis], t1 = (hi[axis] - a[axis]) / d[axis];
    if (t0 > t1) std::swap(t0, t1);
    enter = std::max(enter, t0);
    leave = std::min(leave, t1);
  }
  return enter <= leave;
}

std::invalid_argument nothingNearTheFrame(int width, int height) {
  return std::invalid_argument("no curve of the image comes near its " + std::to_string(width) +
                               " x " + std::to_string(height) +
                               " px frame: there is nothing to modify");
}

}  // namespace

NearestCurvePoint::NearestCurvePoint(const std::vector<std::vector<Point2>>& polylines, int width,
                                     int height, double grid_scale, NearestPointMethod method)
    : scale_(grid_scale), margin_(4) {
  if (width < 1 || height < 1 || !(grid_scale > 0.0) || !std::isfinite(grid_scale)) {
    throw std::invalid_argument("NearestCurvePoint: size and grid scale must be positive");
  }
  grid_ = cv::Size(static_cast<int>(std::ceil(width * scale_)) + 2 * margin_,
                   static_cast<int>(std::ceil(height * scale_)) + 2 * margin_);
  if (method == NearestPointMethod::ExactSegments) {
    bucketSegments(polylines, width, height);
  } else {
    transformGrid(polylines, width, height, method);
  }
}

void NearestCurvePoint::bucketSegments(const std::vector<std::vector<Point2>>& polylines, int width,
                                       int height) {
  // The frame the transforms' grid covers: a curve must come near it, as there.
  const Point2 lo = Point2::Constant(-margin_ / scale_);
  const Point2 hi(grid_.width / scale_ + lo.x(), grid_.height / scale_ + lo.y());
  bool near_the_frame = false;
  for (const Polyline& line : polylines) {
    if (line.empty()) continue;
    // A single point is a segment of no length, so that it counts as in the transforms.
    lines_.push_back(line.size() == 1 ? Polyline{line.front(), line.front()} : line);
    const Polyline& kept = lines_.back();
    for (std::size_t i = 0; i + 1 < kept.size() && !near_the_frame; ++i) {
      near_the_frame = segmentMeetsBox(kept[i], kept[i + 1], lo, hi);
    }
  }
  if (!near_the_frame) throw nothingNearTheFrame(width, height);
  std::vector<const Polyline*> pointers;
  for (const Polyline& line : lines_) pointers.push_back(&line);
  segments_ = std::make_unique<PolylineSetDistance>(std::move(pointers), kSegmentCellPx);
}

void NearestCurvePoint::transformGrid(const std::vector<std::vector<Point2>>& polylines, int width,
                                      int height, NearestPointMethod method) {
  buffers_ = takeBuffers();
  FieldBuffers& b = *buffers_;
  b.mask.create(grid_, CV_8U);
  b.mask.setTo(0);
  const std::size_t cells = b.mask.total();
  assignReused(b.samples, cells, Point2(Point2::Zero()));
  assignReused(b.centre_distance, cells, 1e300);
  // Samples at a quarter grid pixel mark every pixel a segment passes through; each pixel keeps
  // the sample nearest to its centre.
  const double step = 0.25 / scale_;
  auto mark = [&](const Point2& p) {
    const double gx = p.x() * scale_ + margin_, gy = p.y() * scale_ + margin_;
    const int ix = static_cast<int>(std::floor(gx)), iy = static_cast<int>(std::floor(gy));
    if (ix < 0 || iy < 0 || ix >= grid_.width || iy >= grid_.height) return;
    const int index = iy * grid_.width + ix;
    const double d = std::hypot(gx - ix - 0.5, gy - iy - 0.5);
    if (d < b.centre_distance[index]) {
      b.centre_distance[index] = d;
      b.samples[index] = p;
      b.mask.at<unsigned char>(iy, ix) = 1;
    }
  };
  for (const std::vector<Point2>& line : polylines) {
    for (std::size_t i = 0; i + 1 < line.size(); ++i) {
      const int pieces =
          std::max(1, static_cast<int>(std::ceil((line[i + 1] - line[i]).norm() / step)));
      for (int k = 0; k < pieces; ++k)
        mark(line[i] + (line[i + 1] - line[i]) * (double(k) / pieces));
    }
    if (!line.empty()) mark(line.back());
  }
  if (cv::countNonZero(b.mask) == 0) throw nothingNearTheFrame(width, height);
  if (method == NearestPointMethod::Maurer) {
    render_detail::reserveWithHugePages(b.feature, cells);
    render_detail::reserveWithHugePages(b.row_feature, cells);
    maurerFeatureTransform(b.mask, b.feature, b.row_feature);
  } else {
    b.feature = openCvFeatureTransform(b.mask);
  }
}

NearestCurvePoint::~NearestCurvePoint() {
  if (buffers_ && !spareBuffers()) spareBuffers() = std::move(buffers_);
}

Point2 NearestCurvePoint::nearest(const Point2& query) const {
  if (segments_) {
    const PolylineSetDistance::Segment segment = segments_->nearestSegment(query);
    return segment.line < 0 ? Point2::Zero() : segments_->nearestOn(segment, query);
  }
  // Clamp in floating point first: a far-away or non-finite query must not overflow an int.
  auto cell = [](double g, int size) {
    return static_cast<int>(std::isfinite(g) ? std::clamp(g, 0.0, size - 1.0) : 0.0);
  };
  const int ix = cell(query.x() * scale_ + margin_, grid_.width);
  const int iy = cell(query.y() * scale_ + margin_, grid_.height);
  // A pixel's feature is the sample nearest to the pixel's centre, which can be up to a grid
  // pixel further from the query than its true nearest sample (0.76 px inside the leaf's
  // slit: the guard then missed the other side). The features of the pixels around it hold
  // that sample: the exact nearest of those nine.
  const FieldBuffers& b = *buffers_;
  Point2 best = Point2::Zero();
  double best_distance = std::numeric_limits<double>::infinity();
  for (int y = std::max(iy - 1, 0); y <= std::min(iy + 1, grid_.height - 1); ++y) {
    for (int x = std::max(ix - 1, 0); x <= std::min(ix + 1, grid_.width - 1); ++x) {
      const Point2& sample = b.samples[b.feature[static_cast<std::size_t>(y) * grid_.width + x]];
      const double distance = (sample - query).squaredNorm();
      if (distance < best_distance) {
        best = sample;
        best_distance = distance;
      }
    }
  }
  return best;
}

std::optional<Point2> NearestCurvePoint::nearestWithin(const Point2& query, double radius) const {
  if (segments_) {
    const PolylineSetDistance::Segment segment = segments_->nearestSegment(query, radius);
    if (segment.line < 0) return std::nullopt;
    return segments_->nearestOn(segment, query);
  }
  const Point2 found = nearest(query);
  if (!((found - query).norm() < radius)) return std::nullopt;
  return found;
}

}  // namespace pacemod
}  // namespace vicc_glyphs
