#include <gtest/gtest.h>

#include <cstdio>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "curve_geometry.hpp"
#include "vicc_glyphs/io/raster_import.hpp"

namespace vicc_glyphs {
namespace {

const Point2 kCentre(49.5, 39.5);  // pixel (49, 39) covers [49, 50) x [39, 40)
constexpr double kRadius = 25.0;

std::string writeCircle(const std::string& name, int line_type) {
  cv::Mat3b image(80, 100, cv::Vec3b(255, 255, 255));
  cv::circle(image, cv::Point(49, 39), static_cast<int>(kRadius), cv::Scalar(0, 0, 255), cv::FILLED,
             line_type);
  const std::string path = ::testing::TempDir() + "/" + name;
  EXPECT_TRUE(cv::imwrite(path, image));
  return path;
}

void expectRedDiscOnWhite(const DiffusionCurveImage& image) {
  EXPECT_EQ(image.width, 100);
  EXPECT_EQ(image.height, 80);
  ASSERT_GE(image.curves.size(), 1u);
  for (const DiffusionCurve& c : image.curves) {
    EXPECT_EQ(c.control_points.front(), c.control_points.back());
    for (const Point2& p : test::flattenCurve(c, 8)) {
      EXPECT_NEAR((p - kCentre).norm(), kRadius, 1.5);
    }
    for (double s = 0.5; s < c.segmentCount(); s += 1.0) {
      const bool left_inside = (test::besideCurve(c, s, 1.0) - kCentre).norm() < kRadius;
      const Color inside = left_inside ? c.leftColorAt(s) : c.rightColorAt(s);
      const Color outside = left_inside ? c.rightColorAt(s) : c.leftColorAt(s);
      EXPECT_LT((inside - Color(1, 0, 0)).norm(), 0.1) << "s " << s;
      EXPECT_LT((outside - Color(1, 1, 1)).norm(), 0.1) << "s " << s;
    }
  }
}

TEST(RasterImport, RedDiscOnWhiteGivesItsBoundary) {
  const std::string path = writeCircle("vicc_red_disc.png", cv::LINE_8);
  const DiffusionCurveImage image = importRaster(path);
  EXPECT_EQ(image.curves.size(), 1u);
  expectRedDiscOnWhite(image);
  std::remove(path.c_str());
}

TEST(RasterImport, AntiAliasedEdgesDoNotAddRegions) {
  const std::string path = writeCircle("vicc_red_disc_aa.png", cv::LINE_AA);
  const DiffusionCurveImage image = importRaster(path);
  EXPECT_EQ(image.curves.size(), 1u);
  expectRedDiscOnWhite(image);
  std::remove(path.c_str());
}

TEST(RasterImport, TransparentPixelsUseTheAlphaBackground) {
  cv::Mat4b image(40, 40, cv::Vec4b(0, 0, 0, 0));
  cv::rectangle(image, cv::Rect(10, 10, 20, 20), cv::Scalar(255, 0, 0, 255), cv::FILLED);
  const std::string path = ::testing::TempDir() + "/vicc_blue_square.png";
  ASSERT_TRUE(cv::imwrite(path, image));
  RasterImportOptions options;
  options.alpha_background = Color(0, 1, 0);
  const DiffusionCurveImage result = importRaster(path, options);
  ASSERT_EQ(result.curves.size(), 1u);
  const DiffusionCurve& c = result.curves[0];
  const double s = 0.5;
  const bool left_inside =
      (test::besideCurve(c, s, 1.0) - Point2(20, 20)).cwiseAbs().maxCoeff() < 10;
  EXPECT_LT(((left_inside ? c.leftColorAt(s) : c.rightColorAt(s)) - Color(0, 0, 1)).norm(), 0.05);
  EXPECT_LT(((left_inside ? c.rightColorAt(s) : c.leftColorAt(s)) - Color(0, 1, 0)).norm(), 0.05);
  std::remove(path.c_str());
}

}  // namespace
}  // namespace vicc_glyphs
