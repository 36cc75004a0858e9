// Runs the built `vicc_glyph modify` (VICC_GLYPH_BINARY) like a user.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>
#include <sstream>
#include <string>

#include "vicc_glyphs/io/orzan_xml.hpp"

namespace {

namespace fs = std::filesystem;

const std::string kIcons = std::string(VICC_GLYPHS_DATA_DIR) + "/icons/";

std::string readFile(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

struct ToolRun {
  int exit_code = -1;
  std::string err;
};

class ModifyCliTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("vicc_glyph_modify_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  ToolRun run(const std::string& arguments) const {
    const fs::path err = dir_ / "stderr.txt";
    const std::string command = std::string(VICC_GLYPH_BINARY) + " modify " + arguments + " >" +
                                (dir_ / "stdout.txt").string() + " 2>" + err.string();
    const int status = std::system(command.c_str());
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, readFile(err)};
  }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }

  fs::path dir_;
};

TEST_F(ModifyCliTest, WavesWriteThePngTheDciAndAReportPerCurve) {
  const ToolRun r =
      run(kIcons + "water.svg --out " + path("w.png") + " --dci " + path("w.xml") +
          " --size 200 --size-mm 40 --waveform triangle --frequency 3 --amplitude 0.5" +
          " --report " + path("w.json"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const cv::Mat png = cv::imread(path("w.png"));
  EXPECT_EQ(png.cols, 200);
  const vicc_glyphs::DiffusionCurveImage dci = vicc_glyphs::readOrzanXml(path("w.xml"));
  EXPECT_EQ(dci.width, 200);
  const nlohmann::json report = nlohmann::json::parse(readFile(path("w.json")));
  EXPECT_DOUBLE_EQ(report["px_per_mm"].get<double>(), 5.0);
  const nlohmann::json& curve = report["waves"]["curves"][0];
  EXPECT_EQ(report["waves"]["waveform"], "triangle");
  const double length = curve["arc_length_mm"].get<double>();
  EXPECT_EQ(curve["wave_count"].get<int>(), static_cast<int>(std::lround(0.3 * length)));
  EXPECT_DOUBLE_EQ(curve["requested_amplitude_mm"].get<double>(), 0.5);
  EXPECT_NEAR(curve["realised_amplitude_mm"]["max"].get<double>(), 0.5, 0.05);
  EXPECT_TRUE(curve["reduced_by_self_intersection_prevention"].is_array());
  EXPECT_EQ(curve["unresolved_crossings"].get<int>(), 0);
}

TEST_F(ModifyCliTest, DashesAndInflateCombine) {
  const ToolRun r =
      run(kIcons + "heart.svg --out " + path("h.png") +
          " --size 128 --inflate 2 --dashes 5 --dash-color FF8000 --report " + path("h.json"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json report = nlohmann::json::parse(readFile(path("h.json")));
  EXPECT_GT(report["inflate"][0]["area_after_mm2"].get<double>(),
            report["inflate"][0]["area_before_mm2"].get<double>());
  EXPECT_EQ(report["dashes"]["curves"][0]["dashes"].get<int>(), 5);
  EXPECT_EQ(report["curve_count"].get<int>(), 2);  // the heart and its diffusion barrier
}

TEST_F(ModifyCliTest, BadParametersExitWithAMessageNamingThem) {
  const std::string base = kIcons + "heart.svg --out " + path("x.png") + " --size 64 ";
  struct Case {
    std::string args;
    int code;
    std::string named;
  };
  const std::vector<Case> cases{
      {"--waveform square --frequency 3 --amplitude 0.5", 2, "--waveform"},
      {"--frequency 3 --amplitude nan", 2, "--amplitude"},
      {"--frequency 3 --amplitude -0.5", 2, "--amplitude"},
      {"--frequency 0 --amplitude 0.5", 2, "--frequency"},
      {"--frequency 3", 2, "--amplitude"},
      {"--dashes 4", 2, "--dash-color"},
      {"--dashes 4 --dash-color 12345", 2, "--dash-color"},
      {"--dashes 0 --dash-color 123456", 2, "--dashes"},
      {"--inflate inf", 2, "--inflate"},
      {"--size-mm -3", 2, "--size-mm"},
      {"--curves 1,a", 2, "--curves"},
      {"--curves 9 --frequency 3 --amplitude 0.5", 1, "curve index 9"},
      {"--frequency 100000 --amplitude 0.5", 1, "waves_per_mm"},
      // Used to overflow the wave count and leave the icon unmodified with exit code 0.
      {"--frequency 1e300 --amplitude 0.5", 1, "waves_per_mm"},
      // Used to hang in the polygon check's grid (a 10^7 px wave).
      {"--frequency 3 --amplitude 1e6", 1, "amplitude_mm"},
      {"--inflate 1e9", 1, "inflate offset"},
      {"--inflate -13", 1, "inflate offset"},
      // Dashes shorter than a pixel were drawn as an undashed contour (another level).
      {"--dashes 2000 --dash-color 123456", 1, "dashes on curve 0 would be"},
      // At the limit (a quarter of the glyph) the heart was clipped at the frame (94 % black).
      {"--inflate 12.5", 1, "carries curve 0 out of the 64 x 64 px image"},
      {"--curves 0, --inflate 1", 2, "--curves"},
  };
  for (const Case& c : cases) {
    const ToolRun r = run(base + c.args);
    EXPECT_EQ(r.exit_code, c.code) << c.args << ": " << r.err;
    EXPECT_NE(r.err.find(c.named), std::string::npos) << c.args << ": " << r.err;
  }
  const ToolRun missing = run(kIcons + "nope.svg --out " + path("x.png"));
  EXPECT_EQ(missing.exit_code, 1);
  EXPECT_NE(missing.err.find("nope.svg"), std::string::npos);
}

// A modification a curve cannot take leaves it as it was; the user is told so. Where no curve
// takes it, the glyph would look unmodified (the lowest level): an error, and no file.
TEST_F(ModifyCliTest, SkippedModificationsAreWarnedAboutAndNoneTakenIsAnError) {
  const ToolRun some = run(kIcons + "bell.svg --out " + path("b.png") +
                           " --size 256 --frequency 0.2 --amplitude 0.5");
  EXPECT_EQ(some.exit_code, 0) << some.err;
  EXPECT_NE(some.err.find("warning: curve 0: waves not applied: fewer than half a wave"),
            std::string::npos)
      << some.err;
  EXPECT_TRUE(std::filesystem::exists(path("b.png")));
  struct NoneTaken {
    std::string args, output, message;
  };
  const NoneTaken cases[] = {
      {"heart.svg --size 64 --frequency 1e-9 --amplitude 0.5", "x.png",
       "the waves cannot be drawn on any selected curve (curve 0: fewer than half a wave"},
      {"lightning-bolt.svg --size 64 --inflate -8", "y.png",
       "the inflation cannot be drawn on any selected curve (curve 0: nothing is left"},
  };
  for (const NoneTaken& c : cases) {
    const ToolRun r = run(kIcons + c.args + " --out " + path(c.output));
    EXPECT_EQ(r.exit_code, 1) << c.args << ": " << r.err;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << c.args << ": " << r.err;
    EXPECT_FALSE(std::filesystem::exists(path(c.output))) << c.args;
  }
}

TEST_F(ModifyCliTest, HelpSucceeds) { EXPECT_EQ(run("--help").exit_code, 0); }

}  // namespace
