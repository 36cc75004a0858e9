// scripts/rviz_antialiasing, avatar.launch's launch-prefix of rviz: which command line rviz
// gets for antialiasing true / false / auto, with `echo` standing in for rviz.
#include <gtest/gtest.h>

#include <unistd.h>
#include <filesystem>
#include <fstream>
#include <string>

#include "run_command.hpp"

namespace {

namespace fs = std::filesystem;

class RvizAntialiasingTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dev_ = fs::temp_directory_path() / ("vicc_rviz_aa_" + std::to_string(::getpid()));
    fs::create_directories(dev_ / "dri");
  }
  void TearDown() override { fs::remove_all(dev_); }

  // The script with a clean OpenGL environment and `dev_` as /dev.
  vicc_test::CommandResult run(const std::string& mode, const std::string& environment = "") {
    return vicc_test::runCommand(
        "env -u LIBGL_ALWAYS_SOFTWARE -u GALLIUM_DRIVER VICC_DEV_DIR=" + dev_.string() + " " +
        environment + " " + VICC_RVIZ_ANTIALIASING_SCRIPT + " " + mode + " echo -d x.rviz");
  }
  void addDevice(const std::string& name) { std::ofstream(dev_ / name) << ""; }

  fs::path dev_;
};

TEST_F(RvizAntialiasingTest, TrueAndFalseForceIt) {
  addDevice("dri/renderD128");
  EXPECT_EQ(run("true").output, "-d x.rviz\n");
  EXPECT_EQ(run("false").output, "--disable-anti-aliasing -d x.rviz\n");
}

TEST_F(RvizAntialiasingTest, AutoKeepsMsaaOnAGpu) {
  addDevice("dri/renderD128");
  EXPECT_EQ(run("auto").output, "-d x.rviz\n");
  fs::remove(dev_ / "dri/renderD128");
  addDevice("nvidia0");
  EXPECT_EQ(run("auto").output, "-d x.rviz\n");
}

TEST_F(RvizAntialiasingTest, AutoTurnsMsaaOffForSoftwareRendering) {
  const vicc_test::CommandResult no_gpu = run("auto");
  EXPECT_EQ(no_gpu.exit_code, 0);
  EXPECT_NE(no_gpu.output.find("no GPU device"), std::string::npos) << no_gpu.output;
  EXPECT_NE(no_gpu.output.find("--disable-anti-aliasing -d x.rviz\n"), std::string::npos)
      << no_gpu.output;
  addDevice("dri/renderD128");
  for (const char* environment : {"LIBGL_ALWAYS_SOFTWARE=1", "GALLIUM_DRIVER=llvmpipe"}) {
    const vicc_test::CommandResult forced = run("auto", environment);
    EXPECT_NE(forced.output.find("--disable-anti-aliasing -d x.rviz\n"), std::string::npos)
        << environment << ": " << forced.output;
  }
  EXPECT_EQ(run("auto", "LIBGL_ALWAYS_SOFTWARE=0").output, "-d x.rviz\n");
}

TEST_F(RvizAntialiasingTest, AnUnknownModeIsAUsageError) {
  const vicc_test::CommandResult bad = run("maybe");
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.output.find("true, false or auto, got 'maybe'"), std::string::npos) << bad.output;
}

// The launch files hand rviz to the script (roslaunch prints the command it would run).
TEST(RvizAntialiasingLaunch, AvatarLaunchStartsRvizThroughTheScript) {
  const std::string launch = std::string(VICC_AVATAR_LAUNCH);
  const vicc_test::CommandResult automatic =
      vicc_test::runCommand("roslaunch --args rviz " + launch);
  EXPECT_EQ(automatic.exit_code, 0) << automatic.output;
  EXPECT_NE(automatic.output.find("scripts/rviz_antialiasing auto "), std::string::npos)
      << automatic.output;
  EXPECT_NE(automatic.output.find("rviz -d "), std::string::npos) << automatic.output;
  const vicc_test::CommandResult forced =
      vicc_test::runCommand("roslaunch --args rviz " + launch + " antialiasing:=false");
  EXPECT_NE(forced.output.find("scripts/rviz_antialiasing false "), std::string::npos)
      << forced.output;
}

}  // namespace
