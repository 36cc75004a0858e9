// The dynamic_reconfigure side of the tracker's tuning: the .cfg defaults are the config
// structs' defaults, the table-driven conversions carry every field both ways and keep what
// the .cfg does not cover, a .cfg parameter the table lacks or types differently is named, and
// a refused request is described by the values it asked for.
#include <gtest/gtest.h>

#include <functional>
#include <stdexcept>
#include <string>
#include <type_traits>

#include "vicc_tracking/ros/tracker_reconfigure.hpp"

using namespace vicc_tracking;

namespace {

/// IcpConfig's table without min_inliers, as if the .cfg had a key the table lost.
struct IcpWithoutMinInliers {
  IcpConfig icp;
};
template <typename Config, typename Visitor>
std::enable_if_t<std::is_same_v<std::remove_const_t<Config>, IcpWithoutMinInliers>> visitParameters(
    Config& config, Visitor& visit) {
  visit("max_correspondence_distance", config.icp.max_correspondence_distance);
  visit("max_normal_angle_deg", config.icp.max_normal_angle_deg);
  visit("convergence_translation", config.icp.convergence_translation);
  visit("convergence_rotation_deg", config.icp.convergence_rotation_deg);
  visit("min_inlier_ratio", config.icp.min_inlier_ratio);
  visit("max_condition_number", config.icp.max_condition_number);
  visit("max_jump_translation", config.icp.max_jump_translation);
  visit("max_jump_rotation_deg", config.icp.max_jump_rotation_deg);
}

/// A table whose max_jump_translation is an integer, the .cfg's a double.
struct IcpWithIntegerJump {
  IcpConfig icp;
  int max_jump_translation = 1;
};
template <typename Config, typename Visitor>
std::enable_if_t<std::is_same_v<std::remove_const_t<Config>, IcpWithIntegerJump>> visitParameters(
    Config& config, Visitor& visit) {
  visitParameters(config.icp, visit);
  visit("max_jump_translation", config.max_jump_translation);
}

std::string logicErrorOf(const std::function<void()>& action) {
  try {
    action();
  } catch (const std::logic_error& error) {
    return error.what();
  }
  return "";
}

TEST(TrackerReconfigureTest, CfgDefaultsAreTheConfigDefaults) {
  const IcpTuningConfig icp_defaults = IcpTuningConfig::__getDefault__();
  const IcpConfig icp = fromTuning(icp_defaults, IcpConfig{});
  const IcpConfig expected_icp;
  EXPECT_EQ(icp.max_correspondence_distance, expected_icp.max_correspondence_distance);
  EXPECT_EQ(icp.max_normal_angle_deg, expected_icp.max_normal_angle_deg);
  EXPECT_EQ(icp.convergence_translation, expected_icp.convergence_translation);
  EXPECT_EQ(icp.convergence_rotation_deg, expected_icp.convergence_rotation_deg);
  EXPECT_EQ(icp.min_inliers, expected_icp.min_inliers);
  EXPECT_EQ(icp.min_inlier_ratio, expected_icp.min_inlier_ratio);
  EXPECT_EQ(icp.max_condition_number, expected_icp.max_condition_number);
  EXPECT_EQ(icp.max_jump_translation, expected_icp.max_jump_translation);
  EXPECT_EQ(icp.max_jump_rotation_deg, expected_icp.max_jump_rotation_deg);

  const EkfConfig ekf = fromTuning(EkfTuningConfig::__getDefault__(), EkfConfig{});
  const EkfConfig expected_ekf;
  EXPECT_EQ(ekf.process_noise_rotation, expected_ekf.process_noise_rotation);
  EXPECT_EQ(ekf.process_noise_velocity, expected_ekf.process_noise_velocity);
  EXPECT_EQ(ekf.process_noise_position, expected_ekf.process_noise_position);
  EXPECT_EQ(ekf.process_noise_base, expected_ekf.process_noise_base);
  EXPECT_EQ(ekf.measurement_noise_rotation, expected_ekf.measurement_noise_rotation);
  EXPECT_EQ(ekf.measurement_noise_velocity, expected_ekf.measurement_noise_velocity);
  EXPECT_EQ(ekf.measurement_noise_position, expected_ekf.measurement_noise_position);
  EXPECT_EQ(ekf.measurement_noise_base, expected_ekf.measurement_noise_base);
  EXPECT_DOUBLE_EQ(ekf.measurement_noise_reference_interval,
                   expected_ekf.measurement_noise_reference_interval);
  EXPECT_EQ(ekf.measurement_noise_interval_exponent,
            expected_ekf.measurement_noise_interval_exponent);
  EXPECT_EQ(ekf.initial_covariance, expected_ekf.initial_covariance);
  EXPECT_EQ(ekf.imu_aided_virtual_velocity, expected_ekf.imu_aided_virtual_velocity);
}

TEST(TrackerReconfigureTest, ConversionsCarryEveryFieldAndKeepTheRest) {
  IcpConfig icp;
  icp.max_correspondence_distance = 0.07;
  icp.max_normal_angle_deg = 35.0;
  icp.convergence_translation = 2e-4;
  icp.convergence_rotation_deg = 0.02;
  icp.min_inliers = 321;
  icp.min_inlier_ratio = 0.25;
  icp.max_condition_number = 2e5;
  icp.max_jump_translation = 0.2;
  icp.max_jump_rotation_deg = 25.0;
  IcpConfig base;
  base.iterations_per_level = {7, 3};
  const IcpConfig icp_back = fromTuning(toTuning<IcpTuningConfig>(icp), base);
  EXPECT_EQ(icp_back.max_correspondence_distance, 0.07);
  EXPECT_EQ(icp_back.max_normal_angle_deg, 35.0);
  EXPECT_EQ(icp_back.convergence_translation, 2e-4);
  EXPECT_EQ(icp_back.convergence_rotation_deg, 0.02);
  EXPECT_EQ(icp_back.min_inliers, 321);
  EXPECT_EQ(icp_back.min_inlier_ratio, 0.25);
  EXPECT_EQ(icp_back.max_condition_number, 2e5);
  EXPECT_EQ(icp_back.max_jump_translation, 0.2);
  EXPECT_EQ(icp_back.max_jump_rotation_deg, 25.0);
  EXPECT_EQ(icp_back.iterations_per_level, (std::vector<int>{7, 3}));

  EkfConfig ekf = EkfConfig::thesisNoise();
  ekf.measurement_noise_interval_exponent = 2.5;
  ekf.imu_aided_virtual_velocity = false;
  EkfConfig ekf_base;
  ekf_base.imu_noise_file = "imu.yaml";
  const EkfConfig ekf_back = fromTuning(toTuning<EkfTuningConfig>(ekf), ekf_base);
  EXPECT_EQ(ekf_back.process_noise_rotation, ekf.process_noise_rotation);
  EXPECT_EQ(ekf_back.process_noise_velocity, ekf.process_noise_velocity);
  EXPECT_EQ(ekf_back.process_noise_position, ekf.process_noise_position);
  EXPECT_EQ(ekf_back.process_noise_base, ekf.process_noise_base);
  EXPECT_EQ(ekf_back.measurement_noise_rotation, ekf.measurement_noise_rotation);
  EXPECT_EQ(ekf_back.measurement_noise_velocity, ekf.measurement_noise_velocity);
  EXPECT_EQ(ekf_back.measurement_noise_position, ekf.measurement_noise_position);
  EXPECT_EQ(ekf_back.measurement_noise_base, ekf.measurement_noise_base);
  EXPECT_EQ(ekf_back.measurement_noise_reference_interval,
            ekf.measurement_noise_reference_interval);
  EXPECT_EQ(ekf_back.measurement_noise_interval_exponent, 2.5);
  EXPECT_EQ(ekf_back.initial_covariance, ekf.initial_covariance);
  EXPECT_FALSE(ekf_back.imu_aided_virtual_velocity);
  EXPECT_EQ(ekf_back.imu_noise_file, "imu.yaml");
}

TEST(TrackerReconfigureTest, ACfgParameterOutsideTheTableIsNamed) {
  const std::string missing =
      logicErrorOf([] { toTuning<IcpTuningConfig>(IcpWithoutMinInliers{}); });
  EXPECT_NE(missing.find("'min_inliers' is no key"), std::string::npos) << missing;
  const std::string mistyped =
      logicErrorOf([] { toTuning<IcpTuningConfig>(IcpWithIntegerJump{}); });
  EXPECT_NE(mistyped.find("'max_jump_translation' is double_t in the .cfg but int"),
            std::string::npos)
      << mistyped;
  const std::string reading =
      logicErrorOf([] { fromTuning(IcpTuningConfig::__getDefault__(), IcpWithIntegerJump{}); });
  EXPECT_NE(reading.find("max_jump_translation"), std::string::npos) << reading;
}

TEST(TrackerReconfigureTest, DescribesTheRequestedChangesOnly) {
  IcpConfig icp;
  EkfConfig ekf;
  dynamic_reconfigure::Config current, request;
  toTuning<IcpTuningConfig>(icp).__toMessage__(current);
  EXPECT_EQ(describeChanges(current, current), "");
  icp.min_inliers = 3;
  icp.max_normal_angle_deg = 120.0;
  toTuning<IcpTuningConfig>(icp).__toMessage__(request);
  EXPECT_EQ(describeChanges(request, current), "max_normal_angle_deg=120, min_inliers=3");

  toTuning<EkfTuningConfig>(ekf).__toMessage__(current);
  ekf.imu_aided_virtual_velocity = false;
  toTuning<EkfTuningConfig>(ekf).__toMessage__(request);
  EXPECT_EQ(describeChanges(request, current), "imu_aided_virtual_velocity=false");
}

}  // namespace
