// rostest: launch/avatar.launch without rviz creates the sample database (the thesis's Fig. 4.6
// patient) and its status server answers and publishes SDH-046's latest status latched.
#include <gtest/gtest.h>

#include <vicc_msgs/ListExaminationDates.h>
#include <vicc_msgs/ListPatients.h>

#include "panel_test_support.hpp"

using namespace vicc_panel_test;

TEST(AvatarLaunchTest, TheServerListsTheSamplePatient) {
  const auto response = call<vicc_msgs::ListPatients>("list_patients");
  ASSERT_TRUE(response.success) << response.message;
  ASSERT_EQ(response.patients.size(), 1u);
  EXPECT_EQ(response.patients[0].patient_id, "SDH-046");
  EXPECT_EQ(response.patients[0].examination_count, 2u);
  vicc_msgs::ListExaminationDates::Request request;
  request.patient_id = "SDH-046";
  const auto dates = call<vicc_msgs::ListExaminationDates>("list_examination_dates", request);
  ASSERT_TRUE(dates.success) << dates.message;
  EXPECT_EQ(dates.dates, (std::vector<std::string>{kPreOperative, kPostOperative}));
}

TEST(AvatarLaunchTest, TheLaunchPatientIsPublishedLatched) {
  LatchedStatus status;
  ASSERT_TRUE(waitFor([&] { return status.last() != nullptr; }, 20.0));
  EXPECT_EQ(status.last()->patient_id, "SDH-046");
  EXPECT_TRUE(status.last()->has_examination);
  EXPECT_EQ(status.last()->examination_time, kPostOperative);
  EXPECT_EQ(status.last()->legend.size(), 6u);
  EXPECT_FALSE(status.last()->structures.empty());
}

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "avatar_launch_rostest");
  ros::NodeHandle nh;
  const int result = RUN_ALL_TESTS();
  removeSampleDatabase();
  return result;
}
