// callRepeatableService against a real service of this node: a call whose transport fails is
// repeated, at most the given number of times. A callback that returns false stands in for
// the lost response (roscpp reports both the same way: call() returns false).
#include <gtest/gtest.h>
#include <ros/ros.h>
#include <roscpp/Empty.h>

#include <atomic>

#include "vicc_common/ros_service_call.hpp"

namespace {

// Fails the first `failures` calls, then answers (in the spinner's thread: the count is atomic).
class FlakyService {
 public:
  FlakyService(ros::NodeHandle& nh, const std::string& name, int failures)
      : failures_(failures), server_(nh.advertiseService(name, &FlakyService::answer, this)) {}
  int calls() const { return calls_; }

 private:
  bool answer(roscpp::Empty::Request&, roscpp::Empty::Response&) { return ++calls_ > failures_; }

  int failures_;
  std::atomic<int> calls_{0};
  ros::ServiceServer server_;
};

TEST(RosServiceCall, RepeatsAFailedCallUntilItIsAnswered) {
  ros::NodeHandle nh("~");
  FlakyService flaky(nh, "fails_twice", 2);
  roscpp::Empty empty;
  EXPECT_TRUE(vicc_common::callRepeatableService(nh.resolveName("fails_twice"), empty));
  EXPECT_EQ(flaky.calls(), 3);
}

TEST(RosServiceCall, GivesUpAfterTheAttempts) {
  ros::NodeHandle nh("~");
  FlakyService flaky(nh, "fails_often", 5);
  roscpp::Empty empty;
  EXPECT_FALSE(vicc_common::callRepeatableService(nh.resolveName("fails_often"), empty, 2));
  EXPECT_EQ(flaky.calls(), 2);
  ros::ServiceClient client = nh.serviceClient<roscpp::Empty>("fails_often");
  EXPECT_TRUE(vicc_common::callRepeatableService(client, empty, 4));  // calls 3, 4, 5 fail
  EXPECT_EQ(flaky.calls(), 6);
}

TEST(RosServiceCall, AMissingServiceIsNotAnswered) {
  roscpp::Empty empty;
  EXPECT_FALSE(vicc_common::callRepeatableService("/no_such_service", empty));
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "ros_service_call_test");
  ros::AsyncSpinner spinner(1);  // serves this node's own services while a test waits
  spinner.start();
  return RUN_ALL_TESTS();
}
