#pragma once
// A box of text lines (each with an optional colour swatch) drawn over the 3D view: the legend
// (thesis Fig. 4.8) and the clicked structure's name and raw values (Fig. 4.7C). Painted with
// QPainter into a texture shown by an OGRE overlay panel.

#include <string>
#include <vector>

#include <OGRE/OgreMaterial.h>
#include <OGRE/OgreTexture.h>

#include "vicc_anatomy_viz/visual_variables.hpp"

namespace Ogre {
class Overlay;
class PanelOverlayElement;
}  // namespace Ogre

namespace vicc_anatomy_viz::rviz_plugin {

struct OverlayLine {
  std::string text;
  bool has_swatch = false;
  Rgba swatch;
  bool bold = false;
};

class ScreenOverlay {
 public:
  enum class Corner { kTopLeft, kBottomLeft };
  ScreenOverlay(const std::string& name, Corner corner);
  ~ScreenOverlay();
  ScreenOverlay(const ScreenOverlay&) = delete;
  ScreenOverlay& operator=(const ScreenOverlay&) = delete;

  /// Repaints the box; no lines hides it.
  void setLines(const std::vector<OverlayLine>& lines);
  void setVisible(bool visible);

 private:
  std::string name_;
  Corner corner_;
  bool visible_ = true;
  bool has_lines_ = false;
  Ogre::Overlay* overlay_ = nullptr;
  Ogre::PanelOverlayElement* panel_ = nullptr;
  Ogre::MaterialPtr material_;
  Ogre::TexturePtr texture_;
};

}  // namespace vicc_anatomy_viz::rviz_plugin
