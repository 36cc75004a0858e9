// `tracker` node: see TrackerRos. The nodelet (vicc_tracking/TrackerNodelet) is the same
// class in a nodelet manager.
#include <ros/ros.h>

#include "vicc_tracking/frame_memory.hpp"
#include "vicc_tracking/ros/tracker_ros.hpp"

int main(int argc, char** argv) {
  vicc_tracking::keepFreedFrameMemory();
  ros::init(argc, argv, "tracker");
  ros::NodeHandle nh;
  ros::NodeHandle private_nh("~");
  try {
    vicc_tracking::TrackerRos tracker(nh, private_nh);
    ros::spin();
  } catch (const std::exception& error) {
    ROS_FATAL("tracker: %s", error.what());
    return 1;
  }
  return 0;
}
