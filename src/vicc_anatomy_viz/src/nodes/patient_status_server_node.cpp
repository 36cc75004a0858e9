// patient_status_server: serves patients' encoded neurological status (see
// vicc_anatomy_viz/ros/patient_status_server.hpp and docs/patient_status.md).
#include <ros/ros.h>

#include "vicc_anatomy_viz/ros/patient_status_server.hpp"

int main(int argc, char** argv) {
  ros::init(argc, argv, "patient_status_server");
  ros::NodeHandle nh;
  ros::NodeHandle private_nh("~");
  try {
    vicc_anatomy_viz::ros_adapter::PatientStatusServer server(nh, private_nh);
    ros::spin();
  } catch (const std::exception& e) {
    // Only an unusable configuration ends the node; bad requests are answered with errors.
    ROS_FATAL("patient_status_server: %s", e.what());
    return 1;
  }
  return 0;
}
