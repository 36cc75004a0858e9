#pragma once
// An OGRE camera's matrices as the avatar view logic's CameraModel.

#include <OGRE/OgreCamera.h>

#include "vicc_anatomy_viz/avatar_view/occlusion.hpp"

namespace vicc_anatomy_viz::rviz_plugin {

inline avatar_view::CameraModel cameraModel(const Ogre::Camera& camera) {
  avatar_view::CameraModel model;
  const Ogre::Matrix4& view = camera.getViewMatrix();
  const Ogre::Matrix4& projection = camera.getProjectionMatrix();
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 4; ++c) {
      model.view(r, c) = view[r][c];
      model.projection(r, c) = projection[r][c];
    }
  }
  return model;
}

}  // namespace vicc_anatomy_viz::rviz_plugin
