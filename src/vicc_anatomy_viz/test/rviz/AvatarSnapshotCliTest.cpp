// vicc_avatar_snapshot as other tools call it: a PNG of the requested size from a sample
// database (its own Xvfb and private ROS master: DISPLAY and ROS_MASTER_URI are removed), and
// the documented non-zero exits with a clear message for each refused request.
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <QImage>

#include <array>
#include <cstdio>
#include <filesystem>
#include <string>

#include "run_command.hpp"
#include "vicc_anatomy_viz/patient_status_service.hpp"
#include "vicc_anatomy_viz/record_json.hpp"

namespace {

namespace fs = std::filesystem;
using namespace vicc_anatomy_viz;

using vicc_test::CommandResult;

CommandResult snapshot(const std::string& arguments, const std::string& environment = "") {
  return vicc_test::runCommand("env -u DISPLAY -u ROS_MASTER_URI " + environment + " " +
                               VICC_AVATAR_SNAPSHOT + " " + arguments);
}

class AvatarSnapshotCliTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    directory_ = fs::temp_directory_path() / ("vicc_snapshot_test_" + std::to_string(getpid()));
    fs::create_directories(directory_);
    fs::permissions(directory_, fs::perms::owner_all);
    const std::string sample =
        std::string(VICC_TEST_PACKAGE_DIR) + "/data/samples/fig4_6_patient.json";
    PatientStatusConfig config;
    config.encoding_config = defaultEncodingConfigPath();
    config.anatomy_config = defaultAnatomyConfigPath();
    config.store.path = db();
    PatientStatusService(config).record(
        examinationsFromJson(parseJsonText(readTextFile(sample), sample)),
        WriteMode::kRejectExisting);
  }
  static void TearDownTestSuite() { fs::remove_all(directory_); }
  static std::string db() { return (directory_ / "patients.db").string(); }
  static std::string out() { return (directory_ / "avatar.png").string(); }
  static fs::path directory_;
};

fs::path AvatarSnapshotCliTest::directory_;

TEST_F(AvatarSnapshotCliTest, WritesAPngOfTheRequestedSize) {
  const CommandResult run =
      snapshot("--db " + db() + " --patient SDH-046 --date 2023-03-06 --view back " +
               "--hide t_reflex --size 320x480 --out " + out());
  ASSERT_EQ(run.exit_code, 0) << run.output;
  QImage image;
  ASSERT_TRUE(image.load(QString::fromStdString(out())));
  EXPECT_EQ(image.width(), 320);
  EXPECT_EQ(image.height(), 480);
  // White background in the corner, the body (grey, not white) in the middle.
  EXPECT_EQ(image.pixelColor(2, image.height() - 3), QColor(255, 255, 255));
  EXPECT_LT(image.pixelColor(160, 240).lightness(), 250);
}

TEST_F(AvatarSnapshotCliTest, RefusesUnknownPatientsEarlyDatesAndUnreadableDatabases) {
  CommandResult run = snapshot("--db " + db() + " --patient SDH-999 --out " + out());
  EXPECT_EQ(run.exit_code, 3);
  EXPECT_NE(run.output.find("unknown patient 'SDH-999'"), std::string::npos) << run.output;
  run = snapshot("--db " + db() + " --patient SDH-046 --date 2020-01-01 --out " + out());
  EXPECT_EQ(run.exit_code, 3);
  EXPECT_NE(run.output.find("no examination of SDH-046 at or before 2020-01-01"), std::string::npos)
      << run.output;
  run = snapshot("--db " + (directory_ / "missing.db").string() + " --patient SDH-046 --out " +
                 out());
  EXPECT_EQ(run.exit_code, 3);
  EXPECT_NE(run.output.find("cannot read the database"), std::string::npos) << run.output;
  EXPECT_FALSE(fs::exists(directory_ / "missing.db"));  // read-only: nothing created
}

TEST_F(AvatarSnapshotCliTest, RefusesBadCommandLinesAndMissingDisplayServers) {
  CommandResult run = snapshot("--db " + db() + " --patient SDH-046 --view top --out " + out());
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.output.find("--view"), std::string::npos) << run.output;
  run = snapshot("--db " + db() + " --patient SDH-046");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.output.find("--out FILE.png is required"), std::string::npos) << run.output;
  run = snapshot("--db " + db() + " --patient SDH-046 --out " + out(), "DISPLAY=:4711");
  EXPECT_EQ(run.exit_code, 4);
  EXPECT_NE(run.output.find("no display server"), std::string::npos) << run.output;
  run = snapshot("--db " + db() + " --patient SDH-046 --out " + out(), "PATH=/nonexistent");
  EXPECT_EQ(run.exit_code, 4);
  EXPECT_NE(run.output.find("Xvfb is not installed"), std::string::npos) << run.output;
}

}  // namespace
