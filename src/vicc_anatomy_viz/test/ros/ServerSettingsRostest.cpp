#include <gtest/gtest.h>
#include <ros/ros.h>

#include "vicc_anatomy_viz/ros/patient_status_server.hpp"
#include "vicc_common/ros_parameters.hpp"

namespace vicc_anatomy_viz::ros_adapter {
namespace {

std::string privateName(const std::string& name) { return ros::NodeHandle("~").resolveName(name); }

std::string errorOf(const std::string& ns) {
  try {
    readServerSettings(ros::NodeHandle("~" + ns));
  } catch (const std::invalid_argument& error) {
    return error.what();
  }
  return "no error";
}

TEST(ServerSettings, ReadsEveryParameterIntoTheServiceConfig) {
  const PatientStatusServerSettings settings = readServerSettings(ros::NodeHandle("~good"));
  EXPECT_EQ(settings.patient, "0042");  // text stays text
  EXPECT_EQ(settings.date, "2020-01-02");
  const PatientStatusConfig config = settings.serviceConfig();
  EXPECT_EQ(config.store.path, "/tmp/x.db");
  EXPECT_EQ(config.store.busy_timeout_ms, 250);
  EXPECT_EQ(config.plausibility.max_future_seconds, 60);
  EXPECT_EQ(config.view_id, "neurological_status_sdh");
}

TEST(ServerSettings, KeysLeftOutTakeThePackagesFiles) {
  const PatientStatusServerSettings settings = readServerSettings(ros::NodeHandle("~absent"));
  const PatientStatusServerSettings defaults = PatientStatusServerSettings::withDefaultPaths();
  EXPECT_EQ(settings.encoding_config, defaults.encoding_config);
  EXPECT_FALSE(settings.encoding_config.empty());
  EXPECT_EQ(settings.db, defaults.db);
  EXPECT_EQ(settings.busy_timeout_ms, StoreConfig{}.busy_timeout_ms);
}

TEST(ServerSettings, WrongTypesAndInvalidValuesAreErrorsNotDefaults) {
  // A patient id roslaunch typed as a number would have selected nobody with param<>.
  EXPECT_EQ(errorOf("numeric_patient"), "parameter " + privateName("numeric_patient/patient") +
                                            " has the wrong type: expected a string, got '42'");
  EXPECT_EQ(errorOf("wrong_timeout"), "parameter " + privateName("wrong_timeout/busy_timeout_ms") +
                                          " has the wrong type: expected an integer, got 'soon'");
  EXPECT_NE(errorOf("negative_timeout").find("parameters under " + privateName("negative_timeout")),
            std::string::npos);
  EXPECT_NE(errorOf("date_only").find("date is set but patient is not"), std::string::npos);
}

TEST(ServerSettings, TyposAreNamed) {
  std::set<std::string> names;
  PatientStatusServerSettings settings = PatientStatusServerSettings::withDefaultPaths();
  vicc_common::readRosParameters(ros::NodeHandle("~typo"), settings, names);
  EXPECT_EQ(vicc_common::unknownRosParameters(ros::NodeHandle("~typo"), names),
            std::vector<std::string>{privateName("typo/paitent")});
}

}  // namespace
}  // namespace vicc_anatomy_viz::ros_adapter

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "server_settings_test");
  ros::NodeHandle nh;
  return RUN_ALL_TESTS();
}
