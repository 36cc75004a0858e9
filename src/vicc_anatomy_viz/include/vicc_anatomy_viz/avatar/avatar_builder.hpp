#pragma once
// buildAvatarModel with its by-products: the landmarks it found and the time each step took
// (for the vicc_avatar_model report and the tests).

#include <string>

#include "vicc_anatomy_viz/avatar/avatar_manifest.hpp"
#include "vicc_anatomy_viz/avatar/avatar_model.hpp"
#include "vicc_anatomy_viz/avatar/body_landmarks.hpp"

namespace vicc_anatomy_viz::avatar {

struct AvatarBuildTimes {
  double load_seconds = 0;  ///< manifest and skin mesh
  double landmark_seconds = 0;
  double structure_seconds = 0;
  double dermatome_seconds = 0;
  double total_seconds = 0;
};

struct AvatarBuild {
  AvatarManifest manifest;
  AvatarModel model;
  BodyLandmarks landmarks;
  AvatarBuildTimes times;
};

/// Everything buildAvatarModel does; same errors.
AvatarBuild buildAvatar(const std::string& manifest_path, const AnatomyCatalog& catalog);

/// Clearance kept between generated structures and the skin, m.
constexpr float kStructureSkinMargin = 0.003f;

}  // namespace vicc_anatomy_viz::avatar
