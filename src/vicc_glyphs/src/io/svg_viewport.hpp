#pragma once
// The root viewport of an SVG: the viewBox (or 0 0 width height) mapped to pixels, scaled so
// that the image is `size` pixels wide (0: one pixel per user unit), within kMaxSvgPixels.

#include <tinyxml2.h>

#include "svg_transform.hpp"

namespace vicc_glyphs {
namespace io_detail {

struct SvgViewport {
  Affine2 user_to_pixels = Affine2::Identity();
  int width = 0;
  int height = 0;
};

/// preserveAspectRatio is not needed: the image takes the viewBox's aspect. Throws
/// std::invalid_argument for a missing or non-positive size and for too many pixels.
SvgViewport svgViewport(const tinyxml2::XMLElement& root, int size);

}  // namespace io_detail
}  // namespace vicc_glyphs
