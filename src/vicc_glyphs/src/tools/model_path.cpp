#include "model_path.hpp"

namespace vicc_glyphs::tools {

std::string defaultPerceptionModelPath() { return VICC_GLYPHS_DEFAULT_MODEL; }

}  // namespace vicc_glyphs::tools
