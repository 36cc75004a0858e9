#pragma once
// Dermatomes C2-S5 on both sides as skin regions, grown over the skin surface from seeds at
// the ISNCSCI key sensory points (method in docs/avatar_model.md, "Dermatomes").

#include <string>
#include <vector>

#include "vicc_anatomy_viz/avatar/avatar_model.hpp"
#include "vicc_anatomy_viz/avatar/body_landmarks.hpp"

namespace vicc_anatomy_viz::avatar {

/// The dermatome levels labelled, cranial to caudal: C2 ... T12, L1 ... L5, S1 ... S5.
const std::vector<std::string>& dermatomeLevels();

/// Labels every skin triangle with a dermatome and side; one region per level and side,
/// named after the catalogue's dermatome_<level> (ConfigError if the catalogue lacks one).
std::vector<SkinRegion> labelDermatomes(const TriangleMesh& skin, const BodyLandmarks& landmarks,
                                        const AnatomyCatalog& catalog);

}  // namespace vicc_anatomy_viz::avatar
