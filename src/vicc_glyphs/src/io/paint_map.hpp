#pragma once
// The SVG painting model as a planar map: disjoint regions, each of one premultiplied RGBA
// colour, built by painting areas over it in document order (source-over compositing).
// Overlapping and abutting shapes of one paint merge into one region; translucent paint splits
// what lies below into blended regions; layers (group opacity, clip-path) are painted into
// their own map and composited. Resolving over an opaque background gives the picture's
// colour regions, from which the curves are built.

#include <vector>

#include "clipper_geometry.hpp"

namespace vicc_glyphs {
namespace io_detail {

struct PaintRegion {
  Color premultiplied = Color::Zero();
  double alpha = 0.0;
  Paths area;
  IntRect box{0, 0, 0, 0};
};

/// A region of the final, opaque picture.
struct ColorRegion {
  Color color = Color::Zero();
  Paths area;
};

struct ResolvedPicture {
  std::vector<ColorRegion> regions;  ///< disjoint, each colour once, background excluded
  ColorRegion background;            ///< what no region covers (within the canvas)
  bool painted = false;              ///< some paint (any colour) lies within the canvas
};

class PaintMap {
 public:
  /// Paints `area` (non-overlapping polygons) with `color` at opacity `alpha` in [0, 1].
  void paint(const Paths& area, const Color& color, double alpha);
  /// Paints every region of `layer` over this map, its opacity scaled by `opacity` and, when
  /// `clip` is given, restricted to it.
  void composite(const PaintMap& layer, double opacity, const Paths* clip);
  bool empty() const { return regions_.empty(); }
  /// The picture over an opaque `background`, restricted to `canvas`; regions whose colour
  /// equals the background join it.
  ResolvedPicture resolve(const Color& background, const Paths& canvas) const;

 private:
  void paintPremultiplied(const Paths& area, const Color& premultiplied, double alpha);
  void addRegion(PaintRegion region);

  std::vector<PaintRegion> regions_;
};

}  // namespace io_detail
}  // namespace vicc_glyphs
