// rostest: rviz, started with a configuration in which the PatientPanel saved a selection,
// loads the panel plugin without errors and the panel makes the server publish that selection
// (the server started on the latest examination, unfiltered).
#include <gtest/gtest.h>

#include <rosgraph_msgs/Log.h>

#include "panel_test_support.hpp"

using namespace vicc_panel_test;

TEST(AvatarRvizTest, ThePanelInRvizRequestsItsSavedSelection) {
  std::vector<std::string> rviz_errors;
  ros::NodeHandle nh;
  const ros::Subscriber rosout = nh.subscribe<rosgraph_msgs::Log>(
      "/rosout", 100, [&](const rosgraph_msgs::Log::ConstPtr& log) {
        if (log->name == "/rviz" && log->level >= rosgraph_msgs::Log::ERROR) {
          rviz_errors.push_back(log->msg);
        }
      });
  LatchedStatus status;
  // rviz under Xvfb (software OpenGL) takes a few seconds to start.
  const bool selected = waitFor(
      [&] {
        const auto& last = status.last();
        return last && last->examination_time == kPreOperative &&
               last->hidden_categories == std::vector<std::string>{"sensory_disorder"};
      },
      90.0);
  ASSERT_TRUE(selected) << (status.last() ? "last status: " + status.last()->examination_time
                                          : std::string("no status"));
  EXPECT_EQ(status.last()->patient_id, "SDH-046");
  EXPECT_EQ(status.last()->requested_date, kPreOperative);
  for (const auto& structure : status.last()->structures) {
    EXPECT_NE(structure.category, "sensory_disorder") << structure.structure_id;
  }
  for (const auto& error : rviz_errors) {
    EXPECT_EQ(error.find("PatientPanel"), std::string::npos) << error;
  }
}

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "avatar_rviz_rostest");
  ros::NodeHandle nh;
  const int result = RUN_ALL_TESTS();
  removeSampleDatabase();
  return result;
}
