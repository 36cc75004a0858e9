#include "vicc_glyphs/pacemod/wave_layout.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "vicc_glyphs/pacemod/polyline.hpp"

namespace vicc_glyphs {
namespace pacemod {
namespace {

int alternatingSign(int j) { return j % 2 == 0 ? 1 : -1; }

// Peaks at every half period; interior knots every `knots_per_half` th of a half period.
void layOutHalfPeriods(WaveLayout& layout, int knots_per_half, int multiplicity, bool corners) {
  const double half = layout.length / (2.0 * layout.wave_count);
  for (int j = 0; j <= 2 * layout.wave_count; ++j) {
    const double position = j == 2 * layout.wave_count ? layout.length : j * half;
    layout.peaks.push_back({position, alternatingSign(j), corners});
  }
  const int knot_count = 2 * layout.wave_count * knots_per_half;
  for (int m = 1; m < knot_count; ++m) {
    layout.interior_knots.push_back({m * half / knots_per_half, multiplicity});
  }
}

void layOutSawtooth(WaveLayout& layout) {
  const double period = layout.length / layout.wave_count;
  const double low = (1.0 - kSawtoothFlankFraction) * period;
  for (int j = 0; j < layout.wave_count; ++j) {
    layout.peaks.push_back({j * period, 1, true});
    layout.peaks.push_back({j * period + low, -1, true});
    if (j > 0) layout.interior_knots.push_back({j * period, 3});
    layout.interior_knots.push_back({j * period + low, 3});
  }
  layout.peaks.push_back({layout.length, 1, true});
}

// Plateau j is centred on j P/2 with knot points at its centre and a quarter of its width to
// either side; consecutive plateaus are joined by a flank between two corners.
void layOutRectangle(WaveLayout& layout) {
  const double half = layout.length / (2.0 * layout.wave_count);
  const double offset = 0.5 * kRectangleFlankFraction * half;
  const double quarter = 0.25 * (half - 2.0 * offset);
  const int last = 2 * layout.wave_count;
  for (int j = 0; j <= last; ++j) {
    const double centre = j == last ? layout.length : j * half;
    const int sign = alternatingSign(j);
    auto add = [&](double arc_length, int multiplicity) {
      layout.peaks.push_back({arc_length, sign, multiplicity == 3});
      if (arc_length > 0.0 && arc_length < layout.length) {
        layout.interior_knots.push_back({arc_length, multiplicity});
      }
    };
    if (j > 0) {
      add(centre - 0.5 * half + offset, 3);
      const std::size_t corner = layout.peaks.size() - 1;
      layout.straight_spans.push_back(
          {layout.peaks[corner - 1].arc_length, layout.peaks[corner].arc_length});
      add(centre - quarter, 1);
    }
    add(centre, 1);
    if (j < last) {
      add(centre + quarter, 1);
      add(centre + 0.5 * half - offset, 3);
    }
  }
}

}  // namespace

WaveLayout waveLayout(Waveform waveform, int wave_count, double length) {
  if (wave_count < 1) throw std::invalid_argument("waveLayout: wave count must be >= 1");
  if (!std::isfinite(length) || !(length > 0.0)) {
    throw std::invalid_argument("waveLayout: length must be finite and > 0");
  }
  WaveLayout layout;
  layout.waveform = waveform;
  layout.wave_count = wave_count;
  layout.length = length;
  switch (waveform) {
    case Waveform::Sine:
      layOutHalfPeriods(layout, 2, 1, false);
      break;
    case Waveform::Triangle:
      layOutHalfPeriods(layout, 1, 3, true);
      break;
    case Waveform::Sawtooth:
      layOutSawtooth(layout);
      break;
    case Waveform::Rectangle:
      layOutRectangle(layout);
      break;
  }
  if (waveform == Waveform::Triangle || waveform == Waveform::Sawtooth) {
    for (std::size_t i = 0; i + 1 < layout.peaks.size(); ++i) {
      layout.straight_spans.push_back({layout.peaks[i].arc_length, layout.peaks[i + 1].arc_length});
    }
  }
  return layout;
}

std::vector<double> knotVector(const WaveLayout& layout, bool single_knots) {
  std::vector<double> knots(4, 0.0);
  for (const WaveKnot& knot : layout.interior_knots) {
    knots.insert(knots.end(), single_knots ? 1 : knot.multiplicity, knot.arc_length);
  }
  knots.insert(knots.end(), 4, layout.length);
  return knots;
}

int wholeWaveCount(double waves_per_unit, double length) {
  const double waves = waves_per_unit * length;
  if (!std::isfinite(waves) || waves < 0.5) return 0;
  // Saturates instead of overflowing: callers reject counts whose period is below a pixel.
  if (waves >= std::numeric_limits<int>::max()) return std::numeric_limits<int>::max();
  return static_cast<int>(std::lround(waves));
}

void peaksNear(const WaveLayout& layout, double u, double window,
               std::vector<std::size_t>& indices) {
  indices.clear();
  const std::vector<WavePeak>& peaks = layout.peaks;
  for (const auto& [first, second] : indexRangesNear(
           peaks, u, window, layout.length, [](const WavePeak& peak) { return peak.arc_length; })) {
    for (int i = first; i < second; ++i) {
      if (cyclicDistance(peaks[i].arc_length, u, layout.length) <= window) indices.push_back(i);
    }
  }
}

}  // namespace pacemod
}  // namespace vicc_glyphs
