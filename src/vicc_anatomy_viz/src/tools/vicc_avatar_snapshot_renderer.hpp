#pragma once
// The real rviz, off-line: a RenderPanel + VisualizationManager with the AvatarDisplay loaded
// through pluginlib ("vicc_anatomy_viz/Avatar"), a white background, an Orbit camera set to
// a named whole-body view, and frames read back from the OpenGL window. Used by
// vicc_avatar_snapshot, its rostest and the FPS benchmark. Needs a QApplication and an
// initialised ROS node.

#include <QImage>

#include <memory>
#include <string>

#include "vicc_anatomy_viz/avatar_view/occlusion.hpp"
#include "vicc_anatomy_viz/avatar_view/view_preset.hpp"

namespace rviz {
class RenderPanel;
class VisualizationManager;
}  // namespace rviz

namespace vicc_anatomy_viz::rviz_plugin {
class AvatarDisplay;
}

namespace vicc_anatomy_viz::snapshot {

class AvatarRenderer {
 public:
  /// Throws std::runtime_error when the plugin does not load.
  AvatarRenderer(int width, int height, const std::string& status_topic);
  ~AvatarRenderer();

  rviz_plugin::AvatarDisplay& display() { return *display_; }
  /// rviz's manager: its update loop renders the window like rviz does (the FPS bench), and
  /// further displays can be added beside the avatar (e.g. markers).
  rviz::VisualizationManager& manager() { return *manager_; }
  /// Processes Qt and ROS events until the display drew more than `previous` statuses
  /// (false after `timeout_s`).
  bool waitForStatus(unsigned previous, double timeout_s);
  /// Runs the event loop for `seconds` (rviz's update timer, message callbacks).
  void spin(double seconds);

  /// Orbit camera at a whole-body view of the loaded avatar; false without a model.
  bool setView(avatar_view::BodyView view);
  void setOrbit(const avatar_view::OrbitCamera& orbit);
  const avatar_view::OrbitCamera& orbit() const { return orbit_; }
  void setTransparency(bool on);

  /// Updates the displays and renders one frame into the window.
  void renderFrame(float wall_dt = 0.f);
  /// Renders and reads the window back.
  QImage grab();
  /// A click of rviz's Select tool at a pixel (rviz's SelectionManager picks and selects).
  void click(int x, int y);
  /// The camera of the last rendered frame.
  avatar_view::CameraModel camera() const;

 private:
  int width_, height_;
  std::unique_ptr<rviz::RenderPanel> panel_;
  rviz::VisualizationManager* manager_ = nullptr;
  rviz_plugin::AvatarDisplay* display_ = nullptr;
  avatar_view::OrbitCamera orbit_;
};

}  // namespace vicc_anatomy_viz::snapshot
