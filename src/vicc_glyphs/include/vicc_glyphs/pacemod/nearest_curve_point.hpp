#pragma once
// Nearest point on the icon's curves for any point of the image (what the distance transform
// with feature labels of thesis 6.2.3.3 / 6.2.4.1 gives). Three methods, chosen by measurement
// (vicc_glyphs_feature_transform_bench, docs/pacemod.md):
// - ExactSegments (the default): the curves' polylines, their segments bucketed in cells; a
//   query searches the cells around it outward, only as far as it has to. Exact, and it costs
//   nothing for the parts of the image that no query comes near.
// - Maurer / OpenCvLabels: the curves are sampled densely, every sample marks the grid pixel it
//   falls in (keeping the exact sample point), and a feature transform of the whole grid gives
//   each pixel its nearest marked pixel. A query returns the exact sample point nearest to it
//   among the feature pixels of its pixel and the eight around it: a pixel's own feature is
//   nearest to the pixel's centre, up to a grid pixel further from the query than its true
//   nearest sample.

#include <memory>
#include <opencv2/core.hpp>
#include <optional>
#include <vector>

#include "vicc_glyphs/dci/diffusion_curve.hpp"
#include "vicc_glyphs/pacemod/polyline.hpp"

namespace vicc_glyphs {
namespace pacemod {

enum class NearestPointMethod {
  ExactSegments,  ///< the polylines' segments in kSegmentCellPx cells, searched around a query
  Maurer,         ///< Maurer, Qi and Raghavan 2003: exact Euclidean feature transform
  OpenCvLabels,   ///< cv::distanceTransform, DIST_L2 mask 5, DIST_LABEL_PIXEL (approximate)
};

/// ExactSegments' cell size (image pixels), chosen by measurement (docs/pacemod.md).
constexpr double kSegmentCellPx = 8.0;

/// The per-pixel buffers of one field (about 9 MB for a 512 px glyph). A field takes them from
/// its thread's spare set and hands them back when it is destroyed: fresh buffers cost ~2,200
/// page faults (~30 ms on the development VM) per glyph, more than the whole modification.
struct FieldBuffers {
  std::vector<Point2> samples;          ///< exact point per feature pixel (index = pixel index)
  std::vector<int> feature;             ///< per grid pixel: index of the nearest feature pixel
  std::vector<double> centre_distance;  ///< marking: distance of the kept sample to the centre
  std::vector<int> row_feature;         ///< Maurer's first pass
  cv::Mat mask;                         ///< marked grid pixels
};

class NearestCurvePoint {
 public:
  /// `polylines` in image pixels; the grid covers [0, width) x [0, height) at `grid_scale`
  /// grid pixels per image pixel, with a margin (ExactSegments: the frame a curve must come
  /// near, and gridPixel()). Throws std::invalid_argument for a non-positive size or scale, or
  /// when no curve comes near that frame.
  NearestCurvePoint(const std::vector<std::vector<Point2>>& polylines, int width, int height,
                    double grid_scale = 1.0,
                    NearestPointMethod method = NearestPointMethod::ExactSegments);
  ~NearestCurvePoint();
  NearestCurvePoint(const NearestCurvePoint&) = delete;
  NearestCurvePoint& operator=(const NearestCurvePoint&) = delete;

  /// Nearest curve point to `query`: on a segment of the polylines (ExactSegments), or the
  /// nearest sample around the query's grid pixel (the transforms; queries outside the grid
  /// are clamped onto it).
  Point2 nearest(const Point2& query) const;
  /// nearest(query) if it is nearer than `radius`. ExactSegments searches only that far: a
  /// query that nothing comes near costs a few cells.
  std::optional<Point2> nearestWithin(const Point2& query, double radius) const;
  /// Size of one grid pixel in image pixels: the accuracy of the transforms' nearest(), and the
  /// slack the skeleton guard allows at most (with ExactSegments as well).
  double gridPixel() const { return 1.0 / scale_; }

 private:
  void transformGrid(const std::vector<std::vector<Point2>>& polylines, int width, int height,
                     NearestPointMethod method);
  void bucketSegments(const std::vector<std::vector<Point2>>& polylines, int width, int height);

  double scale_;
  int margin_;
  cv::Size grid_;
  std::unique_ptr<FieldBuffers> buffers_;  ///< the transforms' grid
  std::vector<Polyline> lines_;            ///< ExactSegments: the polylines and their buckets
  std::unique_ptr<PolylineSetDistance> segments_;
};

/// The exact Euclidean feature transform of Maurer et al. 2003: for a CV_8U `mask` (non-zero =
/// feature) returns, per pixel (row-major), the row-major index of a nearest feature pixel,
/// or -1 everywhere when there is none.
std::vector<int> maurerFeatureTransform(const cv::Mat& mask);
/// The same into `result`, with `row_feature` as scratch (both keep their storage when they
/// have the room: no allocation for a repeated grid size).
void maurerFeatureTransform(const cv::Mat& mask, std::vector<int>& result,
                            std::vector<int>& row_feature);

/// The same from cv::distanceTransform's pixel labels (approximate 5x5 mask distances).
std::vector<int> openCvFeatureTransform(const cv::Mat& mask);

}  // namespace pacemod
}  // namespace vicc_glyphs
