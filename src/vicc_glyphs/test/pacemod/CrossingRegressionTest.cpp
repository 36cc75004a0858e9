// Regression cases of the PACEMOD bench (bench/pacemod): the 5 crossings of the full grid after
// the Clipper-based SVG import. Every knot point next to them was already flattened by the
// polygon repair; the crossing came from the curve between knot points (a lobe's flank
// overshooting into the leaf's and the pill's thin tips, a swallowtail at the stomach's acute
// corner, a strip across a corner of the brain's small quadrilateral), so the repair widens its
// window. Each case runs the bench's configuration (512 px, 50 mm, all curves, default options)
// and checks the polygons as the bench does.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "vicc_glyphs/dci/flattening.hpp"
#include "vicc_glyphs/io/load.hpp"
#include "vicc_glyphs/io/svg_import.hpp"
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

WaveSpec specOf(const CrossingCase& c) {
  return {c.waveform, c.waves_per_10mm / 10.0, c.amplitude_mm};
}

DiffusionCurveImage benchIcon(const CrossingCase& c) {
  return loadDiffusionCurves(std::string(VICC_GLYPHS_DATA_DIR) + "/icons/" + c.icon, 512);
}

DiffusionCurveImage parseAtBenchSize(const std::string& svg) {
  SvgImportOptions options;
  options.size = 512;
  return parseSvg(svg, options);
}

// `original` waved and checked as the bench does it: all curves, 512 px = 50 mm.
struct WavedGlyph {
  DiffusionCurveImage image;
  std::vector<CurveWaveReport> reports;
  measure::GlyphCheck check;
};

WavedGlyph waveAsTheBench(const DiffusionCurveImage& original, const WaveSpec& spec) {
  WavedGlyph glyph{original, {}, {}};
  glyph.reports = applyWaves(glyph.image, selectCurves(glyph.image, {}), spec, 50.0);
  glyph.check = measure::checkGlyph(original, glyph.image, glyph.reports, spec, 512 / 50.0);
  return glyph;
}

class CrossingRegression : public ::testing::TestWithParam<CrossingCase> {};

TEST_P(CrossingRegression, WavedIconHasNoNewCrossing) {
  const WavedGlyph glyph = waveAsTheBench(benchIcon(GetParam()), specOf(GetParam()));
  for (const CurveWaveReport& r : glyph.reports) EXPECT_EQ(r.unresolved_crossings, 0) << r.curve;
  std::vector<Polyline> lines;  // as the renderer draws them
  for (const DiffusionCurve& curve : glyph.image.curves) lines.push_back(flattenCurve(curve));
  for (const Crossing& x : findCrossings(lines)) {
    ADD_FAILURE() << "curve " << x.a.line << " crosses curve " << x.b.line << " near ("
                  << crossingPoint(lines, x).transpose() << ")";
  }
  EXPECT_EQ(glyph.check.new_crossings, 0);
  EXPECT_EQ(glyph.check.new_subpixel_loops, 0);
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

// Contours that touch: two reels side by side that touch each other and sit on the camera's
// body (like Bootstrap's camera-reels-fill). Any re-fit crosses at the touching points, so the
// repair used to flatten the waves around them further and further and still left 8 crossings
// (sine, 2 waves/10 mm, 0.4 mm); with the original kept where the knot points are flat, the
// waves stay on most of the contours and nothing crosses.
TEST(TouchingContours, WavesStopAtTheTouchingPointsWithoutCrossing) {
  const std::string svg =
      "<svg xmlns='http://www.w3.org/2000/svg' viewBox='0 0 16 16'>"
      "<path d='M6 3a3 3 0 1 1-6 0 3 3 0 0 1 6 0'/><path d='M12 3a3 3 0 1 1-6 0 3 3 0 0 1 6 0'/>"
      "<path d='M2 6h12a2 2 0 0 1 2 2v6a2 2 0 0 1-2 2H2a2 2 0 0 1-2-2V8a2 2 0 0 1 2-2z'/></svg>";
  const DiffusionCurveImage original = parseAtBenchSize(svg);
  ASSERT_EQ(original.curves.size(), 3u);
  const WavedGlyph glyph = waveAsTheBench(original, {Waveform::Sine, 0.2, 0.4});
  for (const CurveWaveReport& r : glyph.reports) EXPECT_EQ(r.unresolved_crossings, 0) << r.curve;
  EXPECT_EQ(glyph.check.new_crossings, 0);
  int knot_points = 0;
  for (const CurveWaveReport& r : glyph.reports) knot_points += r.knot_points;
  EXPECT_LT(glyph.check.reduced_peaks, knot_points / 4) << "of " << knot_points;
}

// Sharp tips (strips): a knot point just before a tip whose own offset point falls past the
// tip's bisector (inside the angle) used to keep its full amplitude whenever the grid field's
// pixel of slack let it through the skeleton guard. Its lobe then crossed over beyond the tip's
// other side: the bench measured 1.02 px for a 4.10 px lobe at the lightning bolt's lower tip,
// 0.64 px for a 1.02 px one at a star's tip. Near a corner the bisector is the skeleton, so the
// half-space test is done exactly there: such knot points are reported ("corner"; since the
// guard's slack is 5 % of the amplitude instead of a grid pixel it catches the lightning bolt's
// itself: "skeleton") and every lobe is within 10 % of what was applied.
class SharpTip : public ::testing::TestWithParam<CrossingCase> {};

TEST_P(SharpTip, LobesBesideATipStayOnTheirSideOfIt) {
  const WavedGlyph glyph = waveAsTheBench(benchIcon(GetParam()), specOf(GetParam()));
  const measure::GlyphCheck& check = glyph.check;
  EXPECT_EQ(check.full_lobes_ok, check.full_lobes);
  EXPECT_EQ(check.reduced_lobes_ok, check.reduced_lobes);
  for (const std::string& failure : check.failures) ADD_FAILURE() << failure;
  EXPECT_EQ(check.new_crossings, 0);
  int limited = 0;  // by the prevention itself, not by the polygon check's repair
  for (const CurveWaveReport& r : glyph.reports) {
    for (const PeakReduction& reduction : r.reductions) limited += reduction.reason != "crossing";
  }
  EXPECT_GT(limited, 0);
}

INSTANTIATE_TEST_SUITE_P(
    BenchGrid, SharpTip,
    ::testing::Values(CrossingCase{"lightning-bolt.svg", Waveform::Sawtooth, 8, 0.4},
                      CrossingCase{"star.svg", Waveform::Sawtooth, 12, 0.1},
                      CrossingCase{"pine-tree.svg", Waveform::Sawtooth, 12, 0.1}),
    [](const ::testing::TestParamInfo<CrossingCase>& info) {
      std::string icon = info.param.icon;
      icon = icon.substr(0, icon.find('.'));
      std::replace(icon.begin(), icon.end(), '-', '_');
      return icon + "_" + waveformName(info.param.waveform);
    });

// Strips around round ends: a snowflake whose six arms (0.57 units of straight side) end in
// half circles of radius 0.25 units of a 16-unit icon, like those of Bootstrap's cloud-snow-fill.
// At 2 waves/10 mm a sawtooth strip from an arm's side to the concave corner between two arms
// passes around an arm's end; kept whole because it ends at an icon corner, its one cubic cut
// the end by up to 1.8 px at an amplitude of 1.02 px: the bench counted 8 + 8 lobes for 7 waves
// there, and here 3 of 14 lobes fail and the count is wrong. Such a strip is split where its
// deviation reaches half its offset.
TEST(RoundArmEnds, SawtoothStripsFollowThemWithTheRequestedCount) {
  const std::string svg =
      "<svg xmlns='http://www.w3.org/2000/svg' viewBox='0 0 16 16'><path d='M8.25 7.567"
      " L8.25 7 A.25 .25 0 0 0 7.75 7 L7.75 7.567 L7.259 7.283 A.25 .25 0 0 0 7.009 7.717"
      " L7.5 8 L7.009 8.283 A.25 .25 0 0 0 7.259 8.717 L7.75 8.433 L7.75 9"
      " A.25 .25 0 0 0 8.25 9 L8.25 8.433 L8.741 8.717 A.25 .25 0 0 0 8.991 8.283 L8.5 8"
      " L8.991 7.717 A.25 .25 0 0 0 8.741 7.283 Z'/></svg>";
  const DiffusionCurveImage original = parseAtBenchSize(svg);
  ASSERT_EQ(original.curves.size(), 1u);
  for (double amplitude_mm : {0.1, 0.4}) {
    const measure::GlyphCheck check =
        waveAsTheBench(original, {Waveform::Sawtooth, 0.2, amplitude_mm}).check;
    EXPECT_EQ(check.unreduced_count_ok, check.unreduced_contours) << amplitude_mm << " mm";
    EXPECT_EQ(check.full_lobes_ok, check.full_lobes) << amplitude_mm << " mm";
    for (const std::string& failure : check.failures) ADD_FAILURE() << failure;
    EXPECT_EQ(check.new_crossings, 0);
  }
}

}  // namespace
}  // namespace pacemod
}  // namespace vicc_glyphs
