#include "paint_map.hpp"

#include <algorithm>

namespace vicc_glyphs {
namespace io_detail {
namespace {

constexpr double kSameColor = 1e-6;

bool sameColor(const Color& a, const Color& b) {
  return (a - b).cwiseAbs().maxCoeff() < kSameColor;
}

}  // namespace

void PaintMap::paint(const Paths& area, const Color& color, double alpha) {
  alpha = std::clamp(alpha, 0.0, 1.0);
  paintPremultiplied(area, color * alpha, alpha);
}

void PaintMap::composite(const PaintMap& layer, double opacity, const Paths* clip) {
  opacity = std::clamp(opacity, 0.0, 1.0);
  for (const PaintRegion& region : layer.regions_) {
    const Paths area = clip ? intersect(region.area, *clip) : region.area;
    paintPremultiplied(area, region.premultiplied * opacity, region.alpha * opacity);
  }
}

// Source-over: below an opaque paint nothing survives; below a translucent one every region it
// overlaps splits into the part outside and a blended part inside.
void PaintMap::paintPremultiplied(const Paths& area, const Color& premultiplied, double alpha) {
  if (area.empty() || alpha <= 0.0) return;
  const IntRect box = boundsOf(area);
  const bool opaque = alpha >= 1.0 - 1e-9;
  Paths uncovered = area;
  std::vector<PaintRegion> blended;
  for (PaintRegion& region : regions_) {
    if (!boxesOverlap(region.box, box)) continue;
    if (!opaque) {
      PaintRegion mixed;
      mixed.area = intersect(region.area, area);
      if (mixed.area.empty()) continue;
      mixed.premultiplied = premultiplied + (1.0 - alpha) * region.premultiplied;
      mixed.alpha = alpha + (1.0 - alpha) * region.alpha;
      uncovered = subtract(uncovered, mixed.area);
      blended.push_back(std::move(mixed));
    }
    region.area = subtract(region.area, area);
    region.box = boundsOf(region.area);
  }
  regions_.erase(std::remove_if(regions_.begin(), regions_.end(),
                                [](const PaintRegion& r) { return r.area.empty(); }),
                 regions_.end());
  for (PaintRegion& region : blended) addRegion(std::move(region));
  addRegion({premultiplied, alpha, uncovered, {}});
}

// Regions of one colour are one region: their shared edges must not become curves.
void PaintMap::addRegion(PaintRegion region) {
  if (region.area.empty()) return;
  for (PaintRegion& existing : regions_) {
    if (std::abs(existing.alpha - region.alpha) < kSameColor &&
        sameColor(existing.premultiplied, region.premultiplied)) {
      existing.area = unite(existing.area, region.area);
      existing.box = boundsOf(existing.area);
      return;
    }
  }
  region.box = boundsOf(region.area);
  regions_.push_back(std::move(region));
}

ResolvedPicture PaintMap::resolve(const Color& background, const Paths& canvas) const {
  ResolvedPicture picture;
  picture.background.color = background;
  Paths painted;
  for (const PaintRegion& region : regions_) {
    const Color color = region.premultiplied + (1.0 - region.alpha) * background;
    Paths area = intersect(region.area, canvas);
    picture.painted |= !area.empty();
    if (area.empty() || sameColor(color, background)) continue;
    painted = unite(painted, area);
    auto same = std::find_if(picture.regions.begin(), picture.regions.end(),
                             [&](const ColorRegion& r) { return sameColor(r.color, color); });
    if (same != picture.regions.end()) {
      same->area = unite(same->area, area);
    } else {
      picture.regions.push_back({color.cwiseMax(0.0).cwiseMin(1.0), std::move(area)});
    }
  }
  picture.background.area = subtract(canvas, painted);
  return picture;
}

}  // namespace io_detail
}  // namespace vicc_glyphs
