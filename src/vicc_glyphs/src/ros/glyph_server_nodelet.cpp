// The glyph server as a nodelet (same interface as the node).
#include <nodelet/nodelet.h>
#include <pluginlib/class_list_macros.hpp>

#include <memory>

#include "vicc_glyphs/ros/glyph_server.hpp"

namespace vicc_glyphs::ros_glyph {

class GlyphServerNodelet : public nodelet::Nodelet {
 private:
  void onInit() override {
    try {
      server_ = std::make_unique<GlyphServer>(getNodeHandle(), getPrivateNodeHandle());
    } catch (const std::exception& e) {
      NODELET_FATAL("glyph_server: %s", e.what());
      throw;
    }
  }
  std::unique_ptr<GlyphServer> server_;
};

}  // namespace vicc_glyphs::ros_glyph

PLUGINLIB_EXPORT_CLASS(vicc_glyphs::ros_glyph::GlyphServerNodelet, nodelet::Nodelet)
