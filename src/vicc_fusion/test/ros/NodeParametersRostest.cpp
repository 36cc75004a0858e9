#include <gtest/gtest.h>
#include <ros/ros.h>

#include "vicc_common/ros_parameters.hpp"
#include "vicc_common/yaml_parameters.hpp"
#include "vicc_fusion/fusion_config_yaml.hpp"
#include "vicc_fusion/ros/fusion_ros.hpp"
#include "vicc_tracking/ros/parameters.hpp"
#include "vicc_tracking/sim/driver_settings.hpp"

namespace vicc_fusion {
namespace {

using vicc_common::toYamlParameters;

ros::NodeHandle privateNamespace(const std::string& ns) { return ros::NodeHandle("~" + ns); }

std::string param(const std::string& name) {
  std::string value;
  EXPECT_TRUE(ros::NodeHandle("~").getParam(name, value)) << name;
  return value;
}

/// What the fusion node reads in `ns`: its own tables and the tracker's.
struct NodeRead {
  FusionRosSettings settings;
  FrameToModelConfig model;
  vicc_tracking::TrackerConfig tracker;
  std::set<std::string> names;
};

NodeRead readNode(const std::string& ns) {
  NodeRead read;
  const ros::NodeHandle nh = privateNamespace(ns);
  read.settings = readFusionRosSettings(nh, read.names);
  read.model = readFrameToModelConfig(nh, read.names);
  read.tracker = vicc_tracking::readTrackerConfig(nh, read.names);
  vicc_tracking::readTrackerNodeSettings(nh, read.names);
  return read;
}

std::string errorOf(const std::string& ns) {
  try {
    readNode(ns);
  } catch (const std::invalid_argument& error) {
    return error.what();
  }
  return "no error";
}

TEST(NodeParameters, ShippedFilesReadTheSameThroughRosAsThroughYaml) {
  const NodeRead read = readNode("shipped");
  FusionParameterSet from_yaml;
  loadFusionParameters(param("tracker_yaml"), from_yaml);
  loadFusionParameters(param("fusion_yaml"), from_yaml);
  EXPECT_EQ(toYamlParameters(read.model), toYamlParameters(from_yaml.model));
  EXPECT_EQ(toYamlParameters(read.settings), toYamlParameters(from_yaml.node));
  EXPECT_EQ(toYamlParameters(read.tracker), toYamlParameters(from_yaml.tracker.tracker));
  EXPECT_TRUE(vicc_common::unknownRosParameters(privateNamespace("shipped"), read.names).empty());
}

TEST(NodeParameters, ValuesOnTheServerReachEveryTable) {
  const NodeRead read = readNode("changed");
  EXPECT_FALSE(read.model.track_against_model);
  EXPECT_EQ(read.model.fusion.max_surfels, 5000);
  EXPECT_DOUBLE_EQ(read.model.prediction.splat_radius_scale, 1.25);  // never read before
  EXPECT_EQ(read.tracker.init_strategy, vicc_tracking::InitStrategyType::kConstantVelocity);
  EXPECT_EQ(read.tracker.icp.iterations_per_level, (std::vector<int>{6, 3}));
}

TEST(NodeParameters, WrongTypesAndInvalidValuesNameTheParameter) {
  const std::string ns = ros::NodeHandle("~").getNamespace();
  EXPECT_EQ(errorOf("wrong_type"), "parameter " + ns +
                                       "/wrong_type/fusion/max_surfels has the wrong type: "
                                       "expected an integer, got 'many'");
  EXPECT_EQ(errorOf("wrong_type_tracker"),
            "parameter " + ns +
                "/wrong_type_tracker/ekf/imu_aided_virtual_velocity has the wrong type: expected "
                "true or false, got 'yes'");
  EXPECT_EQ(errorOf("invalid"), "parameters under " + ns +
                                    "/invalid/fusion: surfel fusion: supersampling must be in "
                                    "1..8");
}

TEST(NodeParameters, TyposInTheNodesNamespaceAreNamed) {
  const NodeRead read = readNode("typo");
  const std::string ns = ros::NodeHandle("~").getNamespace();
  EXPECT_EQ(
      vicc_common::unknownRosParameters(privateNamespace("typo"), read.names),
      (std::vector<std::string>{ns + "/typo/fusion/supersampeling", ns + "/typo/publish_rat"}));
}

TEST(NodeParameters, SimulatedDriversReadTheirTable) {
  std::set<std::string> names;
  vicc_tracking::sim::DepthDriverSettings depth;
  vicc_common::readRosParameters(privateNamespace("driver"), depth, names);
  EXPECT_EQ(depth.driver.scenario, "short_test");
  EXPECT_TRUE(depth.driver.loop);
  EXPECT_FALSE(depth.publish_ground_truth);
  vicc_tracking::sim::DriverSettings imu;
  EXPECT_THROW(vicc_common::readRosParameters(privateNamespace("driver_bad"), imu, names),
               std::invalid_argument);  // a number is no scenario name
  try {
    vicc_common::readRosParameters(privateNamespace("driver_missing"), imu, names);
    FAIL() << "no error";
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find("scenario is required"), std::string::npos);
  }
}

}  // namespace
}  // namespace vicc_fusion

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "node_parameters_test");
  ros::NodeHandle nh;
  return RUN_ALL_TESTS();
}
