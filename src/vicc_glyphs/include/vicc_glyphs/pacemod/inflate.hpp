#pragma once
// Shrinking and inflating icon parts (thesis 6.2.3.3): a selected closed contour is replaced by
// the isoline of its region's distance field at the given offset (offset_contour.hpp), which is
// more robust against local distortions than translating curve points. Following the thesis'
// assumption of homogeneous regions (6.2.3.1), each side of the new curve carries the mean
// colour of the old side (and the mean blur sigma). An inflated part stops 1 px short of the
// closed contours beside it (those that neither enclose it nor lie inside it: the cloud a rain
// drop hangs from), as the mean side colours would be wrong inside them; enclosing contours
// are not consulted.

#include <string>
#include <vector>

#include "vicc_glyphs/dci/diffusion_curve.hpp"

namespace vicc_glyphs {
namespace pacemod {

struct CurveInflateReport {
  int curve = 0;
  double offset_mm = 0.0;  ///< > 0 inflated, < 0 shrunk
  double area_before_mm2 = 0.0;
  double area_after_mm2 = 0.0;
  std::string skipped;   ///< non-empty: left unchanged (open curve, or nothing left)
  bool limited = false;  ///< inflated less where it would have reached a neighbouring contour
};

/// Throws std::invalid_argument for a non-finite offset, an invalid glyph size or a curve index
/// out of range.
std::vector<CurveInflateReport> inflateCurves(DiffusionCurveImage& image,
                                              const std::vector<int>& curves, double offset_mm,
                                              double glyph_size_mm);

}  // namespace pacemod
}  // namespace vicc_glyphs
