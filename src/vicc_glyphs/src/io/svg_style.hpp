#pragma once
// The presentation properties the importer uses, with SVG inheritance: fill (attribute or
// style="fill:..."), fill-rule, display and visibility. Other properties are ignored.

#include <tinyxml2.h>

#include <optional>

#include "fill_regions.hpp"

namespace vicc_glyphs {
namespace io_detail {

struct SvgStyle {
  std::optional<Color> fill = Color(0, 0, 0);  ///< nullopt: fill="none"; SVG default is black
  FillRule rule = FillRule::kNonZero;
  bool displayed = true;  ///< false for display:none (the subtree is skipped)
  bool visible = true;    ///< false for visibility:hidden (inherited, can be overridden)
};

/// The style of `element` given its parent's; style="" declarations win over attributes.
/// Throws std::invalid_argument for values it cannot parse.
SvgStyle cascadeStyle(const tinyxml2::XMLElement& element, const SvgStyle& parent);

}  // namespace io_detail
}  // namespace vicc_glyphs
