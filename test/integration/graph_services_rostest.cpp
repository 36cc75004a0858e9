// rostest: the clinical side of a launched graph (launch/clinic.launch or launch/demo.launch)
// answers, and rviz loads its configuration with every plugin.
//   ServersAnswer: the patient status server on the sample database lists the sample patient
//     SDH-046 and encodes its pre-operative examination (thesis Fig. 4.6); the glyph server
//     renders the intracranial-pressure glyph at the requested size and refuses an unknown
//     design by name.
//   DemoTracks: the replayed recording is tracked on /fusion/odom.
//   RvizLoadsAllPlugins: rviz (under Xvfb, its output in the file given by ~rviz_log)
//     subscribes to the scan's and the avatar's topics, and printed no error.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <sstream>
#include <string>

#include <nav_msgs/Odometry.h>
#include <ros/ros.h>

#include "graph_queries.hpp"
#include "roslaunch_child.hpp"
#include "vicc_msgs/GetEncodedStatus.h"
#include "vicc_msgs/ListPatients.h"
#include "vicc_msgs/RenderGlyph.h"

namespace {

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

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "graph_services_rostest");
  ros::NodeHandle nh;
  const ros::Subscriber odom = nh.subscribe("/fusion/odom", 1000, &countPose);
  return RUN_ALL_TESTS();
}
