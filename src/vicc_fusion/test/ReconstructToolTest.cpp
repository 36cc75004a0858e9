#include <gtest/gtest.h>

#include <sstream>

#include "reconstruct_options.hpp"
#include "reconstruct_report.hpp"

using namespace vicc_fusion;

namespace {

bool parse(std::vector<const char*> args, ReconstructOptions& options) {
  args.insert(args.begin(), "vicc_reconstruct");
  std::ostringstream out;
  return parseReconstructOptions(static_cast<int>(args.size()), args.data(), options, out);
}

TEST(ReconstructToolTest, ParsesTheDocumentedOptions) {
  ReconstructOptions options;
  ASSERT_TRUE(parse({"rec.bag", "--init", "identity", "--levels", "1", "--frame-step", "4",
                     "--trajectory", "t.tum", "--report", "r.json", "--depth-topic", "/d"},
                    options));
  EXPECT_EQ(options.bag_path, "rec.bag");
  EXPECT_EQ(options.init, vicc_tracking::InitStrategyType::kIdentity);
  EXPECT_EQ(options.levels, 1);
  EXPECT_EQ(options.frame_step, 4);
  EXPECT_EQ(options.trajectory_path, "t.tum");
  EXPECT_EQ(options.report_path, "r.json");
  EXPECT_EQ(options.depth_topic, "/d");
  EXPECT_TRUE(options.imu_topic.empty());
}

TEST(ReconstructToolTest, RejectsBadArgumentsWithAMessage) {
  ReconstructOptions options;
  EXPECT_THROW(parse({}, options), std::invalid_argument);
  EXPECT_THROW(parse({"a.bag", "--levels", "4"}, options), std::invalid_argument);
  EXPECT_THROW(parse({"a.bag", "--frame-step", "0"}, options), std::invalid_argument);
  EXPECT_THROW(parse({"a.bag", "--frame-step", "2x"}, options), std::invalid_argument);
  EXPECT_THROW(parse({"a.bag", "--init", "magic"}, options), std::invalid_argument);
  EXPECT_THROW(parse({"a.bag", "--report"}, options), std::invalid_argument);
  EXPECT_THROW(parse({"a.bag", "--bogus"}, options), std::invalid_argument);
  EXPECT_FALSE(parse({"--help"}, options));
}

TEST(ReconstructToolTest, ReportCarriesTheThesisStatistics) {
  vicc_tracking::TrackingStatistics statistics;
  vicc_tracking::FrameReport report;
  report.state = vicc_tracking::TrackingState::kOk;
  report.icp.iterations = 6;
  report.init_error_position = 0.002;
  report.identity_error_position = 0.01;
  report.init_error_rotation_deg = 0.5;
  report.identity_error_rotation_deg = 2.0;
  report.timings.total_ms = 2.0;
  statistics.add(report);
  report.icp.iterations = 8;
  report.camera_pose.translation().x() = 0.01;
  report.timings.total_ms = 4.0;
  statistics.add(report);
  report.state = vicc_tracking::TrackingState::kLost;
  statistics.add(report);

  ReconstructOptions options;
  options.bag_path = "x.bag";
  ReconstructRun run;
  run.wall_time_s = 0.5;
  const nlohmann::json json = makeReport(options, run, statistics);
  EXPECT_EQ(json["frames"]["tracked"], 2);
  EXPECT_EQ(json["frames"]["lost"], 1);
  EXPECT_DOUBLE_EQ(json["icp_iterations"]["mean"].get<double>(), 7.0);
  EXPECT_DOUBLE_EQ(json["icp_iterations"]["std"].get<double>(), 1.0);
  EXPECT_DOUBLE_EQ(json["init_ratio"]["position"]["mean"].get<double>(), 0.2);
  EXPECT_DOUBLE_EQ(json["init_ratio"]["rotation"]["mean"].get<double>(), 0.25);
  EXPECT_DOUBLE_EQ(json["median_ms"]["tracking_total"].get<double>(), 4.0);  // of 2, 4, 4
  EXPECT_NEAR(json["first_to_last_pose"]["position_m"].get<double>(), 0.01, 1e-12);
  EXPECT_DOUBLE_EQ(json["frames_per_second"].get<double>(), 6.0);
}

}  // namespace
