#pragma once
// Which curves of an icon a modification applies to: all, the outer contours (curves not
// enclosed by any other closed curve) or an explicit list of indices.

#include <string>
#include <vector>

#include "vicc_glyphs/dci/diffusion_curve.hpp"

namespace vicc_glyphs {
namespace pacemod {

struct CurveSelection {
  enum class Kind { All, Outer, Indices };
  Kind kind = Kind::All;
  std::vector<int> indices;  ///< for Kind::Indices

  /// "all", "outer" or "I,J,..." (non-negative integers). Throws std::invalid_argument.
  static CurveSelection parse(const std::string& text);
};

/// The selected curve indices, increasing and unique. Throws std::invalid_argument naming an
/// index that the image does not have.
std::vector<int> selectCurves(const DiffusionCurveImage& image, const CurveSelection& selection);

}  // namespace pacemod
}  // namespace vicc_glyphs
