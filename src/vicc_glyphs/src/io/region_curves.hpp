#pragma once
// Diffusion curves from a picture's colour regions: every boundary polygon of every region
// becomes one closed curve of straight segments with the region's colour on its left and, on
// its right, per edge the colour of the region across it (so colours change exactly at the
// vertices where the neighbour changes).

#include "paint_map.hpp"

namespace vicc_glyphs {
namespace io_detail {

DiffusionCurveImage regionCurves(const ResolvedPicture& picture, const IntegerFrame& frame,
                                 int width, int height);

}  // namespace io_detail
}  // namespace vicc_glyphs
