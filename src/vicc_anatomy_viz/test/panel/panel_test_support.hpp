#pragma once
// Shared by the avatar launch and patient panel rostests: service calls, waiting, the latched
// status, and removing the test's sample database.

#include <gtest/gtest.h>

#include <cstdio>
#include <functional>
#include <string>

#include <ros/ros.h>
#include <vicc_msgs/EncodedStatus.h>

#include "vicc_common/ros_service_call.hpp"

namespace vicc_panel_test {

inline const std::string kServer = "/patient_status_server/";
inline const std::string kPreOperative = "2023-03-06T09:15:00Z";
inline const std::string kPostOperative = "2023-03-10T08:40:00Z";

template <typename Service>
typename Service::Response call(const std::string& name, typename Service::Request request = {}) {
  Service service;
  service.request = request;
  EXPECT_TRUE(ros::service::waitForService(kServer + name, ros::Duration(20.0))) << name;
  // The panel tests' requests are queries and selections: repeatable (ros_service_call.hpp).
  EXPECT_TRUE(vicc_common::callRepeatableService(kServer + name, service)) << name;
  return service.response;
}

/// Spins (and runs `pump`, e.g. Qt's event loop) until `condition` holds or `seconds` pass.
inline bool waitFor(const std::function<bool()>& condition, double seconds = 10.0,
                    const std::function<void()>& pump = {}) {
  const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(seconds);
  while (ros::ok() && ros::WallTime::now() < deadline) {
    ros::spinOnce();
    if (pump) pump();
    if (condition()) return true;
    ros::WallDuration(0.01).sleep();
  }
  return condition();
}

/// The last status the server published on its latched topic.
class LatchedStatus {
 public:
  LatchedStatus() {
    sub_ = nh_.subscribe<vicc_msgs::EncodedStatus>(
        kServer + "status", 10,
        [this](const vicc_msgs::EncodedStatus::ConstPtr& msg) { last_ = msg; });
  }
  const vicc_msgs::EncodedStatus::ConstPtr& last() const { return last_; }

 private:
  ros::NodeHandle nh_;
  ros::Subscriber sub_;
  vicc_msgs::EncodedStatus::ConstPtr last_;
};

/// Removes the sample database the launch file created (private parameter ~sample_db).
inline void removeSampleDatabase() {
  std::string db;
  if (ros::param::get("~sample_db", db)) {
    for (const char* suffix : {"", "-wal", "-shm"}) std::remove((db + suffix).c_str());
  }
}

}  // namespace vicc_panel_test
