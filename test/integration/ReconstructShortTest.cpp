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
const std::string kSurface = VICC_SHORT_TEST_SURFACE;

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
  // Frame-to-model: the tracker aligned most frames to the fused model.
  EXPECT_EQ(report["settings"]["tracking"], "frame_to_model");
  EXPECT_GT(report["fusion"]["frames_aligned_to_model"].get<int>(), tracked / 2);
  EXPECT_EQ(report["surfels"]["stable"].get<int>(), report["cloud_points"].get<int>());
  EXPECT_GT(report["fusion"]["median_fusion_ms"].get<double>(), 0.0);
}

TEST(ReconstructShortTest, ModelLiesOnTheTrueSurface) {
  const std::string dir = ::testing::TempDir();
  const std::string report_path = dir + "vicc_short_model.json";
  const std::string mesh_path = dir + "vicc_short_mesh.ply";
  ASSERT_EQ(run(kBag + " --gt " + kTruth + " --truth-surface " + kSurface + " --mesh " + mesh_path +
                    " --report " + report_path + " --quiet",
                dir + "vicc_short_model.err"),
            0)
      << readFile(dir + "vicc_short_model.err");
  const nlohmann::json report = nlohmann::json::parse(readFile(report_path));
  const nlohmann::json& accuracy = report["model_accuracy"];
  EXPECT_LT(accuracy["mean_distance_m"].get<double>(), 0.003);
  EXPECT_LT(accuracy["p95_distance_m"].get<double>(), 0.01);
  EXPECT_GT(accuracy["completeness"].get<double>(), 0.6);
  EXPECT_GT(report["mesh_triangles"].get<int>(), 1000);
  EXPECT_NE(readFile(mesh_path).find("element face"), std::string::npos);
}

TEST(ReconstructShortTest, FrameToFrameAndTrackingOnlyModes) {
  const std::string dir = ::testing::TempDir();
  const std::string report_path = dir + "vicc_short_f2f.json";
  ASSERT_EQ(run(kBag + " --frame-to-frame --report " + report_path + " --quiet",
                dir + "vicc_short_f2f.err"),
            0);
  nlohmann::json report = nlohmann::json::parse(readFile(report_path));
  EXPECT_EQ(report["settings"]["tracking"], "frame_to_frame");
  EXPECT_EQ(report["fusion"]["frames_aligned_to_model"].get<int>(), 0);
  EXPECT_GT(report["surfels"]["stable"].get<int>(), 1000) << "fusion still runs";
  ASSERT_EQ(
      run(kBag + " --no-fusion --report " + report_path + " --quiet", dir + "vicc_short_f2f.err"),
      0);
  report = nlohmann::json::parse(readFile(report_path));
  EXPECT_FALSE(report.contains("surfels"));
  EXPECT_EQ(run(kBag + " --no-fusion --cloud x.ply", dir + "vicc_short_f2f.err"), 2);
  EXPECT_NE(readFile(dir + "vicc_short_f2f.err").find("drop --no-fusion"), std::string::npos);
  EXPECT_EQ(run(kBag + " --truth-surface " + kSurface, dir + "vicc_short_f2f.err"), 2);
  EXPECT_NE(readFile(dir + "vicc_short_f2f.err").find("needs --gt"), std::string::npos);
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
