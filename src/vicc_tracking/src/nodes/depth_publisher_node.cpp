// Simulated pico flexx driver: depth image, amplitude (gray) image and camera_info at the
// scenario's frame rate, and the ground-truth camera pose on tf (map -> <camera frame>_gt).
// Runs as its own process, like the real driver; imu_publisher shares its time base (see
// rig_clock.hpp).
#include <set>
#include <string>

#include <nav_msgs/Path.h>
#include <ros/ros.h>
#include <sensor_msgs/CameraInfo.h>
#include <sensor_msgs/Image.h>
#include <tf2_ros/transform_broadcaster.h>

#include "vicc_common/ros_parameters.hpp"
#include "vicc_tracking/ros/rig_clock.hpp"
#include "vicc_tracking/ros/rig_messages.hpp"
#include "vicc_tracking/sim/driver_settings.hpp"

int main(int argc, char** argv) {
  ros::init(argc, argv, "depth_publisher");
  ros::NodeHandle nh;
  ros::NodeHandle private_nh("~");
  try {
    vicc_tracking::sim::DepthDriverSettings settings;
    std::set<std::string> read_names;
    vicc_common::readRosParameters(private_nh, settings, read_names);
    vicc_common::warnUnknownRosParameters(private_nh, read_names);
    const bool loop = settings.driver.loop;
    const bool publish_ground_truth = settings.publish_ground_truth;
    const vicc_tracking::sim::RigSimulator rig(
        vicc_tracking::sim::loadScenario(settings.driver.scenario));
    ros::Publisher depth_pub =
        nh.advertise<sensor_msgs::Image>(vicc_tracking::RigTopics::kDepth, 5);
    ros::Publisher gray_pub = nh.advertise<sensor_msgs::Image>(vicc_tracking::RigTopics::kGray, 5);
    ros::Publisher info_pub =
        nh.advertise<sensor_msgs::CameraInfo>(vicc_tracking::RigTopics::kCameraInfo, 5);
    tf2_ros::TransformBroadcaster tf_broadcaster;
    // The ground-truth path, for comparing with the tracker's in rviz.
    ros::Publisher path_pub = nh.advertise<nav_msgs::Path>("ground_truth/path", 1, true);
    nav_msgs::Path path;
    path.header.frame_id = rig.scenario().frame_map;
    const ros::Time t0 = vicc_tracking::negotiateRigStartTime(nh);
    const std::vector<double> times = rig.depthTimes();
    ROS_INFO("depth_publisher: scenario '%s', %zu frames at %.1f Hz over %.1f s, start %.3f%s",
             rig.scenario().name.c_str(), times.size(), rig.scenario().depth_rate_hz,
             rig.duration(), t0.toSec(), loop ? ", looping" : "");
    for (int run = 0; ros::ok() && (run == 0 || loop); ++run) {
      const double run_offset = run * vicc_tracking::loopPeriod(rig);
      for (size_t k = 0; k < times.size() && ros::ok(); ++k) {
        const ros::Time stamp = t0 + ros::Duration(run_offset + times[k]);
        // The amplitude image costs a raycast pass only when someone listens.
        const bool gray_wanted = gray_pub.getNumSubscribers() > 0;
        vicc_tracking::RigImages images;
        if (gray_wanted) {
          images = vicc_tracking::rigImageMessages(rig, static_cast<int>(k), stamp);
        } else {
          images.depth = vicc_tracking::rigDepthMessage(rig, static_cast<int>(k), stamp);
        }
        ros::Time::sleepUntil(stamp);
        info_pub.publish(vicc_tracking::rigCameraInfo(rig, stamp));
        depth_pub.publish(images.depth);
        if (gray_wanted) gray_pub.publish(images.gray);
        if (publish_ground_truth) {
          const auto truth = vicc_tracking::rigGroundTruth(rig, times[k], stamp);
          tf_broadcaster.sendTransform(truth);
          if (run == 0) {  // later loops retrace the same path
            geometry_msgs::PoseStamped pose;
            pose.header = truth.header;
            pose.pose.position.x = truth.transform.translation.x;
            pose.pose.position.y = truth.transform.translation.y;
            pose.pose.position.z = truth.transform.translation.z;
            pose.pose.orientation = truth.transform.rotation;
            path.poses.push_back(pose);
            path.header.stamp = stamp;
            path_pub.publish(path);
          }
        }
      }
    }
    ROS_INFO("depth_publisher: scenario finished");
  } catch (const std::exception& error) {
    ROS_FATAL("depth_publisher: %s", error.what());
    return 1;
  }
  return 0;
}
