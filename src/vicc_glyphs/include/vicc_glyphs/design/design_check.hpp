#pragma once
// Every level combination of a design, built: a design file can load and still fail for some
// data (a level whose waves carry the glyph out of its frame, a modification no curve takes, a
// curve that crosses itself where the renderer draws it). The glyph server runs this check
// after start-up on a thread of its own (background_check.hpp); `vicc_glyph check-design` runs
// it offline.

#include <functional>
#include <string>
#include <vector>

#include "vicc_glyphs/design/glyph_design.hpp"

namespace vicc_glyphs::design {

/// Every combination of data levels, the first variable's level changing fastest.
std::vector<std::vector<int>> allLevelCombinations(const GlyphDesign& design);

/// The levels as a reader names them: "probability level 4 [90, 100], amount level 0 [0, 2.5[".
std::string describeLevels(const GlyphDesign& design, const std::vector<int>& levels);

struct LevelProblem {
  std::vector<int> levels;
  std::string problem;
};

struct DesignCheck {
  int size_px = 0;
  int combinations = 0;
  std::vector<LevelProblem> problems;  ///< in the order of allLevelCombinations
};

/// Builds the glyph of every level combination at `size_px` (0: the design's size_px) and
/// reports each that cannot be built (the error) or whose curves cross themselves or each
/// other as the renderer draws them where the icon's do not (a smudge of one side's colour in
/// the other). `progress` (may be empty) is called after each combination with the number
/// done. Throws what loadIcon throws.
DesignCheck checkDesign(const GlyphDesign& design, const perception::PerceptionModel& model,
                        int size_px, const std::function<void(int done, int total)>& progress = {});

}  // namespace vicc_glyphs::design
