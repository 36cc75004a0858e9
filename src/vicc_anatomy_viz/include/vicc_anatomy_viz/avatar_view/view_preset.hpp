#pragma once
// The named whole-body views of vicc_avatar_snapshot as an orbit camera (rviz's Orbit view
// controller: eye = focus + distance (cos yaw cos pitch, sin yaw cos pitch, sin pitch)).
// REP-103 body: the patient faces +x, their left is +y, so "front" looks from +x and puts
// the patient's right on the image's left.

#include <Eigen/Core>

#include <optional>
#include <string>

#include "vicc_anatomy_viz/avatar_view/occlusion.hpp"

namespace vicc_anatomy_viz::avatar_view {

enum class BodyView { kFront, kBack, kLeft, kRight };

std::optional<BodyView> bodyViewFromString(const std::string& name);

struct OrbitCamera {
  Eigen::Vector3f focus = Eigen::Vector3f::Zero();
  float distance = 1.f;
  float yaw = 0.f;    ///< radians
  float pitch = 0.f;  ///< radians
  Eigen::Vector3f eye() const;
};

/// A camera that shows the box [min, max] whole, with a margin, for a vertical field of view
/// `fov_y` (radians) and image aspect (width / height).
OrbitCamera wholeBodyCamera(BodyView view, const Eigen::Vector3f& min, const Eigen::Vector3f& max,
                            float fov_y, float aspect);

/// The pinhole camera (OpenGL conventions, z up) the orbit camera amounts to.
CameraModel cameraModel(const OrbitCamera& orbit, float fov_y, float aspect,
                        float near_clip = 0.01f, float far_clip = 100.f);

}  // namespace vicc_anatomy_viz::avatar_view
