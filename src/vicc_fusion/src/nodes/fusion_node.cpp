// fusion: surfel fusion of a depth camera, tracking frame-to-model (see fusion_ros.hpp).
#include <ros/ros.h>

#include "vicc_fusion/ros/fusion_ros.hpp"
#include "vicc_tracking/frame_memory.hpp"

int main(int argc, char** argv) {
  vicc_tracking::keepFreedFrameMemory();
  ros::init(argc, argv, "fusion");
  ros::NodeHandle nh;
  ros::NodeHandle private_nh("~");
  try {
    vicc_fusion::FusionRos fusion(nh, private_nh);
    ros::spin();
  } catch (const std::exception& error) {
    ROS_FATAL("fusion: %s", error.what());
    return 1;
  }
  return 0;
}
