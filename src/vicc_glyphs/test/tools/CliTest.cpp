#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <opencv2/imgcodecs.hpp>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

// Runs the built vicc_glyph binary (VICC_GLYPH_BINARY, set by cmake/cli.cmake) like a user.

namespace {

namespace fs = std::filesystem;

struct ToolRun {
  int exit_code = -1;
  std::string out;
  std::string err;
};

std::string readFile(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

class CliTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("vicc_glyph_cli_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  ToolRun run(const std::string& arguments, const std::string& binary = VICC_GLYPH_BINARY) const {
    const fs::path out = dir_ / "stdout.txt", err = dir_ / "stderr.txt";
    const std::string command =
        binary + " " + arguments + " >" + out.string() + " 2>" + err.string();
    const int status = std::system(command.c_str());
    ToolRun result;
    result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    result.out = readFile(out);
    result.err = readFile(err);
    return result;
  }

  static std::string data(const std::string& name) {
    return std::string(TEST_DATA_DIR) + "/" + name;
  }
  // The package's own files, from the test data directory (test/tools).
  static std::string packageFile(const std::string& name) {
    return std::string(TEST_DATA_DIR) + "/../../" + name;
  }

  fs::path dir_;
};

cv::Vec3b rgbAt(const cv::Mat& bgr, int x, int y) {
  const cv::Vec3b pixel = bgr.at<cv::Vec3b>(y, x);
  return {pixel[2], pixel[1], pixel[0]};
}

TEST_F(CliTest, RendersAnOrzanXmlWithTheColoursOnTheirSides) {
  const fs::path png = dir_ / "line.png";
  const ToolRun result =
      run("render " + data("left_red_right_blue.xml") + " --out " + png.string());
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const cv::Mat image = cv::imread(png.string());
  ASSERT_EQ(image.size(), cv::Size(40, 32));
  EXPECT_EQ(rgbAt(image, 5, 16), cv::Vec3b(255, 0, 0));
  EXPECT_EQ(rgbAt(image, 35, 16), cv::Vec3b(0, 0, 255));
}

TEST_F(CliTest, RendersAnSvgAtTheRequestedSizeWithReportAndDci) {
  const fs::path png = dir_ / "square.png", xml = dir_ / "square.xml";
  const ToolRun result = run("render " + data("red_square.svg") + " --out " + png.string() +
                             " --size 48 --report --dci " + xml.string());
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const cv::Mat image = cv::imread(png.string());
  ASSERT_EQ(image.size(), cv::Size(48, 48));
  EXPECT_EQ(rgbAt(image, 24, 24), cv::Vec3b(255, 0, 0));
  EXPECT_EQ(rgbAt(image, 2, 2), cv::Vec3b(255, 255, 255));
  EXPECT_TRUE(fs::exists(xml));
  // A flat square: each region takes its one colour, without the multigrid.
  EXPECT_NE(result.out.find("multigrid: not needed, every free region has one Dirichlet value"),
            std::string::npos)
      << result.out;
  EXPECT_EQ(result.out.find("CG iterations"), std::string::npos) << result.out;
  EXPECT_NE(result.out.find("time ms"), std::string::npos);
  EXPECT_EQ(result.err.find("warning"), std::string::npos) << result.err;
  // Colours that diffuse: the default stops on the error tolerance and says so.
  const ToolRun diffused = run("render " + packageFile("data/samples/two_curves.xml") + " --out " +
                               png.string() + " --size 48 --report");
  ASSERT_EQ(diffused.exit_code, 0) << diffused.err;
  EXPECT_NE(diffused.out.find("(error tolerance reached)"), std::string::npos) << diffused.out;
  EXPECT_NE(diffused.out.find("FMG start  : rms residual"), std::string::npos) << diffused.out;
  EXPECT_NE(diffused.out.find("estimated max error"), std::string::npos) << diffused.out;
  EXPECT_EQ(diffused.out.find("not needed"), std::string::npos) << diffused.out;
}

TEST_F(CliTest, CyclesOverrideTheToleranceAndExcludeIt) {
  const fs::path png = dir_ / "square.png";
  const std::string render = "render " + data("red_square.svg") + " --out " + png.string();
  const ToolRun fixed = run(render + " --size 48 --report --cycles 3");
  ASSERT_EQ(fixed.exit_code, 0) << fixed.err;
  EXPECT_NE(fixed.out.find(" 3 CG iterations"), std::string::npos) << fixed.out;
  EXPECT_NE(fixed.out.find("iteration 3: rms residual"), std::string::npos) << fixed.out;
  EXPECT_EQ(fixed.out.find("tolerance reached"), std::string::npos) << fixed.out;
  const ToolRun both = run(render + " --cycles 3 --tolerance 0.01");
  EXPECT_EQ(both.exit_code, 2);
  EXPECT_NE(both.err.find("--cycles and --tolerance exclude each other"), std::string::npos);
  const ToolRun bad = run(render + " --tolerance -1");
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("--tolerance needs a positive number"), std::string::npos);
}

TEST_F(CliTest, BadArgumentsFailWithAMessage) {
  const ToolRun nothing = run("");
  EXPECT_EQ(nothing.exit_code, 2);
  EXPECT_NE(nothing.err.find("usage"), std::string::npos);

  const ToolRun unknown = run("paint x.svg");
  EXPECT_EQ(unknown.exit_code, 2);
  EXPECT_NE(unknown.err.find("unknown subcommand 'paint'"), std::string::npos);

  const ToolRun no_out = run("render " + data("red_square.svg"));
  EXPECT_EQ(no_out.exit_code, 2);
  EXPECT_NE(no_out.err.find("missing --out"), std::string::npos);

  const ToolRun bad_size = run("render " + data("red_square.svg") + " --out x.png --size -3");
  EXPECT_EQ(bad_size.exit_code, 2);
  EXPECT_NE(bad_size.err.find("--size"), std::string::npos);

  const ToolRun bad_outliner =
      run("render " + data("red_square.svg") + " --out x.png --stroke-outliner potrace");
  EXPECT_EQ(bad_outliner.exit_code, 2);
  EXPECT_NE(bad_outliner.err.find("--stroke-outliner"), std::string::npos) << bad_outliner.err;
}

TEST_F(CliTest, BadFilesFailWithAMessage) {
  const ToolRun missing =
      run("render " + (dir_ / "missing.svg").string() + " --out " + (dir_ / "x.png").string());
  EXPECT_EQ(missing.exit_code, 1);
  EXPECT_NE(missing.err.find("missing.svg"), std::string::npos) << missing.err;

  const fs::path broken = dir_ / "broken.xml";
  std::ofstream(broken) << "<curve_set image_width=\"-4\">";
  const ToolRun malformed =
      run("render " + broken.string() + " --out " + (dir_ / "x.png").string());
  EXPECT_EQ(malformed.exit_code, 1);
  EXPECT_FALSE(malformed.err.empty());

  const ToolRun unwritable = run("render " + data("red_square.svg") + " --out " +
                                 (dir_ / "no_such_dir" / "x.png").string());
  EXPECT_EQ(unwritable.exit_code, 1);
  EXPECT_NE(unwritable.err.find("cannot write"), std::string::npos) << unwritable.err;
}

// A picture of only the background would pass for a rendering: a uniform PNG (nothing to
// trace) or a DCI whose curves miss the frame is an error, and nothing is written.
TEST_F(CliTest, NothingToDrawIsAnErrorNotABackgroundPicture) {
  const fs::path outside = dir_ / "outside.xml";
  std::ofstream(outside)
      << "<curve_set image_width=\"32\" image_height=\"32\"><curve><control_points_set>"
         "<control_point x=\"200\" y=\"200\"/><control_point x=\"210\" y=\"210\"/>"
         "<control_point x=\"220\" y=\"220\"/><control_point x=\"230\" y=\"230\"/>"
         "</control_points_set><left_colors_set>"
         "<left_color G=\"0\" R=\"255\" globalID=\"0\" B=\"0\"/></left_colors_set>"
         "<right_colors_set><right_color G=\"0\" R=\"0\" globalID=\"0\" B=\"255\"/>"
         "</right_colors_set></curve></curve_set>";
  const fs::path png = dir_ / "nothing.png";
  const ToolRun render = run("render " + outside.string() + " --out " + png.string());
  EXPECT_EQ(render.exit_code, 1);
  EXPECT_NE(render.err.find("nothing to draw"), std::string::npos) << render.err;
  EXPECT_FALSE(fs::exists(png));
  // Inside the frame, closed (so that waves apply), but both sides barriers: nothing emits a
  // colour.
  const fs::path barriers = dir_ / "barriers.xml";
  std::ofstream(barriers)
      << "<curve_set image_width=\"32\" image_height=\"32\"><curve><control_points_set>"
         "<control_point x=\"4\" y=\"4\"/><control_point x=\"12\" y=\"4\"/>"
         "<control_point x=\"20\" y=\"4\"/><control_point x=\"28\" y=\"4\"/>"
         "<control_point x=\"28\" y=\"12\"/><control_point x=\"28\" y=\"20\"/>"
         "<control_point x=\"28\" y=\"28\"/><control_point x=\"20\" y=\"28\"/>"
         "<control_point x=\"12\" y=\"28\"/><control_point x=\"4\" y=\"28\"/>"
         "<control_point x=\"4\" y=\"20\"/><control_point x=\"4\" y=\"12\"/>"
         "<control_point x=\"4\" y=\"4\"/>"
         "</control_points_set><left_colors_set boundary=\"Neumann\"></left_colors_set>"
         "<right_colors_set boundary=\"Neumann\"></right_colors_set></curve></curve_set>";
  const ToolRun modify = run("modify " + barriers.string() + " --out " + png.string() +
                             " --size 64 --frequency 4 --amplitude 0.5");
  EXPECT_EQ(modify.exit_code, 1);
  EXPECT_NE(modify.err.find("nothing to draw"), std::string::npos) << modify.err;
  EXPECT_FALSE(fs::exists(png));
  // Curves that all miss the frame: nothing to modify (it used to say "NearestCurvePoint: no
  // curve points").
  const ToolRun missed = run("modify " + outside.string() + " --out " + png.string() +
                             " --size 64 --frequency 4 --amplitude 0.5");
  EXPECT_EQ(missed.exit_code, 1);
  EXPECT_NE(missed.err.find("no curve of the image comes near its 64 x 64 px frame"),
            std::string::npos)
      << missed.err;
  // Glyphs narrower than 16 px cannot show their waves: modify refuses them.
  const ToolRun tiny = run("modify " + data("red_square.svg") + " --out " + png.string() +
                           " --size 8 --frequency 4 --amplitude 0.5");
  EXPECT_EQ(tiny.exit_code, 2);
  EXPECT_NE(tiny.err.find("--size"), std::string::npos) << tiny.err;
}

// An output naming the input would destroy it (a traced PNG overwritten by its rendering).
TEST_F(CliTest, AnOutputThatIsTheInputIsRefusedBeforeAnythingIsWritten) {
  const fs::path input = dir_ / "square.svg";
  fs::copy_file(data("red_square.svg"), input);
  const auto size_before = fs::file_size(input);
  const ToolRun render = run("render " + input.string() + " --out " + input.string());
  EXPECT_EQ(render.exit_code, 2);
  EXPECT_NE(render.err.find("INPUT and --out are the same file"), std::string::npos) << render.err;
  const ToolRun modify = run("modify " + input.string() + " --out " + (dir_ / "m.png").string() +
                             " --report " + input.string() + " --inflate 0.5");
  EXPECT_EQ(modify.exit_code, 2);
  EXPECT_NE(modify.err.find("INPUT and --report are the same file"), std::string::npos)
      << modify.err;
  EXPECT_EQ(fs::file_size(input), size_before);
}

TEST_F(CliTest, HelpSucceeds) {
  EXPECT_EQ(run("--help").exit_code, 0);
  const ToolRun help = run("render --help");
  EXPECT_EQ(help.exit_code, 0);
  EXPECT_NE(help.out.find("--size N"), std::string::npos);
}

// A copy of vicc_glyph with no share/vicc_glyphs near it (as when copied out of the devel
// space) aborted (uncaught exception) before reading its arguments.
TEST_F(CliTest, CopiedBinaryWithoutShareRunsWithHelpAndModelAndSaysWhatIsMissing) {
  const fs::path copy = dir_ / "a" / "b" / "c" / "vicc_glyph";  // share/ looked for up to c/../..
  fs::create_directories(copy.parent_path());
  fs::copy_file(VICC_GLYPH_BINARY, copy);
  for (const std::string command : {"levels", "design", "design-map", "fit-model"}) {
    const ToolRun help = run(command + " --help", copy.string());
    EXPECT_EQ(help.exit_code, 0) << command << ": " << help.err;
    EXPECT_NE(help.out.find("usage: vicc_glyph " + command), std::string::npos) << help.out;
  }
  const std::string model = packageFile("config/perception_model.yaml");
  const ToolRun given = run("levels --model " + model, copy.string());
  EXPECT_EQ(given.exit_code, 0) << given.err;
  EXPECT_NE(given.out.find("levels"), std::string::npos);

  const fs::path rows = dir_ / "rows.csv";
  std::ofstream(rows) << "label,lon,lat,probability,amount\nA,8,50,95,1\n";
  const std::string map = "design-map " + packageFile("designs/rain_forecast_sine.yaml") +
                          " --table " + rows.string() + " --out " + (dir_ / "map.png").string();
  EXPECT_EQ(run(map + " --model " + model, copy.string()).exit_code, 0);
  const fs::path survey = dir_ / "survey.csv";
  std::ofstream(survey) << "stimulus,perceived,experiment,second_stimulus\n1,1,ColAmpl2,\n";
  const std::vector<std::pair<std::string, std::string>> without_model{
      {"levels", "give --model MODEL.yaml"},
      {"design " + packageFile("designs/rain_forecast_sine.yaml") +
           " --values probability=5,amount=1 --out " + (dir_ / "glyph.png").string(),
       "give --model MODEL.yaml"},
      {map, "give --model MODEL.yaml"},
      {"fit-model " + survey.string() + " --out " + (dir_ / "m.yaml").string(),
       "give --base MODEL.yaml"},
  };
  for (const auto& [command, hint] : without_model) {
    const ToolRun missing = run(command, copy.string());
    EXPECT_EQ(missing.exit_code, 1) << command;
    EXPECT_NE(missing.err.find("the default perception model was not found"), std::string::npos)
        << missing.err;
    EXPECT_NE(missing.err.find(hint), std::string::npos) << missing.err;
  }
}

TEST_F(CliTest, FitModelRefusesASurveyWithoutAnswers) {
  const fs::path survey = dir_ / "survey.csv", model = dir_ / "fitted.yaml";
  std::ofstream(survey) << "stimulus,perceived,experiment,second_stimulus\n\n";
  const ToolRun empty = run("fit-model " + survey.string() + " --out " + model.string());
  EXPECT_EQ(empty.exit_code, 1);
  EXPECT_NE(empty.err.find(survey.string() + ": the table has no answers"), std::string::npos)
      << empty.err;
  EXPECT_FALSE(fs::exists(model));  // the base model is not written as if fitted
}

}  // namespace
