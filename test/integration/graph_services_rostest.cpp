// rostest: the clinical side of a launched graph (launch/clinic.launch or launch/demo.launch)
// answers, and rviz loads its configuration with every plugin.
//   ServersAnswer: the patient status server on the sample database lists the sample patient
//     SDH-046 and encodes its pre-operative examination (thesis Fig. 4.6); the glyph server
//     renders the intracranial-pressure glyph at the requested size and refuses an unknown
//     design by name.
//   DemoTracks: the replayed recording is tracked on /fusion/odom.
//   RvizLoadsAllPlugins: rviz (under Xvfb, its output in the file given by ~rviz_log)
//     subscribes to the scan's and the avatar's topics, and printed no error.
//   ClinicStopsOnSigint (argument: CLINIC_LAUNCH): runs clinic.launch itself on a database of
//     its own, records an examination, sends SIGINT: roslaunch ends with exit code 0 within
//     10 s, and the database passes `vicc_patient check` and holds the new examination.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <nav_msgs/Odometry.h>
#include <ros/ros.h>

#include "graph_queries.hpp"
#include "roslaunch_child.hpp"
#include "vicc_msgs/GetEncodedStatus.h"
#include "vicc_msgs/ListPatients.h"
#include "vicc_msgs/RecordExamination.h"
#include "vicc_msgs/RenderGlyph.h"

extern char** environ;

namespace {

std::vector<std::string> g_program_args;  // positional, after gtest and ros::init removed theirs

const ros::Duration kServiceWait(90.0);  // the sample database is imported on first start
// Poses on /fusion/odom since the start: subscribed before the first test, so a replay that
// ends while ServersAnswer waits for the servers is still counted.
std::size_t g_poses = 0;
void countPose(const nav_msgs::OdometryConstPtr&) { ++g_poses; }

TEST(GraphServices, ServersAnswer) {
  ASSERT_TRUE(
      ros::service::waitForService("/patient_status_server/get_encoded_status", kServiceWait));
  vicc_msgs::ListPatients list;
  ASSERT_TRUE(ros::service::call("/patient_status_server/list_patients", list));
  ASSERT_TRUE(list.response.success) << list.response.message;
  const auto& patients = list.response.patients;
  const auto sample = std::find_if(patients.begin(), patients.end(), [](const auto& patient) {
    return patient.patient_id == "SDH-046";
  });
  ASSERT_NE(sample, patients.end()) << "the sample patient SDH-046 is not listed";
  EXPECT_GE(sample->examination_count, 2u) << "Fig. 4.6 has a pre- and a post-operative status";

  vicc_msgs::GetEncodedStatus status;
  status.request.patient_id = "SDH-046";
  status.request.date = "2023-03-06T09:15:00Z";  // the pre-operative examination
  ASSERT_TRUE(ros::service::call("/patient_status_server/get_encoded_status", status));
  ASSERT_TRUE(status.response.success) << status.response.message;
  EXPECT_TRUE(status.response.status.has_examination);
  EXPECT_EQ(status.response.status.patient_id, "SDH-046");
  const auto& structures = status.response.status.structures;
  EXPECT_TRUE(std::any_of(structures.begin(), structures.end(), [](const auto& structure) {
    return structure.structure_id == "dermatome_L5" && structure.side == "left" &&
           structure.category == "radicular_pain";
  })) << "the left L5 radicular pain of the sample is not encoded";

  ASSERT_TRUE(ros::service::waitForService("/glyph_server/render", kServiceWait));
  vicc_msgs::RenderGlyph glyph;
  glyph.request.design = "intracranial_pressure";
  glyph.request.names = {"pressure", "category"};
  glyph.request.values = {22.0, 2.0};
  glyph.request.size = 96;
  ASSERT_TRUE(ros::service::call("/glyph_server/render", glyph));
  ASSERT_TRUE(glyph.response.success) << glyph.response.message;
  EXPECT_EQ(glyph.response.image.width, 96u);
  EXPECT_GT(glyph.response.image.height, 0u);
  EXPECT_EQ(glyph.response.image.encoding, "rgb8");
  EXPECT_EQ(glyph.response.image.data.size(),
            std::size_t{glyph.response.image.step} * glyph.response.image.height);

  vicc_msgs::RenderGlyph unknown;
  unknown.request.design = "no_such_design";
  ASSERT_TRUE(ros::service::call("/glyph_server/render", unknown));
  EXPECT_FALSE(unknown.response.success);
  EXPECT_NE(unknown.response.message.find("no_such_design"), std::string::npos)
      << unknown.response.message;
}

TEST(GraphServices, DemoTracks) {
  EXPECT_TRUE(vicc_test::spinUntil([] { return g_poses > 20; }, ros::WallDuration(120.0)))
      << "the demo's replay was not tracked (" << g_poses << " poses on /fusion/odom)";
}

/// The lines of rviz's output that report an error (ROS_ERROR, an OGRE exception, a plugin
/// that failed to load); "media_export" (a harmless message of the Debian package's plugin
/// scan) is not one.
std::string errorLines(const std::string& path) {
  std::ifstream log(path);
  std::string line, errors;
  while (std::getline(log, line)) {
    const bool error = line.find("[ERROR]") != std::string::npos ||
                       line.find("EXCEPTION") != std::string::npos ||
                       line.find("failed to load") != std::string::npos;
    if (error && line.find("media_export") == std::string::npos) errors += line + "\n";
  }
  return errors;
}

TEST(GraphServices, RvizLoadsAllPlugins) {
  std::string rviz_log;
  ASSERT_TRUE(ros::param::get("~rviz_log", rviz_log)) << "no ~rviz_log given";
  EXPECT_TRUE(vicc_test::spinUntil(
      [] {
        return vicc_test::nodeSubscribes("/rviz", "/fusion/model") &&
               vicc_test::nodeSubscribes("/rviz", "/patient_status_server/status");
      },
      ros::WallDuration(120.0)))
      << "rviz did not subscribe to the model and the patient status:\n"
      << errorLines(rviz_log);
  ros::WallDuration(5.0).sleep();  // the first status and model are drawn
  EXPECT_EQ(errorLines(rviz_log), "") << "rviz reported errors (log " << rviz_log << ")";
  EXPECT_TRUE(vicc_test::nodeIsRegistered("/rviz")) << "rviz ended";
}

TEST(GraphServices, ClinicStopsOnSigint) {
  ASSERT_EQ(g_program_args.size(), 1u) << "usage: graph_services_rostest CLINIC_LAUNCH";
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("vicc_clinic_sigint_" + std::to_string(getpid()));
  std::filesystem::create_directories(dir);
  const std::string db = (dir / "sample.db").string();
  const std::string log = (dir / "roslaunch.log").string();
  const pid_t roslaunch = vicc_test::startRoslaunch(
      {"roslaunch", g_program_args[0], "rviz:=false", "sample_db:=" + db}, log);
  ASSERT_NE(roslaunch, 0) << "roslaunch could not be started";
  const bool up =
      ros::service::waitForService("/patient_status_server/record_examination", kServiceWait);
  EXPECT_TRUE(up) << vicc_test::readTextFile(log);

  vicc_msgs::RecordExamination record;
  record.request.patient_id = "SDH-046";
  record.request.taken_at = "2023-03-20T08:00:00Z";
  vicc_msgs::Finding finding;
  finding.category = "paresis";
  finding.structure_id = "tibialis_anterior";
  finding.side = "right";
  vicc_msgs::PropertyValue strength;
  strength.prop_type = "muscle_strength";
  strength.value = "5";
  finding.values.push_back(strength);
  record.request.findings.push_back(finding);
  EXPECT_TRUE(up && ros::service::call("/patient_status_server/record_examination", record));
  EXPECT_TRUE(record.response.success) << record.response.message;

  vicc_test::expectCleanSigintStop(roslaunch, log);

  const ros::WallDuration tool_limit(60.0);
  const vicc_test::ChildRun check =
      vicc_test::runToEnd({"rosrun", "vicc_anatomy_viz", "vicc_patient", "check", "--db", db},
                          tool_limit, (dir / "check.log").string());
  EXPECT_EQ(check.exitCode(), 0) << "the database is not consistent after SIGINT:\n"
                                 << check.printed;
  const vicc_test::ChildRun list =
      vicc_test::runToEnd({"rosrun", "vicc_anatomy_viz", "vicc_patient", "list", "--db", db},
                          tool_limit, (dir / "list.log").string());
  EXPECT_EQ(list.exitCode(), 0) << list.printed;
  EXPECT_NE(list.printed.find("SDH-046"), std::string::npos) << list.printed;
  EXPECT_NE(list.printed.find("2023-03-20"), std::string::npos)
      << "the examination recorded before SIGINT is not in the database:\n"
      << list.printed;
  std::filesystem::remove_all(dir);
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "graph_services_rostest");
  for (int i = 1; i < argc; ++i)
    if (std::string(argv[i]).rfind("--", 0) != 0) g_program_args.emplace_back(argv[i]);
  ros::NodeHandle nh;
  const ros::Subscriber odom = nh.subscribe("/fusion/odom", 1000, &countPose);
  return RUN_ALL_TESTS();
}
