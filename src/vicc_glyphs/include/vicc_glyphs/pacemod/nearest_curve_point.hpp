#pragma once
// Nearest point on the icon's curves for any point of the image (the distance transform with
// feature labels of thesis 6.2.3.3 / 6.2.4.1): the curves are sampled densely, every sample
// marks the grid pixel it falls in (keeping the exact sample point), and a feature transform of
// that grid gives each pixel its nearest marked pixel. A query returns the exact sample point
// nearest to it among the feature pixels of its pixel and the eight around it: a pixel's own
// feature is nearest to the pixel's centre, up to a grid pixel further from the query than its
// true nearest sample.

#include <memory>
#include <opencv2/core.hpp>
#include <vector>

#include "vicc_glyphs/dci/diffusion_curve.hpp"

namespace vicc_glyphs {
namespace pacemod {

enum class FeatureTransform {
  OpenCvLabels,  ///< cv::distanceTransform, DIST_L2 mask 5, DIST_LABEL_PIXEL (approximate)
  Maurer,        ///< Maurer, Qi and Raghavan 2003: exact Euclidean feature transform
};

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
  /// grid pixels per image pixel, with a margin. Throws std::invalid_argument for a
  /// non-positive size or scale, or when there is no point at all.
  NearestCurvePoint(const std::vector<std::vector<Point2>>& polylines, int width, int height,
                    double grid_scale = 1.0, FeatureTransform method = FeatureTransform::Maurer);
  ~NearestCurvePoint();
  NearestCurvePoint(const NearestCurvePoint&) = delete;
  NearestCurvePoint& operator=(const NearestCurvePoint&) = delete;

  /// Nearest curve sample to `query` (queries outside the grid are clamped onto it).
  Point2 nearest(const Point2& query) const;
  /// Size of one grid pixel in image pixels: the accuracy of nearest().
  double gridPixel() const { return 1.0 / scale_; }

 private:
  double scale_;
  int margin_;
  cv::Size grid_;
  std::unique_ptr<FieldBuffers> buffers_;
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
