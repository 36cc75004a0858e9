#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <opencv2/core.hpp>
#include <optional>
#include <random>

#include "vicc_glyphs/pacemod/nearest_curve_point.hpp"

namespace vicc_glyphs {
namespace pacemod {
namespace {

cv::Mat randomMask(int width, int height, int features, unsigned seed) {
  std::mt19937 random(seed);
  cv::Mat mask = cv::Mat::zeros(height, width, CV_8U);
  for (int i = 0; i < features; ++i) {
    mask.at<unsigned char>(random() % height, random() % width) = 1;
  }
  return mask;
}

double bruteForceDistance(const cv::Mat& mask, int x, int y) {
  double best = 1e300;
  for (int v = 0; v < mask.rows; ++v) {
    for (int u = 0; u < mask.cols; ++u) {
      if (mask.at<unsigned char>(v, u)) best = std::min(best, std::hypot(u - x, v - y));
    }
  }
  return best;
}

double featureDistance(const std::vector<int>& features, const cv::Mat& mask, int x, int y) {
  const int f = features[y * mask.cols + x];
  EXPECT_GE(f, 0);
  EXPECT_TRUE(mask.at<unsigned char>(f / mask.cols, f % mask.cols));
  return std::hypot(f % mask.cols - x, f / mask.cols - y);
}

TEST(FeatureTransformTest, MaurerIsExactAndOpenCvLabelsAreWithinAPixel) {
  for (unsigned seed : {1u, 2u, 3u}) {
    const cv::Mat mask = randomMask(47, 31, 12, seed);
    const std::vector<int> maurer = maurerFeatureTransform(mask);
    const std::vector<int> opencv = openCvFeatureTransform(mask);
    for (int y = 0; y < mask.rows; ++y) {
      for (int x = 0; x < mask.cols; ++x) {
        const double exact = bruteForceDistance(mask, x, y);
        EXPECT_NEAR(featureDistance(maurer, mask, x, y), exact, 1e-9) << x << "," << y;
        EXPECT_LT(featureDistance(opencv, mask, x, y), exact + 1.0) << x << "," << y;
      }
    }
  }
}

TEST(FeatureTransformTest, EmptyMaskHasNoFeatures) {
  const std::vector<int> maurer = maurerFeatureTransform(cv::Mat::zeros(5, 4, CV_8U));
  for (int f : maurer) EXPECT_EQ(f, -1);
}

TEST(FeatureTransformTest, NearestCurvePointReturnsExactSamplesOfTheCurves) {
  const std::vector<std::vector<Point2>> lines{{{10, 10}, {90, 10}}, {{10, 30}, {90, 30}}};
  for (NearestPointMethod method : {NearestPointMethod::ExactSegments, NearestPointMethod::Maurer,
                                    NearestPointMethod::OpenCvLabels}) {
    const NearestCurvePoint field(lines, 100, 40, 2.0, method);
    const Point2 a = field.nearest({50.2, 14.0});
    EXPECT_NEAR(a.y(), 10.0, 1e-12);
    EXPECT_NEAR(a.x(), 50.2, 0.5);
    EXPECT_NEAR(field.nearest({50.0, 27.0}).y(), 30.0, 1e-12);
    EXPECT_NEAR(field.nearest({1e9, -1e9}).y(), 10.0, 1e-12);  // clamped onto the grid
  }
  EXPECT_THROW(NearestCurvePoint({}, 10, 10), std::invalid_argument);
}

// nearestWithin answers exactly when nearest() lies within the radius, for every method; the
// bucketed segments give the exact nearest point of the polylines, the transforms one of their
// samples within a grid pixel of it.
TEST(FeatureTransformTest, NearestWithinARadiusAgreesWithNearest) {
  std::vector<std::vector<Point2>> lines{{}, {}};
  for (int i = 0; i <= 200; ++i) {
    const double angle = 2 * M_PI * i / 200;
    lines[0].push_back({60 + 30 * std::cos(angle), 50 + 20 * std::sin(angle)});
    lines[1].push_back({20 + 0.3 * i, 90 + 5 * std::sin(0.2 * i)});
  }
  std::mt19937 random(5);
  std::uniform_real_distribution<double> x(0, 120), y(0, 110), radius(0.2, 15);
  for (NearestPointMethod method : {NearestPointMethod::ExactSegments, NearestPointMethod::Maurer,
                                    NearestPointMethod::OpenCvLabels}) {
    const NearestCurvePoint field(lines, 120, 110, 1.0, method);
    for (int k = 0; k < 500; ++k) {
      const Point2 q(x(random), y(random));
      const double exact =
          std::min(distanceToPolyline(q, lines[0]), distanceToPolyline(q, lines[1]));
      const Point2 nearest = field.nearest(q);
      const double found = (nearest - q).norm();
      if (method == NearestPointMethod::ExactSegments) {
        EXPECT_NEAR(found, exact, 1e-9) << q.transpose();
      } else {
        EXPECT_LT(found, exact + (method == NearestPointMethod::Maurer ? 1.0 : 4.5))
            << q.transpose();
      }
      const double r = radius(random);
      const std::optional<Point2> within = field.nearestWithin(q, r);
      EXPECT_EQ(within.has_value(), found < r) << q.transpose() << " radius " << r;
      if (within) {
        EXPECT_NEAR((*within - nearest).norm(), 0.0, 1e-12);
      }
    }
  }
  // A curve only outside the frame (and its margin) leaves nothing to modify, for every method.
  for (NearestPointMethod method :
       {NearestPointMethod::ExactSegments, NearestPointMethod::Maurer}) {
    EXPECT_THROW(NearestCurvePoint({{{-30, -30}, {-20, -30}}}, 50, 50, 1.0, method),
                 std::invalid_argument);
    EXPECT_NO_THROW(NearestCurvePoint({{{-30, 10}, {20, 10}}}, 50, 50, 1.0, method));
  }
}

// A pixel's feature is the sample nearest to the pixel's centre: for (50.5, 25.2) in pixel row
// 25 that is the line at y = 29.95 (row 29, 4 rows away; the other line is in row 20), though
// the line at y = 20.95 is 0.5 px nearer to the query itself. The pixels around it know better.
TEST(FeatureTransformTest, NearestCurvePointLooksAtThePixelsAroundTheQuery) {
  const std::vector<std::vector<Point2>> lines{{{10, 20.95}, {90, 20.95}},
                                               {{10, 29.95}, {90, 29.95}}};
  const NearestCurvePoint field(lines, 100, 40, 1.0);
  EXPECT_NEAR(field.nearest({50.5, 25.2}).y(), 20.95, 1e-12);
  EXPECT_NEAR(field.nearest({50.5, 25.7}).y(), 29.95, 1e-12);
  EXPECT_NEAR(field.nearest({50.5, 25.2}).x(), 50.5, 0.5);
}

// Fields reuse their thread's buffers: a field built after a larger one (different grid size,
// curves elsewhere) must not see the earlier field's samples, and a field that is still alive
// keeps its own buffers while another is built.
TEST(FeatureTransformTest, ReusedBuffersCarryNothingOverBetweenFields) {
  const std::vector<std::vector<Point2>> many{
      {{5, 5}, {195, 5}}, {{5, 95}, {195, 95}}, {{100, 20}, {100, 80}}};
  const std::vector<std::vector<Point2>> one{{{10, 30}, {50, 30}}};
  auto expect_only_the_short_line = [](const NearestCurvePoint& field) {
    for (double x = 0.0; x <= 60.0; x += 7.5) {
      for (double y = 0.0; y <= 60.0; y += 7.5) {
        const Point2 p = field.nearest({x, y});
        EXPECT_NEAR(p.y(), 30.0, 1e-12) << x << "," << y;
        EXPECT_NEAR(p.x(), std::clamp(x, 10.0, 50.0), 0.6) << x << "," << y;
      }
    }
  };
  {  // the same grid size: stale marks would land on the very cells queried below
    const std::vector<std::vector<Point2>> elsewhere{{{2, 2}, {58, 2}}, {{2, 58}, {58, 58}}};
    const NearestCurvePoint same_grid(elsewhere, 60, 60);
  }
  expect_only_the_short_line(NearestCurvePoint(one, 60, 60));
  { const NearestCurvePoint large(many, 200, 100, 1.5); }
  const NearestCurvePoint after_large(one, 60, 60);
  expect_only_the_short_line(after_large);
  const NearestCurvePoint while_alive(many, 200, 100, 1.5);
  expect_only_the_short_line(after_large);
  EXPECT_NEAR(while_alive.nearest({100.0, 50.0}).x(), 100.0, 1e-12);
  EXPECT_NEAR(while_alive.nearest({150.0, 3.0}).y(), 5.0, 1e-12);
}

}  // namespace
}  // namespace pacemod
}  // namespace vicc_glyphs
