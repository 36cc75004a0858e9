#include "region_curves.hpp"

#include <algorithm>
#include <cmath>
#include <unordered_map>

#include "bezier_refit.hpp"
#include "side_colors.hpp"

namespace vicc_glyphs {
namespace io_detail {
namespace {

// Where a colour change at a vertex takes effect on either side of it (curve parameter).
constexpr double kColorStep = 1e-3;
// Polygon vertices turning by more than 30 degrees are corners of the refit curve.
const double kCornerCosine = std::cos(30.0 * M_PI / 180.0);
// A polygon edge at least this many sample spacings long is a straight edge of the icon.
constexpr double kStraightEdgeSpacings = 8.0;

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

  // A hole that one other colour region fills along its whole length is that region's outline
  // again, reversed with the sides swapped: it adds no constraint, and a second curve along the
  // same boundary would let an edit of one (a design's encoding, a PACEMOD wave) leave the
  // other's colours and geometry behind. A hole with several colours across (or the
  // background) is the only curve there and stays.
  bool repeatsAnOutline(const Path& path) const {
    if (ClipperLib::Orientation(path)) return false;  // an outer boundary
    const int n = static_cast<int>(path.size());
    int filler = -2;
    for (int i = 0; i < n; ++i) {
      // The region across an edge of the reversed path, as curve() sees it.
      const IntPoint& a = path[(i + 1) % n];
      const IntPoint& b = path[i];
      const int across = regionAcross(a, b, frame_.toPixel(a), frame_.toPixel(b));
      if (!isColorRegion(across) || (filler != -2 && across != filler)) return false;
      filler = across;
    }
    return filler != -2;
  }

  // Clipper's outer boundaries run clockwise on screen (y down) and holes anticlockwise: the
  // region lies on their right, so the reversed path has it on its left. The polygon is refit
  // with cubics between its breaks: corners and the vertices where the colour across changes.
  DiffusionCurve curve(const Path& path, const Color& color, double tolerance,
                       double spacing) const {
    const Path reversed(path.rbegin(), path.rend());
    const int n = static_cast<int>(reversed.size());
    std::vector<Point2> p;
    for (const IntPoint& q : reversed) p.push_back(frame_.toPixel(q));
    std::vector<Color> across;  // edge i runs from vertex i to i + 1
    for (int i = 0; i < n; ++i) {
      across.push_back(colorAcross(reversed[i], reversed[(i + 1) % n], p[i], p[(i + 1) % n]));
    }
    std::vector<int> breaks;
    std::vector<bool> corner(n, false);
    // At a smooth end of a long straight edge: the edge's direction (else zero). Such a vertex
    // is a break too, so that the edge is fitted as the exact line it is (fitted together with
    // its neighbours it bulges by up to the tolerance, and shapes that touch it overlap), with
    // the edge's direction as the tangent on both sides (a C1 join, no corner).
    std::vector<Point2> straight(n, Point2::Zero());
    for (int i = 0; i < n; ++i) {
      const Point2 in = (p[i] - p[(i + n - 1) % n]).normalized();
      const Point2 out = (p[(i + 1) % n] - p[i]).normalized();
      corner[i] = !(in.dot(out) > kCornerCosine);
      if (!corner[i] && (p[(i + 1) % n] - p[i]).norm() >= kStraightEdgeSpacings * spacing) {
        straight[i] = out;
      } else if (!corner[i] &&
                 (p[i] - p[(i + n - 1) % n]).norm() >= kStraightEdgeSpacings * spacing) {
        straight[i] = in;
      }
      const bool straight_end = straight[i] != Point2::Zero();
      if (corner[i] || straight_end || across[i] != across[(i + n - 1) % n]) breaks.push_back(i);
    }
    if (breaks.empty()) breaks = {0, n / 2};  // a smooth loop of one colour
    DiffusionCurve curve;
    curve.control_points.push_back(p[breaks[0]]);
    std::vector<ColorPoint> right;
    int segments = 0;
    for (std::size_t b = 0; b < breaks.size(); ++b) {
      const int from = breaks[b];
      const int to = b + 1 < breaks.size() ? breaks[b + 1] : breaks[0] + n;
      // Long edges are sampled densely: the fit controls its error at the points only.
      std::vector<Point2> piece = {p[from]};
      for (int i = from + 1; i <= to; ++i) {
        const Point2& a = p[(i - 1) % n];
        const Point2& b = p[i % n];
        const int steps =
            std::clamp(static_cast<int>(std::ceil((b - a).norm() / spacing)), 1, 4096);
        for (int k = 1; k <= steps; ++k)
          piece.push_back(a + (b - a) * (static_cast<double>(k) / steps));
      }
      const int added =
          fitCubics(piece, tangent(p, corner, straight, from, true),
                    tangent(p, corner, straight, to % n, false), tolerance, curve.control_points);
      right.push_back({segments + kColorStep, across[from]});
      segments += added;
      right.push_back({segments - kColorStep, across[from]});
    }
    curve.left_colors = {{0.0, color}, {static_cast<double>(segments), color}};
    curve.right_colors = reduceColorRuns(right, segments);
    return curve;
  }

 private:
  // Unit tangent at vertex v leaving it (`leaving`) or pointing back from it: one-sided at a
  // corner, along the edge at the end of a long straight edge, centred elsewhere.
  static Point2 tangent(const std::vector<Point2>& p, const std::vector<bool>& corner,
                        const std::vector<Point2>& straight, int v, bool leaving) {
    const int n = static_cast<int>(p.size());
    const Point2& next = p[(v + 1) % n];
    const Point2& previous = p[(v + n - 1) % n];
    if (corner[v]) return (leaving ? next - p[v] : previous - p[v]).normalized();
    if (straight[v] != Point2::Zero()) return leaving ? straight[v] : Point2(-straight[v]);
    const Point2 centred = (next - previous).normalized();
    return leaving ? centred : Point2(-centred);
  }

  static std::vector<const Paths*> areas(const ResolvedPicture& picture) {
    std::vector<const Paths*> all;
    for (const ColorRegion& region : picture.regions) all.push_back(&region.area);
    all.push_back(&picture.background.area);
    return all;
  }

  bool isColorRegion(int region) const {
    return region >= 0 && region < static_cast<int>(picture_.regions.size());
  }

  const Color& colorOf(int region) const {
    return isColorRegion(region) ? picture_.regions[region].color : picture_.background.color;
  }

  Color colorAcross(const IntPoint& a, const IntPoint& b, const Point2& pa,
                    const Point2& pb) const {
    return colorOf(regionAcross(a, b, pa, pb));
  }

  // The neighbour owns the same edge in the opposite direction; where the two boundaries do
  // not share vertices, a point just right of the edge's middle is located instead. -1 or the
  // background's index: no colour region.
  int regionAcross(const IntPoint& a, const IntPoint& b, const Point2& pa, const Point2& pb) const {
    const auto shared = owner_.find({a, b});
    if (shared != owner_.end()) return shared->second;
    const Point2 d = pb - pa;
    const double length = d.norm();
    if (!(length > 0.0)) return -1;
    const double offset = std::max(4.0 / frame_.unitsPerPixel(), std::min(1e-3, 0.25 * length));
    const Point2 right_normal(-d.y() / length, d.x() / length);
    return locator_.locate(frame_.toInt(0.5 * (pa + pb) + offset * right_normal));
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
  // As fine as the flattening: the refit adds at most that much to its error.
  const double tolerance = std::max(width, height) / 8192.0;
  const double spacing = std::max(width, height) / 256.0;
  for (const ColorRegion& region : picture.regions) {
    for (const Path& path : region.area) {
      if (path.size() >= 3 && !builder.repeatsAnOutline(path))
        image.curves.push_back(builder.curve(path, region.color, tolerance, spacing));
    }
  }
  return image;
}

}  // namespace io_detail
}  // namespace vicc_glyphs
