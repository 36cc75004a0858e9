// "vicc_glyph design" (contract command line) run like a user.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <iterator>
#include <opencv2/imgcodecs.hpp>
#include <string>
#include <utility>
#include <vector>

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
  // design-map of the rain design for a table with these rows (after its header).
  vicc_glyphs::test::ToolRun map(const std::string& rows, const std::string& options = "",
                                 const std::string& header = kRainHeader) const {
    std::ofstream(dir_ / "rows.csv") << header << rows;
    return run("design-map " + design("rain_forecast_sine") + " --table " +
               (dir_ / "rows.csv").string() + " --out " + mapPng().string() + " " + options);
  }
  std::filesystem::path mapPng() const { return dir_ / "map.png"; }
  static constexpr const char* kRainHeader = "label,lon,lat,probability,amount\n";
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
  EXPECT_EQ(result.err, "");  // apart: no overlap warning
  std::ofstream(csv) << "label,lon,lat,probability,amount\nA,8,50,95,1\nB,12,52,140,20\n";
  const auto bad = run("design-map " + design("rain_forecast_sine") + " --table " + csv.string() +
                       " --out " + png.string());
  EXPECT_EQ(bad.exit_code, 1);
  EXPECT_NE(bad.err.find("line 3 (B): probability = 140 is outside its domain"), std::string::npos)
      << bad.err;
}

namespace {

// Sum of B, G and R of the darkest pixel in the rectangle: below 400 where a glyph draws.
double darkestIn(const cv::Mat& image, const cv::Rect& area) {
  double low = 255 * 3;
  const cv::Mat part = image(area & cv::Rect(0, 0, image.cols, image.rows));
  part.forEach<cv::Vec3b>(
      [&](const cv::Vec3b& p, const int*) { low = std::min<double>(low, p[0] + p[1] + p[2]); });
  return low;
}

}  // namespace

TEST_F(DesignCliTest, MapRefusesAWidthThatLeavesNoRoomBetweenTheMargins) {
  // 2 x 200 > 300 made the scale negative: the map was drawn upside down.
  const auto narrow = map("A,8,50,95,1\nB,12,52,40,20\n", "--width 300 --glyph-size 200");
  EXPECT_EQ(narrow.exit_code, 2);
  EXPECT_NE(narrow.err.find("--width 300 is too narrow for --glyph-size 200: --width must be at "
                            "least 3 x --glyph-size (600)"),
            std::string::npos)
      << narrow.err;
  EXPECT_FALSE(std::filesystem::exists(mapPng()));
  EXPECT_EQ(map("A,8,50,95,1\n", "--width 383 --glyph-size 128").exit_code, 2);
  EXPECT_EQ(map("A,8,50,95,1\n", "--width 384 --glyph-size 128").exit_code, 0);
}

// A map written over its table would destroy the table it was drawn from.
TEST_F(DesignCliTest, MapRefusesAnOutputThatIsTheTable) {
  std::ofstream(dir_ / "rows.csv") << kRainHeader << "A,8,50,95,1\n";
  const auto size_before = std::filesystem::file_size(dir_ / "rows.csv");
  const auto same = run("design-map " + design("rain_forecast_sine") + " --table " +
                        (dir_ / "rows.csv").string() + " --out " + (dir_ / "rows.csv").string());
  EXPECT_EQ(same.exit_code, 2);
  EXPECT_NE(same.err.find("--table and --out are the same file"), std::string::npos) << same.err;
  EXPECT_EQ(std::filesystem::file_size(dir_ / "rows.csv"), size_before);
}

TEST_F(DesignCliTest, MapIsNorthUpAndItsHeightIsBounded) {
  // 0.001 degrees of longitude over 2 of latitude: fitted to the width the map was 14 GB.
  const auto tall = map("South,10,50,95,1\nNorth,10.001,52,40,20\n");
  ASSERT_EQ(tall.exit_code, 0) << tall.err;
  cv::Mat image = cv::imread(mapPng().string());
  ASSERT_EQ(image.cols, 900);
  EXPECT_EQ(image.rows, 8192);
  EXPECT_LT(darkestIn(image, {400, 0, 100, 150}), 400);                   // North at the top
  EXPECT_LT(darkestIn(image, {400, image.rows - 200, 100, 200}), 400);    // South at the bottom
  EXPECT_EQ(darkestIn(image, {0, 200, 900, image.rows - 400}), 255 * 3);  // white between

  // One longitude for all rows (a zero span) tried to allocate 1.9 TB.
  ASSERT_EQ(map("South,10,50,95,1\nNorth,10,52,40,20\n").exit_code, 0);
  EXPECT_EQ(cv::imread(mapPng().string()).rows, 8192);
}

// A label is drawn after all glyphs, on a white halo: glyph BB, just south of AA, covers AA's
// label, and AA's letters must look as on white paper. (Drawn with each glyph, the label lay
// under the next glyph's cloud.) The letters are where the map with label AA differs from the
// same map with an empty label; CC fixes the extent, so the three maps share one layout.
TEST_F(DesignCliTest, MapLabelsStayReadableOverANeighbouringGlyph) {
  const std::string options = "--glyph-size 128 --width 500";
  std::string warnings;
  const auto draw = [&](const std::string& rows) {
    const auto run = map(rows, options);
    EXPECT_EQ(run.exit_code, 0);
    warnings = run.err;
    return cv::imread(mapPng().string());
  };
  const cv::Mat unlabelled = draw(",8,52,95,20\nCC,12,50,40,1\n");
  const cv::Mat alone = draw("AA,8,52,95,20\nCC,12,50,40,1\n");
  EXPECT_EQ(warnings, "");
  const cv::Mat covered = draw("AA,8,52,95,20\nBB,8.1,51,95,20\nCC,12,50,40,1\n");
  // The halo that keeps AA's label readable whitens a part of BB's glyph: said on stderr.
  EXPECT_NE(warnings.find("warning: the label of 'AA' (line 2) covers part of the glyph of 'BB' "
                          "(line 3)"),
            std::string::npos)
      << warnings;
  ASSERT_EQ(alone.size(), covered.size());
  ASSERT_EQ(alone.size(), unlabelled.size());
  const auto difference = [](const cv::Vec3b& a, const cv::Vec3b& b) {
    return std::abs(a[0] - b[0]) + std::abs(a[1] - b[1]) + std::abs(a[2] - b[2]);
  };
  int letters = 0, as_on_paper = 0;
  cv::Rect letter_box;
  for (int y = 0; y < alone.rows; ++y) {
    for (int x = 0; x < alone.cols; ++x) {
      if (difference(alone.at<cv::Vec3b>(y, x), unlabelled.at<cv::Vec3b>(y, x)) == 0) continue;
      ++letters;
      letter_box |= cv::Rect(x, y, 1, 1);
      as_on_paper += difference(alone.at<cv::Vec3b>(y, x), covered.at<cv::Vec3b>(y, x)) <= 30;
    }
  }
  ASSERT_GT(letters, 20);
  EXPECT_GT(as_on_paper, 0.95 * letters) << as_on_paper << " of " << letters;
  // Beside the letters: white paper in the map without BB, BB's grey-blue cloud (110-140 per
  // channel) in the other.
  const cv::Rect left_of(letter_box.x - 10, letter_box.y, 5, letter_box.height);
  const cv::Rect right_of(letter_box.br().x + 5, letter_box.y, 5, letter_box.height);
  for (const cv::Rect& beside : {left_of, right_of}) {
    EXPECT_EQ(darkestIn(alone, beside), 3 * 255);
    EXPECT_LT(darkestIn(covered, beside), 450);
  }
}

TEST_F(DesignCliTest, MapRefusesALabelItsFontCannotDraw) {
  const auto umlaut = map("Th\u00fcringen,11,51,95,1\n");
  EXPECT_EQ(umlaut.exit_code, 1);
  EXPECT_NE(umlaut.err.find("line 2, column label: 'Th\u00fcringen' has a character the map's "
                            "font cannot draw"),
            std::string::npos)
      << umlaut.err;
  EXPECT_FALSE(std::filesystem::exists(mapPng()));
  EXPECT_EQ(map("Thueringen,11,51,95,1\n").exit_code, 0);
}

TEST_F(DesignCliTest, MapCentresRowsAtOnePlace) {
  const auto single = map("A,10,50,95,1\n", "--glyph-size 96 --width 900");
  ASSERT_EQ(single.exit_code, 0) << single.err;
  const cv::Mat image = cv::imread(mapPng().string());
  EXPECT_EQ(image.size(), cv::Size(900, 2 * 96 + 20));
  EXPECT_LT(darkestIn(image, {430, 76, 40, 40}), 400);              // centre (450, 96)
  EXPECT_EQ(darkestIn(image, {0, 0, 390, image.rows}), 255 * 3);    // nothing left of it
  EXPECT_EQ(darkestIn(image, {510, 0, 390, image.rows}), 255 * 3);  // nor right of it
}

TEST_F(DesignCliTest, MapWarnsNamingBothRowsWhoseGlyphsOverlap) {
  const auto same = map("Here,10,50,95,1\nThere,12,52,40,20\nAlsoHere,10,50,40,20\n");
  ASSERT_EQ(same.exit_code, 0) << same.err;
  EXPECT_NE(same.err.find("warning: the glyphs of 'Here' (line 2) and 'AlsoHere' (line 4) "
                          "overlap"),
            std::string::npos)
      << same.err;
  EXPECT_EQ(same.err.find("'There'"), std::string::npos) << same.err;
  EXPECT_TRUE(std::filesystem::exists(mapPng()));
}

TEST_F(DesignCliTest, MapRefusesNonFiniteAndOutOfRangeCellsNamingLineAndColumn) {
  const std::vector<std::pair<std::string, std::string>> cases{
      {"B,nan,50,95,1", "line 3, column lon: 'nan' is not a finite number"},
      {"B,8,inf,95,1", "line 3, column lat: 'inf' is not a finite number"},
      {"B,8,-90.5,95,1", "line 3, column lat: '-90.5' is outside [-90, 90]"},
      {"B,180.5,50,95,1", "line 3, column lon: '180.5' is outside [-180, 180]"},
      {"B,8,50,NaN,1", "line 3, column probability: 'NaN' is not a finite number"},
      {"B,8,50,95,-inf", "line 3, column amount: '-inf' is not a finite number"},
      {"B,8,50,95,", "line 3, column amount: '' is not a number"},
  };
  for (const auto& [row, message] : cases) {
    const auto bad = map("A,8,50,95,1\n" + row + "\n");
    EXPECT_EQ(bad.exit_code, 1) << row;
    EXPECT_NE(bad.err.find(message), std::string::npos) << row << ": " << bad.err;
    EXPECT_EQ(bad.err.find("OpenCV"), std::string::npos) << bad.err;
  }
}

TEST_F(DesignCliTest, MapHeaderMustHaveEachDesignVariableOnce) {
  const std::vector<std::pair<std::string, std::string>> cases{
      {"label,lon,lat,probability,amount,amount\n", "column 'amount' appears twice in the header"},
      {"label,lon,lat,lat,probability,amount\n", "column 'lat' appears twice in the header"},
      {"label,lon,lat,probability,amount,wind\n",
       "column 'wind' is not a variable of the design (design rain_forecast_sine has "
       "probability, amount)"},
      {"label,lon,lat,amount\n", "the header has no column for variable 'probability'"},
      {"lat,lon,label,probability,amount\n", "the header must start with label,lon,lat"},
  };
  for (const auto& [header, message] : cases) {
    const auto bad = map("A,8,50,95,1,1\n", "", header);
    EXPECT_EQ(bad.exit_code, 1) << header;
    EXPECT_NE(bad.err.find(message), std::string::npos) << header << ": " << bad.err;
  }
  // Any column order is fine: the values go by name.
  const auto reordered = map("A,8,50,1,95\n", "", "label,lon,lat,amount,probability\n");
  EXPECT_EQ(reordered.exit_code, 0) << reordered.err;
}

TEST_F(DesignCliTest, MapAcceptsWindowsLineEndsAndByteOrderMark) {
  const auto crlf =
      map("A,8,50,95,1\r\nB,12,52,40,20\r\n", "", "label,lon,lat,probability,amount\r\n");
  ASSERT_EQ(crlf.exit_code, 0) << crlf.err;
  EXPECT_NE(crlf.out.find("(2 glyphs)"), std::string::npos) << crlf.out;
  // Spreadsheets also start the file with a UTF-8 byte order mark.
  const auto bom = map("A,8,50,95,1\r\n", "", "\xEF\xBB\xBFlabel,lon,lat,probability,amount\r\n");
  EXPECT_EQ(bom.exit_code, 0) << bom.err;
}

TEST_F(DesignCliTest, CheckDesignBuildsEveryLevelCombination) {
  const auto result = run("check-design " + design("rain_forecast_sine") + " --size 96");
  EXPECT_EQ(result.exit_code, 0) << result.err;
  EXPECT_NE(result.out.find("rain_forecast_sine at 96 px: all 15 level combinations build"),
            std::string::npos)
      << result.out;
}

// A design that loads but fails for some data: the heavy-rain drops inflated by 3.5 mm leave
// the frame. The glyph server would meet that only when heavy rain is forecast.
TEST_F(DesignCliTest, CheckDesignListsTheLevelsThatFail) {
  std::ifstream shipped(design("rain_forecast_sine"));
  std::string text((std::istreambuf_iterator<char>(shipped)), std::istreambuf_iterator<char>());
  for (const auto& [from, to] : std::vector<std::pair<std::string, std::string>>{
           {"icon: icons/", "icon: " + std::string(VICC_GLYPHS_DESIGNS_DIR) + "/icons/"},
           {"offsets_mm: [-0.8, 0.0, 0.8]", "offsets_mm: [-0.8, 0.0, 3.5]"}}) {
    const std::size_t at = text.find(from);
    ASSERT_NE(at, std::string::npos) << from;
    text.replace(at, from.size(), to);
  }
  std::ofstream(dir_ / "rain_forecast_sine.yaml") << text;
  const auto result =
      run("check-design " + (dir_ / "rain_forecast_sine.yaml").string() + " --size 96");
  EXPECT_EQ(result.exit_code, 1) << result.err;
  EXPECT_NE(result.out.find("5 of 15 level combinations fail"), std::string::npos) << result.out;
  EXPECT_NE(result.out.find("probability level 4 [90, 100], amount level 2 [7.6, 200]: "),
            std::string::npos)
      << result.out;
  EXPECT_NE(result.out.find("out of the 96 x 96 px frame"), std::string::npos) << result.out;
  EXPECT_EQ(result.out.find("amount level 1"), std::string::npos) << result.out;
}

TEST_F(DesignCliTest, CheckDesignUsageErrors) {
  EXPECT_EQ(run("check-design").exit_code, 2);
  EXPECT_EQ(run("check-design " + design("rain_forecast_sine") + " --size 8").exit_code, 2);
  const auto missing = run("check-design " + (dir_ / "none.yaml").string());
  EXPECT_EQ(missing.exit_code, 1);
  EXPECT_NE(missing.err.find("none.yaml"), std::string::npos) << missing.err;
}
