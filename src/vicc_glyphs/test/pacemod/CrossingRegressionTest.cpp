// Regression cases of the PACEMOD bench (bench/pacemod): the 5 crossings of the full grid after
// the Clipper-based SVG import. Every knot point next to them was already flattened by the
// polygon repair; the crossing came from the curve between knot points (a lobe's flank
// overshooting into the leaf's and the pill's thin tips, a swallowtail at the stomach's acute
// corner, a strip across a corner of the brain's small quadrilateral), so the repair widens its
// window. Each case runs the bench's configuration (512 px, 50 mm, all curves, default options)
// and checks the polygons as the bench does.
#include <gtest/gtest.h>

#include <string>

#include "vicc_glyphs/io/load.hpp"
#include "vicc_glyphs/pacemod/curve_selection.hpp"
#include "vicc_glyphs/pacemod/periodic_waves.hpp"
#include "vicc_glyphs/pacemod/polygon_crossings.hpp"
#include "vicc_glyphs/pacemod/polyline.hpp"
#include "wave_check.hpp"

namespace vicc_glyphs {
namespace pacemod {
namespace {

struct CrossingCase {
  const char* icon;
  Waveform waveform;
  double waves_per_10mm;
  double amplitude_mm;
};

class CrossingRegression : public ::testing::TestWithParam<CrossingCase> {};

TEST_P(CrossingRegression, WavedIconHasNoNewCrossing) {
  const CrossingCase& c = GetParam();
  const DiffusionCurveImage original =
      loadDiffusionCurves(std::string(VICC_GLYPHS_DATA_DIR) + "/icons/" + c.icon, 512);
  DiffusionCurveImage image = original;
  const WaveSpec spec{c.waveform, c.waves_per_10mm / 10.0, c.amplitude_mm};
  const std::vector<CurveWaveReport> reports =
      applyWaves(image, selectCurves(image, {}), spec, 50.0);
  for (const CurveWaveReport& r : reports) EXPECT_EQ(r.unresolved_crossings, 0) << r.curve;
  std::vector<Polyline> lines;
  for (const DiffusionCurve& curve : image.curves) lines.push_back(sampleCurve(curve, 16));
  for (const Crossing& x : findCrossings(lines)) {
    ADD_FAILURE() << "curve " << x.a.line << " at segment " << x.a.segment / 16.0
                  << " crosses curve " << x.b.line << " at segment " << x.b.segment / 16.0
                  << " near (" << lines[x.a.line][x.a.segment].transpose() << ")";
  }
  const measure::GlyphCheck check = measure::checkGlyph(original, image, reports, spec, 512 / 50.0);
  EXPECT_EQ(check.new_crossings, 0);
}

INSTANTIATE_TEST_SUITE_P(BenchGrid, CrossingRegression,
                         ::testing::Values(CrossingCase{"leaf.svg", Waveform::Sine, 8, 1.2},
                                           CrossingCase{"stomach.svg", Waveform::Sine, 8, 1.2},
                                           CrossingCase{"pill.svg", Waveform::Sine, 12, 1.2},
                                           CrossingCase{"brain.svg", Waveform::Sawtooth, 4, 1.2}),
                         [](const ::testing::TestParamInfo<CrossingCase>& info) {
                           std::string icon = info.param.icon;
                           return icon.substr(0, icon.find('.')) + "_" +
                                  waveformName(info.param.waveform);
                         });

}  // namespace
}  // namespace pacemod
}  // namespace vicc_glyphs
