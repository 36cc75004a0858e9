#pragma once
// The presentation properties the importer uses, with SVG inheritance and the CSS cascade
// (presentation attributes < <style> rules < style=""): fill and stroke paints with their
// opacities, fill-rule, the stroke geometry, color (for currentColor), display, visibility,
// clip-rule, and the non-inherited opacity, clip-path, mask and filter. Properties that would
// change the picture but are not implemented (markers, vector-effect, paint-order,
// mix-blend-mode, CSS transform) are recorded so that the importer can name them.
// Properties that do not change a filled or stroked shape (fonts, ...) are ignored.

#include <tinyxml2.h>

#include <optional>
#include <string>

#include "svg_css.hpp"
#include "svg_stroke.hpp"

namespace vicc_glyphs {
namespace io_detail {

struct SvgPaint {
  enum class Kind { kNone, kColor, kCurrentColor, kReference };
  Kind kind = Kind::kNone;
  Color color = Color::Zero();
  std::string reference;  ///< element id of url(#id)
};

struct SvgStyle {
  SvgPaint fill{SvgPaint::Kind::kColor, Color::Zero(), {}};  ///< SVG default: black
  double fill_opacity = 1.0;
  FillRule rule = FillRule::kNonZero;
  SvgPaint stroke;  ///< SVG default: none
  double stroke_opacity = 1.0;
  StrokeGeometry stroke_geometry;
  Color color = Color::Zero();  ///< the value of currentColor
  FillRule clip_rule = FillRule::kNonZero;
  bool displayed = true;  ///< false for display:none (the subtree is skipped)
  bool visible = true;    ///< false for visibility:hidden (inherited, can be overridden)
  // Not inherited:
  double opacity = 1.0;
  std::string clip_path;    ///< element id of clip-path: url(#id), empty for none
  std::string mask;         ///< raw value when not none (unsupported)
  std::string filter;       ///< raw value when not none (unsupported)
  std::string unsupported;  ///< "name: value" of an unimplemented property set on this element
};

/// The style of `element` given its parent's. Throws std::invalid_argument for values it
/// cannot parse.
SvgStyle cascadeStyle(const tinyxml2::XMLElement& element, const SvgStyle& parent,
                      const StyleSheet& sheet);

/// The colour a paint stands for with this style's `color`; nullopt for none or a reference.
std::optional<Color> paintColor(const SvgPaint& paint, const SvgStyle& style);

}  // namespace io_detail
}  // namespace vicc_glyphs
