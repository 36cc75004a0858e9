#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "vicc_glyphs/io/load.hpp"

namespace vicc_glyphs {
namespace {

const std::string kData = VICC_GLYPHS_DATA_DIR;

TEST(Load, DispatchesOnExtensionCaseInsensitively) {
  const std::string upper = ::testing::TempDir() + "/vicc_SAMPLE.XML";
  {
    std::ifstream in(kData + "/samples/two_curves.xml");
    std::ofstream out(upper);
    out << in.rdbuf();
  }
  EXPECT_EQ(loadDiffusionCurves(upper).curves.size(), 2u);
  std::remove(upper.c_str());
  const DiffusionCurveImage heart = loadDiffusionCurves(kData + "/icons/heart.svg");
  EXPECT_EQ(heart.width, 24);
  EXPECT_FALSE(heart.curves.empty());
}

TEST(Load, SizeScalesEveryFormat) {
  EXPECT_EQ(loadDiffusionCurves(kData + "/icons/heart.svg", 96).width, 96);
  const DiffusionCurveImage xml = loadDiffusionCurves(kData + "/samples/two_curves.xml", 128);
  EXPECT_EQ(xml.width, 128);
  EXPECT_EQ(xml.height, 96);
  EXPECT_LT((xml.curves[0].control_points[0] - Point2(16, 20)).norm(), 1e-9);

  cv::Mat3b image(30, 30, cv::Vec3b(255, 255, 255));
  cv::rectangle(image, cv::Rect(8, 8, 14, 14), cv::Scalar(0, 0, 0), cv::FILLED);
  const std::string png = ::testing::TempDir() + "/vicc_square.PNG";
  ASSERT_TRUE(cv::imwrite(png, image));
  const DiffusionCurveImage traced = loadDiffusionCurves(png, 60);
  EXPECT_EQ(traced.width, 60);
  EXPECT_EQ(traced.curves.size(), 1u);
  std::remove(png.c_str());
}

TEST(Load, NegativeSizeIsAnError) {
  EXPECT_THROW(loadDiffusionCurves(kData + "/icons/heart.svg", -1), FormatError);
}

}  // namespace
}  // namespace vicc_glyphs
