#pragma once
// Inner structures generated from the skin's landmarks: shapes swept along a bone axis (muscle
// bellies filling a sector of the limb, slender ellipses, organs filling a cavity), their
// cross-sections sized from the skin's cross-section so that they lie under the skin, and
// proxies on the skin above small structures.

#include "vicc_anatomy_viz/avatar/avatar_manifest.hpp"
#include "vicc_anatomy_viz/avatar/avatar_model.hpp"
#include "vicc_anatomy_viz/avatar/body_landmarks.hpp"

namespace vicc_anatomy_viz::avatar {

/// Closed mesh of `shape` on `side` (its section at every station, scaled by the belly
/// profile). Every ring vertex lies inside the skin's cross-section at least `margin` from
/// the skin. ConfigError (naming `what`) when the bone axis leaves the skin.
TriangleMesh generateShape(const TriangleMesh& skin, const BodyLandmarks& landmarks,
                           const GeneratedShape& shape, Side side, float margin,
                           const std::string& what);

/// The proxy disc on the skin (centre, outward normal, radius) as `placement` says.
SkinProxy placeProxy(const TriangleMesh& skin, const BodyLandmarks& landmarks,
                     const ProxyPlacement& placement, Side side, const std::string& what);

}  // namespace vicc_anatomy_viz::avatar
