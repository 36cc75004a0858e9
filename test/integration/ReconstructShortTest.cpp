// Cross-package integration: a recording made by vicc_make_bag (vicc_tracking) is tracked by
// vicc_reconstruct (vicc_fusion) through its command line, and the outputs are checked
// against the simulator's ground truth.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cstdlib>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "vicc_tracking/tum_trajectory.hpp"

namespace {

const std::string kTool = VICC_RECONSTRUCT_BINARY;
const std::string kBag = VICC_SHORT_TEST_BAG;
const std::string kTruth = VICC_SHORT_TEST_GT;

int run(const std::string& arguments, const std::string& stderr_path) {
  const int status = std::system((kTool + " " + arguments + " 2> " + stderr_path).c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

std::string readFile(const std::string& path) {
  std::ifstream in(path);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

TEST(ReconstructShortTest, TracksTheSimulatedRecordingWithinTolerance) {
  const std::string dir = ::testing::TempDir();
  const std::string report_path = dir + "vicc_short_report.json";
  const std::string trajectory_path = dir + "vicc_short.tum";
  const std::string cloud_path = dir + "vicc_short.ply";
  ASSERT_EQ(run(kBag + " --levels 2 --frame-step 2 --gt " + kTruth + " --report " + report_path +
                    " --trajectory " + trajectory_path + " --cloud " + cloud_path + " --quiet",
                dir + "vicc_short.err"),
            0)
      << readFile(dir + "vicc_short.err");
  const nlohmann::json report = nlohmann::json::parse(readFile(report_path));
  EXPECT_EQ(report["settings"]["init"], "ekf");
  EXPECT_EQ(report["settings"]["frame_step"], 2);
  EXPECT_EQ(report["frames"]["lost"], 0);
  const int tracked = report["frames"]["tracked"];
  EXPECT_GT(tracked, 20);
  EXPECT_GT(report["frames"]["initializing"].get<int>(), 0) << "the still phase comes first";
  EXPECT_LT(report["ground_truth_error"]["max_position_m"].get<double>(), 0.02);
  EXPECT_LT(report["ground_truth_error"]["max_rotation_deg"].get<double>(), 2.0);
  EXPECT_GT(report["icp_iterations"]["mean"].get<double>(), 1.0);
  EXPECT_LT(report["init_ratio"]["position"]["mean"].get<double>(), 1.0)
      << "the EKF guess should beat the identity guess";
  EXPECT_GT(report["cloud_points"].get<int>(), 1000);
  EXPECT_EQ(vicc_tracking::readTumTrajectory(trajectory_path).size(), static_cast<size_t>(tracked));
}

TEST(ReconstructShortTest, ClearErrorsForBadInvocations) {
  const std::string err = ::testing::TempDir() + "vicc_bad.err";
  EXPECT_EQ(run("--levels 2", err), 2);
  EXPECT_NE(readFile(err).find("no bag given"), std::string::npos);
  EXPECT_EQ(run("/nonexistent.bag", err), 1);
  EXPECT_NE(readFile(err).find("cannot read bag"), std::string::npos);
  EXPECT_EQ(run(kBag + " --depth-topic /imu/data_raw", err), 1);
  EXPECT_NE(readFile(err).find("expected sensor_msgs/Image"), std::string::npos) << readFile(err);
}

}  // namespace
