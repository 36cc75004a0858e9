// glyph_server node: see include/vicc_glyphs/ros/glyph_server.hpp.
#include <ros/ros.h>

#include <iostream>

#include "vicc_glyphs/render/process_heap.hpp"
#include "vicc_glyphs/ros/glyph_server.hpp"

int main(int argc, char** argv) {
  ros::init(argc, argv, "glyph_server");
  // The node's process is its own (unlike the nodelet's): glyph after glyph reuses the heap
  // instead of faulting in fresh pages for every large buffer.
  if (!vicc_glyphs::keepFreedMemoryForReuse()) {
    ROS_WARN("glyph_server: could not set malloc to keep freed memory; glyphs take longer");
  }
  try {
    vicc_glyphs::ros_glyph::GlyphServer server(ros::NodeHandle(), ros::NodeHandle("~"));
    ros::spin();
  } catch (const std::exception& e) {
    // Also on stderr: the node may fail before rosconsole's output is set up.
    std::cerr << "glyph_server: " << e.what() << std::endl;
    ROS_FATAL("glyph_server: %s", e.what());
    return 1;
  }
  return 0;
}
