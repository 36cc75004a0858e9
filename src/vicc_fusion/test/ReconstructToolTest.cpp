#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include <unistd.h>

#include "reconstruct_options.hpp"
#include "reconstruct_report.hpp"
#include "vicc_common/yaml_parameters.hpp"
#include "vicc_fusion/fusion_config_yaml.hpp"
#include "vicc_fusion/fusion_parameters.hpp"
#include "vicc_paths/package_share.hpp"
#include "vicc_tracking/tracker_config_yaml.hpp"

// This package's own config/ (fusion.yaml); vicc_tracking's is found through vicc_paths.
#if !defined(VICC_FUSION_CONFIG_DIR)
#error "VICC_FUSION_CONFIG_DIR must be defined by the build"
#endif

using namespace vicc_fusion;
using vicc_common::toYamlParameters;

namespace {

/// vicc_tracking's config/, found as an installed consumer finds it (share/ next to this test).
std::string trackerConfigDir() {
  static const int anchor = 0;
  return vicc_paths::packageDataPath("vicc_tracking", "config", &anchor).string();
}

bool parse(std::vector<const char*> args, ReconstructOptions& options) {
  args.insert(args.begin(), "vicc_reconstruct");
  std::ostringstream out;
  return parseReconstructOptions(static_cast<int>(args.size()), args.data(), options, out);
}

/// A YAML file in the test's temporary directory, removed at the end of the test.
class TempYaml {
 public:
  explicit TempYaml(const std::string& text)
      : path_(std::filesystem::temp_directory_path() /
              ("vicc_reconstruct_test_" + std::to_string(::getpid()) + "_" +
               std::to_string(counter_++) + ".yaml")) {
    std::ofstream(path_) << text;
  }
  ~TempYaml() { std::filesystem::remove(path_); }
  std::string path() const { return path_.string(); }

 private:
  static inline int counter_ = 0;
  std::filesystem::path path_;
};

/// The message parseReconstructOptions() throws for `--config` with this YAML text.
std::string configError(const std::string& text) {
  const TempYaml file(text);
  ReconstructOptions options;
  try {
    parse({"a.bag", "--config", file.path().c_str()}, options);
  } catch (const std::invalid_argument& error) {
    return error.what();
  }
  return "(no error)";
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

TEST(ReconstructToolTest, IntensityTopicDefaultsToAutomaticAndNoneTurnsItOff) {
  ReconstructOptions automatic;
  ASSERT_TRUE(parse({"rec.bag"}, automatic));
  EXPECT_TRUE(automatic.intensity_topic.empty());
  ReconstructOptions named;
  ASSERT_TRUE(parse({"rec.bag", "--intensity-topic", "/pico_flexx/image_mono8"}, named));
  EXPECT_EQ(named.intensity_topic, "/pico_flexx/image_mono8");
  ReconstructOptions off;
  ASSERT_TRUE(parse({"rec.bag", "--intensity-topic", "none"}, off));
  EXPECT_EQ(off.intensity_topic, "none");
  ReconstructOptions tracking_only;
  EXPECT_TRUE(parse({"rec.bag", "--no-fusion", "--intensity-topic", "none"}, tracking_only));
  ReconstructOptions bad;
  EXPECT_THROW(parse({"rec.bag", "--intensity-topic"}, bad), std::invalid_argument);
  EXPECT_THROW(parse({"rec.bag", "--intensity-topic", ""}, bad), std::invalid_argument);
  EXPECT_THROW(parse({"rec.bag", "--no-fusion", "--intensity-topic", "/gray"}, bad),
               std::invalid_argument);
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

TEST(ReconstructToolTest, ConfigFileRoundTripsNonDefaultValues) {
  vicc_tracking::TrackerParameterSet written;
  written.tracker.init_strategy = vicc_tracking::InitStrategyType::kImu;
  written.tracker.preprocessing.pyramid_levels = 2;
  written.tracker.preprocessing.bilateral_filter = false;
  written.tracker.icp.iterations_per_level = {7, 3};
  written.tracker.ekf.process_noise_position = 2.5e-7;
  written.tracker.ekf.measurement_noise_rotation = 1.0 / 3.0;  // needs all 17 digits
  written.tracker.synchronizer.max_gap = 0.25;
  written.node.map_frame = "world";
  const std::string yaml = vicc_tracking::toYaml(written);
  const TempYaml file(yaml);

  ReconstructOptions options;
  ASSERT_TRUE(parse({"rec.bag", "--config", file.path().c_str()}, options));
  EXPECT_EQ(options.config_paths, std::vector<std::string>{file.path()});
  EXPECT_EQ(options.init, vicc_tracking::InitStrategyType::kImu);
  EXPECT_EQ(options.levels, 2);
  EXPECT_FALSE(options.tracker.preprocessing.bilateral_filter);
  EXPECT_EQ(options.tracker.icp.iterations_per_level, (std::vector<int>{7, 3}));
  EXPECT_EQ(options.tracker.ekf.process_noise_position, 2.5e-7);
  EXPECT_EQ(options.tracker.ekf.measurement_noise_rotation, 1.0 / 3.0);
  EXPECT_EQ(options.tracker.ekf.process_noise_velocity,
            vicc_tracking::EkfConfig{}.process_noise_velocity);
  EXPECT_EQ(options.tracker.synchronizer.max_gap, 0.25);
  // Every parameter comes back: the read set writes the same text.
  EXPECT_EQ(vicc_tracking::toYaml(vicc_tracking::loadTrackerParameters(file.path())), yaml);

  // --init and --levels on the command line override the file.
  options = ReconstructOptions{};
  ASSERT_TRUE(parse({"rec.bag", "--config", file.path().c_str(), "--init", "ekf", "--levels", "1"},
                    options));
  EXPECT_EQ(options.init, vicc_tracking::InitStrategyType::kEkf);
  EXPECT_EQ(options.tracker.init_strategy, vicc_tracking::InitStrategyType::kEkf);
  EXPECT_EQ(options.tracker.preprocessing.pyramid_levels, 1);
  EXPECT_EQ(options.tracker.ekf.process_noise_position, 2.5e-7);

  // The report records the parameters that were used.
  const nlohmann::json json =
      makeReport(options, ReconstructRun{}, vicc_tracking::TrackingStatistics{});
  EXPECT_EQ(json["settings"]["config"], file.path());
  EXPECT_EQ(json["tracker_parameters"]["ekf"]["process_noise_position"].get<double>(), 2.5e-7);
  EXPECT_EQ(json["tracker_parameters"]["init_strategy"], "ekf");
}

TEST(ReconstructToolTest, ConfigFilesOfThePackageLoad) {
  // The node's file documents the defaults: reading it must change nothing.
  const std::string directory = trackerConfigDir();
  const auto defaults = vicc_tracking::loadTrackerParameters(directory + "/tracker.yaml");
  EXPECT_EQ(vicc_tracking::toYaml(defaults), vicc_tracking::toYaml({}));
  ReconstructOptions options;
  EXPECT_TRUE(parse({"a.bag", "--config", (directory + "/tracker.yaml").c_str()}, options));
  // The thesis's noise values (5.4.4) are a named file, no longer the defaults.
  options = ReconstructOptions{};
  EXPECT_TRUE(parse({"a.bag", "--config", (directory + "/tracker_thesis.yaml").c_str()}, options));
  const vicc_tracking::EkfConfig& thesis = options.tracker.ekf;
  EXPECT_EQ(thesis.process_noise_rotation, 1e-5);
  EXPECT_EQ(thesis.process_noise_velocity, 1e-2);
  EXPECT_EQ(thesis.process_noise_position, 1e-1);
  EXPECT_EQ(thesis.process_noise_base, 1e-5);
  EXPECT_EQ(thesis.measurement_noise_rotation, 1e-3);
  EXPECT_EQ(thesis.measurement_noise_velocity, 1e-6);
  EXPECT_EQ(thesis.measurement_noise_position, 1e-5);
  EXPECT_EQ(thesis.measurement_noise_base, 1e-13);
  EXPECT_EQ(thesis.initial_covariance, 1e-4);
  EXPECT_EQ(thesis.measurement_noise_interval_exponent, 0.0);  // one fixed R
  // The defaults are the IMU-derived values of tracker.yaml.
  const vicc_tracking::EkfConfig& ekf_defaults = defaults.tracker.ekf;
  EXPECT_EQ(ekf_defaults.process_noise_velocity, 1e-5);
  EXPECT_EQ(ekf_defaults.measurement_noise_position, 2.5e-3);
  EXPECT_EQ(ekf_defaults.initial_covariance, 1e-7);
  EXPECT_EQ(ekf_defaults.measurement_noise_interval_exponent, 3.0);
  EXPECT_EQ(ekf_defaults.imu_noise_file, "");
}

TEST(ReconstructToolTest, EveryShippedParameterFileLoads) {
  // Every node parameter file of vicc_tracking/config and vicc_fusion/config, and every IMU
  // noise file: a file added later is covered without touching this test.
  std::vector<std::string> parameter_files = {std::string(VICC_FUSION_CONFIG_DIR) + "/fusion.yaml"};
  const std::filesystem::path tracker_dir = trackerConfigDir();
  for (const auto& entry : std::filesystem::directory_iterator(tracker_dir)) {
    if (entry.path().extension() == ".yaml") parameter_files.push_back(entry.path().string());
  }
  ASSERT_GE(parameter_files.size(), 4u);  // fusion, tracker, tracker_thesis, imu_trusting
  for (const std::string& file : parameter_files) {
    FusionParameterSet parameters;
    EXPECT_NO_THROW(loadFusionParameters(file, parameters)) << file;
    ReconstructOptions options;
    EXPECT_NO_THROW(parse({"a.bag", "--config", file.c_str()}, options)) << file;
  }
  int imu_files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(tracker_dir / "imu")) {
    EXPECT_NO_THROW(vicc_tracking::loadImuNoise(entry.path().string())) << entry.path();
    ++imu_files;
  }
  EXPECT_GE(imu_files, 2);
}

TEST(ReconstructToolTest, ImuNoiseFileDerivesTheProcessNoise) {
  const std::string file = trackerConfigDir() + "/imu/bosch_bmi270.yaml";
  ReconstructOptions options;
  ASSERT_TRUE(parse({"a.bag", "--imu-noise", file.c_str()}, options));
  EXPECT_EQ(options.tracker.ekf.imu_noise_file, file);
  const vicc_tracking::EkfConfig defaults;
  EXPECT_NE(options.tracker.ekf.process_noise_velocity, defaults.process_noise_velocity);
  EXPECT_NE(options.tracker.ekf.process_noise_rotation, defaults.process_noise_rotation);
  EXPECT_EQ(options.tracker.ekf.measurement_noise_velocity, defaults.measurement_noise_velocity);
  const nlohmann::json json =
      makeReport(options, ReconstructRun{}, vicc_tracking::TrackingStatistics{});
  EXPECT_EQ(json["tracker_parameters"]["ekf"]["imu_noise_file"], file);
  options = ReconstructOptions{};
  EXPECT_THROW(parse({"a.bag", "--imu-noise", "/nonexistent/imu.yaml"}, options),
               std::invalid_argument);
  EXPECT_THROW(parse({"a.bag", "--imu-noise"}, options), std::invalid_argument);
}

TEST(ReconstructToolTest, ConfigFileRejectsUnknownKeysNamingThem) {
  const std::string nested = configError("ekf:\n  process_noise_rotaton: 1.0e-3\n");
  EXPECT_NE(nested.find("ekf/process_noise_rotaton: unknown key"), std::string::npos) << nested;
  EXPECT_NE(nested.find("process_noise_rotation"), std::string::npos) << nested;  // the known
  const std::string top = configError("init_stratgy: imu\n");
  EXPECT_NE(top.find("init_stratgy: unknown key"), std::string::npos) << top;
  // The fusion node's sections are known (fusion.yaml loads), their keys are checked too.
  const std::string section = configError("fusion:\n  supersampeling: 2\n");
  EXPECT_NE(section.find("fusion/supersampeling: unknown key"), std::string::npos) << section;
  const std::string prediction = configError("prediction:\n  stable_confidence: 2\n");
  EXPECT_NE(prediction.find("prediction/stable_confidence: unknown key"), std::string::npos)
      << prediction;  // the prediction takes fusion/stable_confidence
}

TEST(ReconstructToolTest, ConfigReadsTheFusionNodesFileToo) {
  const std::string fusion_yaml = std::string(VICC_FUSION_CONFIG_DIR) + "/fusion.yaml";
  ReconstructOptions defaults;
  ASSERT_TRUE(parse({"a.bag", "--config", fusion_yaml.c_str()}, defaults));
  EXPECT_EQ(toYamlParameters(defaults.model), toYamlParameters(FrameToModelConfig{}))
      << "fusion.yaml documents the defaults";

  const TempYaml fusion_file(
      "frame_to_model: false\nmin_prediction_coverage: 0.75\ntrack: false\n"
      "fusion:\n  supersampling: 2\n  stable_confidence: 5.0\n"
      "prediction:\n  splat_radius_scale: 1.3\n");
  const TempYaml tracker_file("init_strategy: identity\npreprocessing:\n  pyramid_levels: 2\n");
  ReconstructOptions options;
  ASSERT_TRUE(parse(
      {"a.bag", "--config", tracker_file.path().c_str(), "--config", fusion_file.path().c_str()},
      options));
  EXPECT_EQ(options.init, vicc_tracking::InitStrategyType::kIdentity);
  EXPECT_EQ(options.levels, 2);
  EXPECT_FALSE(options.frame_to_model);
  EXPECT_EQ(options.model.min_prediction_coverage, 0.75);
  EXPECT_EQ(options.model.fusion.supersampling, 2);
  EXPECT_EQ(options.model.fusion.stable_confidence, 5.0);
  EXPECT_EQ(options.model.prediction.splat_radius_scale, 1.3);
  const nlohmann::json json =
      makeReport(options, ReconstructRun{}, vicc_tracking::TrackingStatistics{});
  EXPECT_EQ(json["fusion_parameters"]["fusion"]["supersampling"], 2);
  EXPECT_EQ(json["fusion_parameters"]["frame_to_model"], false);
  EXPECT_EQ(json["settings"]["config_files"].size(), 2u);

  // A later file overrides an earlier one; keys it leaves out stay as the earlier set them.
  const TempYaml later("fusion:\n  supersampling: 3\n");
  options = ReconstructOptions{};
  ASSERT_TRUE(
      parse({"a.bag", "--config", fusion_file.path().c_str(), "--config", later.path().c_str()},
            options));
  EXPECT_EQ(options.model.fusion.supersampling, 3);
  EXPECT_EQ(options.model.fusion.stable_confidence, 5.0);

  // A value fusion's validate() rejects names the file and the section.
  const std::string invalid = configError("fusion:\n  supersampling: 9\n");
  EXPECT_NE(invalid.find(": fusion: surfel fusion: supersampling must be in 1..8"),
            std::string::npos)
      << invalid;
}

TEST(ReconstructToolTest, ConfigFileRejectsWrongTypesNamingTheKey) {
  const std::string text = configError("icp:\n  min_inliers: many\n");
  EXPECT_NE(text.find("icp/min_inliers: has the wrong type: expected an integer, got 'many'"),
            std::string::npos)
      << text;
  const std::string fraction = configError("preprocessing:\n  pyramid_levels: 2.5\n");
  EXPECT_NE(fraction.find("preprocessing/pyramid_levels: has the wrong type"), std::string::npos)
      << fraction;
  const std::string list = configError("icp:\n  iterations_per_level: 10\n");
  EXPECT_NE(list.find("icp/iterations_per_level: has the wrong type: expected a list"),
            std::string::npos)
      << list;
  const std::string flag = configError("ekf:\n  imu_aided_virtual_velocity: maybe\n");
  EXPECT_NE(flag.find("ekf/imu_aided_virtual_velocity: has the wrong type"), std::string::npos)
      << flag;
  const std::string section = configError("ekf: 1.0e-3\n");
  EXPECT_NE(section.find("ekf: must be a section"), std::string::npos) << section;
  const std::string strategy = configError("init_strategy: magic\n");
  EXPECT_NE(strategy.find("init_strategy: "), std::string::npos) << strategy;
  // Values of the right type that the config rejects name their section.
  const std::string invalid = configError("ekf:\n  process_noise_position: -1.0\n");
  EXPECT_NE(invalid.find(": ekf: "), std::string::npos) << invalid;
  EXPECT_NE(configError("a: [").find("not valid YAML"), std::string::npos);
  EXPECT_NE(configError("").find("(no error)"), std::string::npos);  // empty: all defaults
  ReconstructOptions options;
  EXPECT_THROW(parse({"a.bag", "--config", "/nonexistent/tracker.yaml"}, options),
               std::invalid_argument);
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
