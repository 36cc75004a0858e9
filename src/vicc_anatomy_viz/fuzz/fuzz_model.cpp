#include "fuzz_targets.hpp"

namespace vicc_anatomy_viz::fuzz {

const EncodingModel& fuzzModel() {
  static const EncodingModel model =
      EncodingModel::load(VICC_ANATOMY_VIZ_SOURCE_DIR "/config/encoding/neurological_status.yaml",
                          VICC_ANATOMY_VIZ_SOURCE_DIR "/config/anatomy/structures.yaml");
  return model;
}

}  // namespace vicc_anatomy_viz::fuzz
