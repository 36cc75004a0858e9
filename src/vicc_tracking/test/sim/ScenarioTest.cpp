#include <gtest/gtest.h>

#include <fstream>

#include "vicc_tracking/sim/rig_simulator.hpp"

using namespace vicc_tracking::sim;

namespace {

std::string errorOf(const std::string& yaml) {
  const std::string path = ::testing::TempDir() + "vicc_bad_scenario.yaml";
  std::ofstream(path) << yaml;
  try {
    loadScenario(path);
  } catch (const std::runtime_error& error) {
    return error.what();
  }
  return "";
}

const char* kMinimal =
    "name: t\n"
    "scene:\n  - {type: box, center: [0, 0, -0.02], size: [1, 1, 0.04]}\n"
    "trajectory:\n  target: [0, 0, 0]\n"
    "  keyframes:\n    - [0, 0, 30, 0.6, 0]\n    - [1, 20, 30, 0.6, 0]\n    - [2, 0, 30, 0.6, 0]\n";

TEST(ScenarioTest, AllShippedScenariosLoad) {
  const auto names = availableScenarios();
  for (const char* expected : {"hen", "hen_slow", "hen_duplo", "office", "short_test"}) {
    EXPECT_NE(std::find(names.begin(), names.end(), expected), names.end()) << expected;
  }
  for (const auto& name : names) {
    const Scenario scenario = loadScenario(name);
    EXPECT_EQ(scenario.name, name);
    EXPECT_EQ(scenario.camera.width, 224);
    // A real rotation between IMU and optical axes.
    EXPECT_GT(Eigen::AngleAxisd(scenario.imu_to_camera.linear()).angle(), 1.0);
  }
}

TEST(ScenarioTest, MinimalFileUsesPicoFlexxDefaults) {
  const std::string path = ::testing::TempDir() + "vicc_min_scenario.yaml";
  std::ofstream(path) << kMinimal;
  const Scenario scenario = loadScenario(path);
  EXPECT_EQ(scenario.camera.height, 171);
  EXPECT_DOUBLE_EQ(scenario.depth_rate_hz, 15.0);
  EXPECT_DOUBLE_EQ(scenario.imu.rate_hz, 200.0);
  EXPECT_DOUBLE_EQ(scenario.scene.front().albedo, 1.0);
}

TEST(ScenarioTest, AlbedoAndAmplitudeNoiseAreReadAndChecked) {
  std::string with_albedo = kMinimal;
  with_albedo.replace(with_albedo.find("size: [1, 1, 0.04]}"), 19,
                      "size: [1, 1, 0.04], albedo: 0.3}");
  const std::string path = ::testing::TempDir() + "vicc_albedo_scenario.yaml";
  std::ofstream(path) << with_albedo << "tof: {amplitude_scale: 500, amplitude_sigma: 2}\n";
  const Scenario scenario = loadScenario(path);
  EXPECT_DOUBLE_EQ(scenario.scene.front().albedo, 0.3);
  EXPECT_DOUBLE_EQ(scenario.tof.amplitude_scale, 500.0);
  EXPECT_DOUBLE_EQ(scenario.tof.amplitude_sigma, 2.0);
  std::string negative = with_albedo;
  negative.replace(negative.find("albedo: 0.3"), 11, "albedo: -1");
  EXPECT_NE(errorOf(negative).find("scene[0]/albedo"), std::string::npos) << errorOf(negative);
  const std::string bad_scale = std::string(kMinimal) + "tof: {amplitude_scale: 0}\n";
  EXPECT_NE(errorOf(bad_scale).find("amplitude_scale"), std::string::npos) << errorOf(bad_scale);
}

TEST(ScenarioTest, ErrorsNameTheFileAndKey) {
  EXPECT_NE(errorOf("scene: []\n").find("name: missing"), std::string::npos);
  std::string bad_rate = std::string(kMinimal) + "imu: {rate_hz: -5}\n";
  EXPECT_NE(errorOf(bad_rate).find("rate_hz"), std::string::npos) << errorOf(bad_rate);
  std::string bad_type = kMinimal;
  bad_type.replace(bad_type.find("type: box"), 9, "type: cone");
  EXPECT_NE(errorOf(bad_type).find("scene[0]/type"), std::string::npos);
  EXPECT_NE(errorOf("name: [unclosed\n").find("not valid YAML"), std::string::npos);
  try {
    loadScenario("no_such_scenario");
    FAIL();
  } catch (const std::runtime_error& error) {
    EXPECT_NE(std::string(error.what()).find("available: hen"), std::string::npos) << error.what();
  }
}

}  // namespace
