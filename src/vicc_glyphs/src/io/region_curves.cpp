#include "region_curves.hpp"

#include <algorithm>
#include <unordered_map>

#include "side_colors.hpp"

namespace vicc_glyphs {
namespace io_detail {
namespace {

// Where a colour change at a vertex takes effect on either side of it (curve parameter).
constexpr double kColorStep = 1e-3;

struct EdgeKey {
  IntPoint from, to;
  bool operator==(const EdgeKey& o) const { return from == o.from && to == o.to; }
};

struct EdgeHash {
  std::size_t operator()(const EdgeKey& e) const {
    std::size_t h = 1469598103934665603ull;
    for (ClipperLib::cInt v : {e.from.X, e.from.Y, e.to.X, e.to.Y}) {
      h = (h ^ static_cast<std::size_t>(v)) * 1099511628211ull;
    }
    return h;
  }
};

// Which region a point lies in: the regions' polygons nest as outer boundaries and holes,
// so a point is inside a region when an odd number of its polygons contain it.
class RegionLocator {
 public:
  explicit RegionLocator(const std::vector<const Paths*>& areas) : areas_(areas) {
    for (const Paths* area : areas) {
      std::vector<IntRect> boxes;
      for (const Path& path : *area) boxes.push_back(boundsOf({path}));
      boxes_.push_back(std::move(boxes));
    }
  }

  /// Index of the region containing `p`, or -1 (outside all, or on a boundary).
  int locate(const IntPoint& p) const {
    for (std::size_t r = 0; r < areas_.size(); ++r) {
      int inside = 0;
      for (std::size_t k = 0; k < areas_[r]->size(); ++k) {
        const IntRect& b = boxes_[r][k];
        if (p.X < b.left || p.X > b.right || p.Y < b.top || p.Y > b.bottom) continue;
        const int result = ClipperLib::PointInPolygon(p, (*areas_[r])[k]);
        if (result < 0) return -1;
        inside += result;
      }
      if (inside % 2 == 1) return static_cast<int>(r);
    }
    return -1;
  }

 private:
  std::vector<const Paths*> areas_;
  std::vector<std::vector<IntRect>> boxes_;
};

class CurveBuilder {
 public:
  CurveBuilder(const ResolvedPicture& picture, const IntegerFrame& frame)
      : picture_(picture), frame_(frame), locator_(areas(picture)) {
    const auto all = areas(picture);
    for (std::size_t r = 0; r < all.size(); ++r) {
      for (const Path& path : *all[r]) {
        for (std::size_t i = 0; i < path.size(); ++i) {
          owner_[{path[i], path[(i + 1) % path.size()]}] = static_cast<int>(r);
        }
      }
    }
  }

  // Clipper's outer boundaries run clockwise on screen (y down) and holes anticlockwise: the
  // region lies on their right, so the reversed path has it on its left.
  DiffusionCurve curve(const Path& path, const Color& color) const {
    Path reversed(path.rbegin(), path.rend());
    const std::size_t n = reversed.size();
    DiffusionCurve curve;
    std::vector<ColorPoint> right;
    curve.control_points.push_back(frame_.toPixel(reversed[0]));
    for (std::size_t i = 0; i < n; ++i) {
      const IntPoint& a = reversed[i];
      const IntPoint& b = reversed[(i + 1) % n];
      const Point2 pa = frame_.toPixel(a);
      const Point2 pb = frame_.toPixel(b);
      curve.control_points.insert(curve.control_points.end(),
                                  {pa + (pb - pa) / 3.0, pa + 2.0 * (pb - pa) / 3.0, pb});
      const Color across = colorAcross(a, b, pa, pb);
      right.push_back({i + kColorStep, across});
      right.push_back({i + 1.0 - kColorStep, across});
    }
    const double segments = static_cast<double>(n);
    curve.left_colors = {{0.0, color}, {segments, color}};
    curve.right_colors = reduceColorRuns(right, segments);
    return curve;
  }

 private:
  static std::vector<const Paths*> areas(const ResolvedPicture& picture) {
    std::vector<const Paths*> all;
    for (const ColorRegion& region : picture.regions) all.push_back(&region.area);
    all.push_back(&picture.background.area);
    return all;
  }

  const Color& colorOf(int region) const {
    return region >= 0 && region < static_cast<int>(picture_.regions.size())
               ? picture_.regions[region].color
               : picture_.background.color;
  }

  // The neighbour owns the same edge in the opposite direction; where the two boundaries do
  // not share vertices, a point just right of the edge's middle is located instead.
  Color colorAcross(const IntPoint& a, const IntPoint& b, const Point2& pa,
                    const Point2& pb) const {
    const auto shared = owner_.find({a, b});
    if (shared != owner_.end()) return colorOf(shared->second);
    const Point2 d = pb - pa;
    const double length = d.norm();
    if (!(length > 0.0)) return picture_.background.color;
    const double offset = std::max(4.0 / frame_.unitsPerPixel(), std::min(1e-3, 0.25 * length));
    const Point2 right_normal(-d.y() / length, d.x() / length);
    return colorOf(locator_.locate(frame_.toInt(0.5 * (pa + pb) + offset * right_normal)));
  }

  const ResolvedPicture& picture_;
  const IntegerFrame& frame_;
  RegionLocator locator_;
  std::unordered_map<EdgeKey, int, EdgeHash> owner_;
};

}  // namespace

DiffusionCurveImage regionCurves(const ResolvedPicture& picture, const IntegerFrame& frame,
                                 int width, int height) {
  DiffusionCurveImage image;
  image.width = width;
  image.height = height;
  const CurveBuilder builder(picture, frame);
  for (const ColorRegion& region : picture.regions) {
    for (const Path& path : region.area) {
      if (path.size() >= 3) image.curves.push_back(builder.curve(path, region.color));
    }
  }
  return image;
}

}  // namespace io_detail
}  // namespace vicc_glyphs
