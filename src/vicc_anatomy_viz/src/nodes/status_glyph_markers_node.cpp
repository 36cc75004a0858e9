// status_glyph_markers: a status glyph (default: intracranial pressure) above the avatar's
// head as a MarkerArray (see vicc_anatomy_viz/ros/status_glyph_markers.hpp).
#include <ros/ros.h>

#include "vicc_anatomy_viz/ros/status_glyph_markers.hpp"

int main(int argc, char** argv) {
  ros::init(argc, argv, "status_glyph_markers");
  ros::NodeHandle nh;
  ros::NodeHandle private_nh("~");
  try {
    vicc_anatomy_viz::ros_adapter::StatusGlyphMarkers markers(nh, private_nh);
    ros::spin();
  } catch (const std::exception& e) {
    ROS_FATAL("status_glyph_markers: %s", e.what());
    return 1;
  }
  return 0;
}
