// Simulated IMU driver: sensor_msgs/Imu (REP-145 raw: rad/s, specific force incl. gravity,
// no orientation) in imu_link, and the IMU -> camera extrinsic on /tf_static.
#include <set>
#include <string>

#include <ros/ros.h>
#include <sensor_msgs/Imu.h>
#include <tf2_ros/static_transform_broadcaster.h>

#include "vicc_common/ros_parameters.hpp"
#include "vicc_tracking/ros/rig_clock.hpp"
#include "vicc_tracking/ros/rig_messages.hpp"
#include "vicc_tracking/sim/driver_settings.hpp"

int main(int argc, char** argv) {
  ros::init(argc, argv, "imu_publisher");
  ros::NodeHandle nh;
  ros::NodeHandle private_nh("~");
  try {
    vicc_tracking::sim::DriverSettings settings;
    std::set<std::string> read_names;
    vicc_common::readRosParameters(private_nh, settings, read_names);
    vicc_common::warnUnknownRosParameters(private_nh, read_names);
    const bool loop = settings.loop;
    const vicc_tracking::sim::RigSimulator rig(vicc_tracking::sim::loadScenario(settings.scenario));
    ros::Publisher imu_pub = nh.advertise<sensor_msgs::Imu>(vicc_tracking::RigTopics::kImu, 400);
    tf2_ros::StaticTransformBroadcaster static_broadcaster;
    const ros::Time t0 = vicc_tracking::negotiateRigStartTime(nh);
    static_broadcaster.sendTransform(vicc_tracking::rigExtrinsic(rig, t0));
    const std::vector<double> times = rig.imuTimes();
    ROS_INFO("imu_publisher: scenario '%s', %zu readings at %.0f Hz, start %.3f%s",
             rig.scenario().name.c_str(), times.size(), rig.scenario().imu.rate_hz, t0.toSec(),
             loop ? ", looping" : "");
    for (int run = 0; ros::ok() && (run == 0 || loop); ++run) {
      const double run_offset = run * vicc_tracking::loopPeriod(rig);
      for (size_t k = 0; k < times.size() && ros::ok(); ++k) {
        const ros::Time stamp = t0 + ros::Duration(run_offset + times[k]);
        ros::Time::sleepUntil(stamp);
        imu_pub.publish(vicc_tracking::rigImuMessage(rig, static_cast<int>(k), stamp));
      }
    }
    ROS_INFO("imu_publisher: scenario finished");
    ros::spin();  // keep the latched /tf_static available
  } catch (const std::exception& error) {
    ROS_FATAL("imu_publisher: %s", error.what());
    return 1;
  }
  return 0;
}
