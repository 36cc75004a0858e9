#pragma once
// The cross-section of a generated structure at one station of its bone (internal to
// structure_generator): an ellipse, a sector of the limb, or the cavity inside the skin's
// section, as a ring of points in the station's plane.

#include <Eigen/Core>

#include <vector>

#include "vicc_anatomy_viz/avatar/avatar_manifest.hpp"
#include "vicc_anatomy_viz/avatar/body_landmarks.hpp"
#include "vicc_anatomy_viz/avatar/cross_section.hpp"

namespace vicc_anatomy_viz::avatar {

/// A full-size ring (scale 1) and the point it shrinks to, in plane coordinates.
struct SectionRing {
  Eigen::Vector2f centre = Eigen::Vector2f::Zero();
  std::vector<Eigen::Vector2f> points;
  float size = 0;  ///< a characteristic radius, m (neighbouring stations grow by a bounded ratio)

  /// The ring scaled towards its centre.
  std::vector<Eigen::Vector2f> scaled(float scale) const;
};

/// Points per ring of a section shape (the same at every station, so rings can be stitched).
int ringPointCount(SectionShape section);

/// The ring of `shape` in `plane` (its origin on the bone axis, normal along it), `skin` the
/// skin's section loop around the axis, `bone` the frame the azimuths are measured in.
SectionRing sectionRing(const SectionLoop& skin, const SectionPlane& plane, const BoneFrame& bone,
                        const GeneratedShape& shape);

}  // namespace vicc_anatomy_viz::avatar
