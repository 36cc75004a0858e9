#include "vicc_glyphs/pacemod/image_frame.hpp"

#include <algorithm>

#include "vicc_glyphs/pacemod/polyline.hpp"

namespace vicc_glyphs {
namespace pacemod {

double reachBeyondFrame(const DiffusionCurve& curve, int width, int height) {
  double beyond = -1e300;
  for (const Point2& p : sampleCurve(curve, 16)) {
    beyond = std::max({beyond, -p.x(), -p.y(), p.x() - width, p.y() - height});
  }
  return beyond;
}

std::optional<int> curveCarriedOutOfFrame(const DiffusionCurveImage& before,
                                          const DiffusionCurveImage& after,
                                          const std::vector<int>& curves) {
  constexpr double kTolerancePx = 0.5;
  for (int index : curves) {
    const auto i = static_cast<size_t>(index);
    if (index < 0 || i >= before.curves.size() || i >= after.curves.size()) continue;
    if (reachBeyondFrame(before.curves[i], before.width, before.height) <= kTolerancePx &&
        reachBeyondFrame(after.curves[i], after.width, after.height) > kTolerancePx) {
      return index;
    }
  }
  return std::nullopt;
}

}  // namespace pacemod
}  // namespace vicc_glyphs
