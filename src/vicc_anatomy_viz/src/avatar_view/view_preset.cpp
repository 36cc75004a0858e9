#include "vicc_anatomy_viz/avatar_view/view_preset.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace vicc_anatomy_viz::avatar_view {

std::optional<BodyView> bodyViewFromString(const std::string& name) {
  if (name == "front") return BodyView::kFront;
  if (name == "back") return BodyView::kBack;
  if (name == "left") return BodyView::kLeft;
  if (name == "right") return BodyView::kRight;
  return std::nullopt;
}

Eigen::Vector3f OrbitCamera::eye() const {
  return focus + distance * Eigen::Vector3f(std::cos(yaw) * std::cos(pitch),
                                            std::sin(yaw) * std::cos(pitch), std::sin(pitch));
}

OrbitCamera wholeBodyCamera(BodyView view, const Eigen::Vector3f& min, const Eigen::Vector3f& max,
                            float fov_y, float aspect) {
  constexpr float kPi = 3.14159265f;
  constexpr float kMargin = 1.1f;
  OrbitCamera camera;
  camera.focus = 0.5f * (min + max);
  switch (view) {
    case BodyView::kFront:
      camera.yaw = 0.f;
      break;
    case BodyView::kBack:
      camera.yaw = kPi;
      break;
    case BodyView::kLeft:
      camera.yaw = 0.5f * kPi;
      break;
    case BodyView::kRight:
      camera.yaw = -0.5f * kPi;
      break;
  }
  const Eigen::Vector3f extent = max - min;
  const bool sideways = view == BodyView::kLeft || view == BodyView::kRight;
  const float half_width = 0.5f * (sideways ? extent.x() : extent.y());
  const float half_height = 0.5f * extent.z();
  const float half_depth = 0.5f * (sideways ? extent.y() : extent.x());
  const float tan_y = std::tan(0.5f * fov_y);
  const float needed = std::max(half_height / tan_y, half_width / (tan_y * aspect));
  camera.distance = kMargin * needed + half_depth;
  return camera;
}

CameraModel cameraModel(const OrbitCamera& orbit, float fov_y, float aspect, float near_clip,
                        float far_clip) {
  const Eigen::Vector3f eye = orbit.eye();
  const Eigen::Vector3f back = (eye - orbit.focus).normalized();  // eye z axis
  const Eigen::Vector3f right = Eigen::Vector3f::UnitZ().cross(back).normalized();
  const Eigen::Vector3f up = back.cross(right);
  CameraModel camera;
  camera.view.block<1, 3>(0, 0) = right.transpose();
  camera.view.block<1, 3>(1, 0) = up.transpose();
  camera.view.block<1, 3>(2, 0) = back.transpose();
  camera.view.block<3, 1>(0, 3) = -camera.view.block<3, 3>(0, 0) * eye;
  const float focal = 1.f / std::tan(0.5f * fov_y);
  camera.projection = Eigen::Matrix4f::Zero();
  camera.projection(0, 0) = focal / aspect;
  camera.projection(1, 1) = focal;
  camera.projection(2, 2) = (far_clip + near_clip) / (near_clip - far_clip);
  camera.projection(2, 3) = 2.f * far_clip * near_clip / (near_clip - far_clip);
  camera.projection(3, 2) = -1.f;
  return camera;
}

}  // namespace vicc_anatomy_viz::avatar_view
