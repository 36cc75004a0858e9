#include "vicc_avatar_snapshot_renderer.hpp"

#include <OGRE/OgreCamera.h>
#include <OGRE/OgreRenderWindow.h>
#include <OGRE/OgreRoot.h>
#include <ros/ros.h>
#include <rviz/display_group.h>
#include <rviz/properties/property.h>
#include <rviz/properties/vector_property.h>
#include <rviz/render_panel.h>
#include <rviz/selection/selection_manager.h>
#include <rviz/view_controller.h>
#include <rviz/view_manager.h>
#include <rviz/visualization_manager.h>
#include <QApplication>
#include <QColor>
#include <QElapsedTimer>

#include <algorithm>
#include <stdexcept>
#include <vector>

#include "vicc_anatomy_viz/rviz/avatar_display.hpp"
#include "vicc_anatomy_viz/rviz/avatar_meshes.hpp"
#include "vicc_anatomy_viz/rviz/ogre_camera.hpp"

namespace vicc_anatomy_viz::snapshot {
namespace {

rviz::Property& child(rviz::Property* parent, const char* name) {
  rviz::Property* property = parent ? parent->subProp(name) : nullptr;
  if (!property) throw std::runtime_error(std::string("rviz has no property '") + name + "'");
  return *property;
}

}  // namespace

AvatarRenderer::AvatarRenderer(int width, int height, const std::string& status_topic)
    : width_(width), height_(height), panel_(std::make_unique<rviz::RenderPanel>()) {
  panel_->setFixedSize(width, height);
  panel_->show();
  manager_ = new rviz::VisualizationManager(panel_.get());
  panel_->initialize(manager_->getSceneManager(), manager_);
  manager_->initialize();
  manager_->setFixedFrame("avatar");
  rviz::Property& global = child(manager_->getRootDisplayGroup(), "Global Options");
  child(&global, "Background Color").setValue(QColor(255, 255, 255));
  manager_->getViewManager()->setCurrentViewControllerType("rviz/Orbit");
  rviz::Display* display = manager_->createDisplay("vicc_anatomy_viz/Avatar", "Avatar", true);
  display_ = dynamic_cast<rviz_plugin::AvatarDisplay*>(display);
  if (!display_)
    throw std::runtime_error(
        "rviz could not load the display plugin vicc_anatomy_viz/Avatar "
        "(is the workspace's devel/setup.bash sourced?)");
  child(display_, "Topic").setValue(QString::fromStdString(status_topic));
  // A still shows the first category of every alternation; the legend names the alternation.
  child(display_, "Alternation period").setValue(0.0);
  manager_->startUpdate();
}

AvatarRenderer::~AvatarRenderer() {
  delete manager_;
  panel_.reset();
}

void AvatarRenderer::spin(double seconds) {
  QElapsedTimer timer;
  timer.start();
  while (timer.elapsed() < seconds * 1000.0) {
    QApplication::processEvents(QEventLoop::AllEvents, 10);
    ros::spinOnce();
  }
}

bool AvatarRenderer::waitForStatus(unsigned previous, double timeout_s) {
  QElapsedTimer timer;
  timer.start();
  while (display_->drawnStatusCount() <= previous) {
    if (timer.elapsed() > timeout_s * 1000.0 || !ros::ok()) return false;
    spin(0.02);
  }
  return true;
}

void AvatarRenderer::setOrbit(const avatar_view::OrbitCamera& orbit) {
  orbit_ = orbit;
  rviz::ViewController* view = manager_->getViewManager()->getCurrent();
  child(view, "Distance").setValue(orbit.distance);
  child(view, "Yaw").setValue(orbit.yaw);
  child(view, "Pitch").setValue(orbit.pitch);
  static_cast<rviz::VectorProperty&>(child(view, "Focal Point"))
      .setVector(Ogre::Vector3(orbit.focus.x(), orbit.focus.y(), orbit.focus.z()));
}

bool AvatarRenderer::setView(avatar_view::BodyView view) {
  const avatar::AvatarModel* model = display_->model();
  Eigen::Vector3f min, max;
  if (!model || !rviz_plugin::meshBounds(model->skin, min, max)) return false;
  const Ogre::Camera* camera = manager_->getViewManager()->getCurrent()->getCamera();
  const float aspect = static_cast<float>(width_) / static_cast<float>(height_);
  setOrbit(avatar_view::wholeBodyCamera(view, min, max, camera->getFOVy().valueRadians(), aspect));
  return true;
}

void AvatarRenderer::setTransparency(bool on) {
  child(display_, "View-dependent transparency").setValue(on);
}

void AvatarRenderer::renderFrame(float wall_dt) {
  manager_->getViewManager()->getCurrent()->update(wall_dt, wall_dt);
  display_->update(wall_dt, wall_dt);
  panel_->getRenderWindow()->update(true);
}

QImage AvatarRenderer::grab() {
  spin(0.1);  // rviz's own update: view controller, displays, overlays
  renderFrame();
  Ogre::RenderWindow* window = panel_->getRenderWindow();
  const int width = static_cast<int>(window->getWidth());
  const int height = static_cast<int>(window->getHeight());
  // Tightly packed rows for OGRE, then into the QImage (its rows are 4-byte aligned).
  std::vector<unsigned char> pixels(static_cast<std::size_t>(width) * height * 3);
  const Ogre::PixelBox box(width, height, 1, Ogre::PF_BYTE_RGB, pixels.data());
  window->copyContentsToMemory(Ogre::Box(0, 0, width, height), box, Ogre::RenderTarget::FB_AUTO);
  QImage image(width, height, QImage::Format_RGB888);
  for (int y = 0; y < height; ++y)
    std::copy_n(&pixels[static_cast<std::size_t>(y) * width * 3], width * 3, image.scanLine(y));
  return image;
}

void AvatarRenderer::click(int x, int y) {
  manager_->getSelectionManager()->select(panel_->getViewport(), x, y, x + 1, y + 1,
                                          rviz::SelectionManager::Replace);
  spin(0.05);
}

avatar_view::CameraModel AvatarRenderer::camera() const {
  return rviz_plugin::cameraModel(*manager_->getViewManager()->getCurrent()->getCamera());
}

}  // namespace vicc_anatomy_viz::snapshot
