// "vicc_glyph design" (contract command line) run like a user.
#include <gtest/gtest.h>

#include <fstream>
#include <opencv2/imgcodecs.hpp>

#include "../support/tool_run.hpp"

namespace {

class DesignCliTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = vicc_glyphs::test::freshTestDirectory(
        "vicc_glyph_design_", ::testing::UnitTest::GetInstance()->current_test_info()->name());
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  vicc_glyphs::test::ToolRun run(const std::string& args) const {
    return vicc_glyphs::test::runTool(args, dir_);
  }
  static std::string design(const std::string& name) {
    return std::string(VICC_GLYPHS_DESIGNS_DIR) + "/" + name + ".yaml";
  }
  std::filesystem::path dir_;
};

}  // namespace

TEST_F(DesignCliTest, WritesPngAndDciAtTheRequestedSize) {
  const auto png = dir_ / "rain.png", xml = dir_ / "rain.xml";
  const auto result =
      run("design " + design("rain_forecast_sine") + " --values probability=65,amount=3 --out " +
          png.string() + " --dci " + xml.string() + " --size 96");
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const cv::Mat image = cv::imread(png.string());
  EXPECT_EQ(image.cols, 96);
  EXPECT_TRUE(std::filesystem::file_size(xml) > 100);
}

TEST_F(DesignCliTest, BadValuesExitTwoNamingTheParameter) {
  const std::string out = " --out " + (dir_ / "x.png").string();
  const auto outside =
      run("design " + design("rain_forecast_sine") + " --values probability=120,amount=3" + out);
  EXPECT_EQ(outside.exit_code, 2);
  EXPECT_NE(outside.err.find("probability = 120 is outside its domain"), std::string::npos)
      << outside.err;
  const auto nan =
      run("design " + design("rain_forecast_sine") + " --values probability=nan,amount=3" + out);
  EXPECT_EQ(nan.exit_code, 2);
  EXPECT_NE(nan.err.find("probability is NaN"), std::string::npos) << nan.err;
  const auto missing =
      run("design " + design("rain_forecast_sine") + " --values probability=50" + out);
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_NE(missing.err.find("amount"), std::string::npos);
  const auto usage = run("design " + design("rain_forecast_sine") + out);
  EXPECT_EQ(usage.exit_code, 2);
  const auto no_file = run("design /nonexistent.yaml --values a=1" + out);
  EXPECT_EQ(no_file.exit_code, 1);
  EXPECT_FALSE(std::filesystem::exists(dir_ / "x.png"));
}

TEST_F(DesignCliTest, MapPlacesOneGlyphPerRow) {
  const auto csv = dir_ / "rows.csv", png = dir_ / "map.png";
  std::ofstream(csv) << "label,lon,lat,probability,amount\nA,8,50,95,1\nB,12,52,40,20\n";
  const auto result =
      run("design-map " + design("rain_forecast_sine") + " --table " + csv.string() + " --out " +
          png.string() + " --glyph-size 128 --width 500");
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_NE(result.out.find("(2 glyphs)"), std::string::npos);
  const cv::Mat map = cv::imread(png.string());
  EXPECT_EQ(map.cols, 500);
  // Glyph A sits at the left margin (x = 128), B at the right (x = 372): both draw there.
  const auto darkest = [&](int x0) {
    double low = 255;
    for (int y = 0; y < map.rows; ++y) {
      for (int x = x0 - 20; x < x0 + 20; ++x) {
        const cv::Vec3b p = map.at<cv::Vec3b>(y, x);
        low = std::min<double>(low, p[0] + p[1] + p[2]);
      }
    }
    return low;
  };
  EXPECT_LT(darkest(128), 400);
  EXPECT_LT(darkest(372), 400);
  std::ofstream(csv) << "label,lon,lat,probability,amount\nA,8,50,95,1\nB,12,52,140,20\n";
  const auto bad = run("design-map " + design("rain_forecast_sine") + " --table " + csv.string() +
                       " --out " + png.string());
  EXPECT_EQ(bad.exit_code, 1);
  EXPECT_NE(bad.err.find("probability = 140 is outside its domain"), std::string::npos);
}
