#pragma once
// Where a periodic wave puts its knots and translated knot points along a closed contour of
// arc length L with n whole waves (period P = L / n), thesis 6.2.4.1 and Fig. 6.14B. All
// positions are arc lengths in [0, L]; the modified spline is parametrised by the original
// contour's arc length, so a knot at arc length l is the knot value l.
//
// - sine: peaks (translated knot points) at j P/2 with alternating sign, one intermediate
//   single knot between two peaks: single knots every P/4.
// - triangle: corners at j P/2 (knot multiplicity 3), straight strips between them.
// - sawtooth: corners (multiplicity 3) at j P (+) and j P + (1 - f) P (-): a slow ramp and a
//   steep flank of f P (f = kSawtoothFlankFraction); straight strips between them.
// - rectangle: plateaus centred on j P/2 (a single knot and translated knot point in their
//   middle); each change of side at P/4 + j P/2 is a straight flank between two corners
//   (multiplicity 3) a small offset w/2 before and after it (w = kRectangleFlankFraction P/2),
//   translated in opposite directions; knot points at the centre of a plateau and a quarter of
//   its width to either side keep it on the offset contour.
// Sign +1 means along the outward normal; the wave starts outward at arc length 0, and as the
// count is whole it ends there again, so the contour stays closed.

#include <cstddef>
#include <vector>

#include "vicc_glyphs/pacemod/wave_spec.hpp"

namespace vicc_glyphs {
namespace pacemod {

constexpr double kSawtoothFlankFraction = 0.1;   ///< steep flank: this fraction of a period
constexpr double kRectangleFlankFraction = 0.1;  ///< flank width: this fraction of P/2

struct WaveKnot {
  double arc_length = 0.0;
  int multiplicity = 1;  ///< 1 (smooth) or 3 (a corner: C0)
};

/// A translated knot point: the contour point at `arc_length` moves by sign * amplitude along
/// the outward normal.
struct WavePeak {
  double arc_length = 0.0;
  int sign = 1;
  bool corner = false;  ///< sits on a knot of multiplicity 3
};

struct ArcInterval {
  double begin = 0.0;
  double end = 0.0;
};

struct WaveLayout {
  Waveform waveform = Waveform::Sine;
  int wave_count = 0;
  double length = 0.0;
  std::vector<WaveKnot> interior_knots;  ///< strictly inside (0, L), increasing
  std::vector<WavePeak> peaks;           ///< increasing, first at 0 and last at L
  /// Knot spans that become straight lines between their two corners.
  std::vector<ArcInterval> straight_spans;
};

/// Throws std::invalid_argument for wave_count < 1 or a length that is not finite and > 0.
WaveLayout waveLayout(Waveform waveform, int wave_count, double length);

/// Clamped cubic knot vector over [0, L]: 0 and L four times, the interior knots with their
/// multiplicities (or all with multiplicity 1 when `single_knots`).
std::vector<double> knotVector(const WaveLayout& layout, bool single_knots = false);

/// The whole wave count for a closed contour: round(waves_per_unit * length), maybe 0.
int wholeWaveCount(double waves_per_unit, double length);

/// The peaks within `window` of arc length `u` along the closed contour (cyclicDistance of
/// their arc length and u at most `window`), as increasing indices into layout.peaks, written
/// to `indices` (cleared first): the candidates of indexRangesNear (polyline.hpp), each with the
/// test a scan of all peaks would give.
void peaksNear(const WaveLayout& layout, double u, double window,
               std::vector<std::size_t>& indices);

}  // namespace pacemod
}  // namespace vicc_glyphs
