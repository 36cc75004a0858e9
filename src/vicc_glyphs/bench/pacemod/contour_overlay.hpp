#pragma once
// A picture of a waved glyph for hunting the bench's failures: the original curves (grey), the
// modified ones (red), the knot points with the amplitude applied (blue: full, orange: reduced)
// and text lines, as an SVG (view it with any browser or rsvg-convert).

#include <string>
#include <vector>

#include "vicc_glyphs/dci/diffusion_curve.hpp"
#include "vicc_glyphs/pacemod/periodic_waves.hpp"

namespace vicc_glyphs {
namespace pacemod {
namespace measure {

/// Writes the overlay to `path`; `notes` are printed in the top left corner, `marks` circled.
/// Returns false when the file cannot be written.
bool writeContourOverlay(const std::string& path, const DiffusionCurveImage& original,
                         const DiffusionCurveImage& modified,
                         const std::vector<CurveWaveReport>& reports, const WaveSpec& spec,
                         double px_per_mm, const std::vector<std::string>& notes,
                         const std::vector<Point2>& marks);

}  // namespace measure
}  // namespace pacemod
}  // namespace vicc_glyphs
