#pragma once
// The standard dermatome map as data on the body's landmarks (internal): for every level, the
// body parts it may cover and its band axes, after Keegan & Garrett (1948) and the evidence-
// based map of Lee, McPhee & Stringer (2008). Seeds are sampled on these axes and on the
// ISNCSCI key sensory point, then grown over the skin (dermatome_labelling.cpp).

#include <string>
#include <vector>

#include "vicc_anatomy_viz/avatar/skin_segmentation.hpp"
#include "vicc_anatomy_viz/avatar/triangle_grid.hpp"

namespace vicc_anatomy_viz::avatar::dermatome_map {

/// A band axis on a bone segment: from fraction `from` at azimuth `azimuth_from` to fraction
/// `to` at `azimuth_to` (degrees, 0 anterior, +90 lateral). On the trunk the bone is the
/// trunk, the fractions are heights relative to the key point (see ringSeeds).
struct BandAxis {
  std::string segment;
  float from, to;
  float azimuth_from, azimuth_to;
};

struct LevelMap {
  std::string level;
  std::vector<BodyPart> parts;  ///< where the level may grow
  std::vector<BandAxis> axes;
  bool trunk_ring = false;  ///< a half ring around the trunk at the key point's height
  /// Where the ring meets the arm, its seed moves down under the axilla (T3 and below).
  float max_reach = 0;  ///< > 0: grows at most this far (m) from its seeds (S4, S5)
  bool ring_under_axilla = false;
};

const std::vector<LevelMap>& levels();

/// Seed points on the skin for one level and side: the key point, the band axes sampled and,
/// for trunk levels, the half ring from the front midline round to the spine.
std::vector<Eigen::Vector3f> seedPoints(const TriangleMesh& skin, const TriangleGrid& grid,
                                        const BodyLandmarks& landmarks,
                                        const SkinSegmentation& segmentation, const LevelMap& level,
                                        Side side);

}  // namespace vicc_anatomy_viz::avatar::dermatome_map
