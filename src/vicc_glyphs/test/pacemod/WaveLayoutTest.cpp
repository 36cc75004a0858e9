#include <gtest/gtest.h>

#include <random>
#include <stdexcept>
#include <vector>

#include "vicc_glyphs/pacemod/polyline.hpp"
#include "vicc_glyphs/pacemod/wave_layout.hpp"

namespace vicc_glyphs {
namespace pacemod {
namespace {

void expectKnots(const WaveLayout& layout, const std::vector<WaveKnot>& expected) {
  ASSERT_EQ(layout.interior_knots.size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) {
    EXPECT_NEAR(layout.interior_knots[i].arc_length, expected[i].arc_length, 1e-12) << i;
    EXPECT_EQ(layout.interior_knots[i].multiplicity, expected[i].multiplicity) << i;
  }
}

void expectPeaks(const WaveLayout& layout, const std::vector<WavePeak>& expected) {
  ASSERT_EQ(layout.peaks.size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) {
    EXPECT_NEAR(layout.peaks[i].arc_length, expected[i].arc_length, 1e-12) << i;
    EXPECT_EQ(layout.peaks[i].sign, expected[i].sign) << i;
    EXPECT_EQ(layout.peaks[i].corner, expected[i].corner) << i;
  }
}

TEST(WaveLayoutTest, SineHasPeaksEveryHalfPeriodAndOneIntermediateSingleKnot) {
  // L = 12, 3 waves: P = 4, peaks every 2, knots every 1.
  const WaveLayout layout = waveLayout(Waveform::Sine, 3, 12.0);
  std::vector<WaveKnot> knots;
  for (int m = 1; m < 12; ++m) knots.push_back({double(m), 1});
  expectKnots(layout, knots);
  expectPeaks(layout, {{0, 1, false},
                       {2, -1, false},
                       {4, 1, false},
                       {6, -1, false},
                       {8, 1, false},
                       {10, -1, false},
                       {12, 1, false}});
  EXPECT_TRUE(layout.straight_spans.empty());
  const std::vector<double> vector = knotVector(layout);
  EXPECT_EQ(vector.size(), 4u + 11u + 4u);
  EXPECT_EQ(vector.front(), 0.0);
  EXPECT_EQ(vector.back(), 12.0);
}

TEST(WaveLayoutTest, TriangleHasTripleKnotsAtEveryCornerAndStraightStrips) {
  const WaveLayout layout = waveLayout(Waveform::Triangle, 2, 8.0);
  expectKnots(layout, {{2, 3}, {4, 3}, {6, 3}});
  expectPeaks(layout, {{0, 1, true}, {2, -1, true}, {4, 1, true}, {6, -1, true}, {8, 1, true}});
  ASSERT_EQ(layout.straight_spans.size(), 4u);
  EXPECT_EQ(layout.straight_spans[1].begin, 2.0);
  EXPECT_EQ(layout.straight_spans[1].end, 4.0);
  EXPECT_EQ(knotVector(layout).size(), 4u + 9u + 4u);
  EXPECT_EQ(knotVector(layout, true).size(), 4u + 3u + 4u);
}

TEST(WaveLayoutTest, SawtoothShiftsEverySecondCornerTowardsTheNextPeak) {
  // L = 10, 2 waves: P = 5; the low corner sits (1 - 0.1) P after each high one.
  const WaveLayout layout = waveLayout(Waveform::Sawtooth, 2, 10.0);
  expectKnots(layout, {{4.5, 3}, {5, 3}, {9.5, 3}});
  expectPeaks(layout,
              {{0, 1, true}, {4.5, -1, true}, {5, 1, true}, {9.5, -1, true}, {10, 1, true}});
  EXPECT_EQ(layout.straight_spans.size(), 4u);
}

TEST(WaveLayoutTest, RectangleHasCornerPairsAroundEachChangeOfSide) {
  // L = 8, 1 wave: half period 4, changes at 2 and 6, corners 0.5 * 0.1 * 4 = 0.2 around them;
  // plateaus 3.6 wide with knot points at their centre and 0.9 to either side.
  const WaveLayout layout = waveLayout(Waveform::Rectangle, 1, 8.0);
  expectKnots(
      layout,
      {{0.9, 1}, {1.8, 3}, {2.2, 3}, {3.1, 1}, {4, 1}, {4.9, 1}, {5.8, 3}, {6.2, 3}, {7.1, 1}});
  expectPeaks(layout, {{0, 1, false},
                       {0.9, 1, false},
                       {1.8, 1, true},
                       {2.2, -1, true},
                       {3.1, -1, false},
                       {4, -1, false},
                       {4.9, -1, false},
                       {5.8, -1, true},
                       {6.2, 1, true},
                       {7.1, 1, false},
                       {8, 1, false}});
  ASSERT_EQ(layout.straight_spans.size(), 2u);
  EXPECT_NEAR(layout.straight_spans[0].begin, 1.8, 1e-12);
  EXPECT_NEAR(layout.straight_spans[0].end, 2.2, 1e-12);
}

TEST(WaveLayoutTest, ClosedContoursGetWholeWaveCounts) {
  EXPECT_EQ(wholeWaveCount(0.3, 10.0), 3);
  EXPECT_EQ(wholeWaveCount(0.34, 10.0), 3);
  EXPECT_EQ(wholeWaveCount(0.36, 10.0), 4);
  EXPECT_EQ(wholeWaveCount(0.04, 10.0), 0);
  EXPECT_THROW(waveLayout(Waveform::Sine, 0, 10.0), std::invalid_argument);
  EXPECT_THROW(waveLayout(Waveform::Sine, 2, -1.0), std::invalid_argument);
}

TEST(WaveLayoutTest, WaveformNamesRoundTripAndSpecsAreValidated) {
  for (Waveform w : {Waveform::Sine, Waveform::Triangle, Waveform::Sawtooth, Waveform::Rectangle}) {
    EXPECT_EQ(parseWaveform(waveformName(w)), w);
  }
  EXPECT_FALSE(parseWaveform("square").has_value());
  EXPECT_EQ(validate(WaveSpec{Waveform::Sine, 0.2, 0.5}), "");
  EXPECT_NE(validate(WaveSpec{Waveform::Sine, 0.2, -0.1}).find("amplitude_mm"), std::string::npos);
  EXPECT_NE(validate(WaveSpec{Waveform::Sine, 0.0, 0.1}).find("waves_per_mm"), std::string::npos);
}

TEST(WaveLayoutTest, PeaksNearAreThoseAScanOfAllFinds) {
  // The repair rounds cap the knot points around a crossing through peaksNear: it must give
  // exactly the peaks that testing every one gives, around the closing point too.
  std::mt19937 random(5);
  for (const Waveform waveform : {Waveform::Sine, Waveform::Rectangle, Waveform::Sawtooth}) {
    for (const double length : {37.0, 1000.0 / 3.0, 4096.25}) {
      const WaveLayout layout = waveLayout(waveform, 7 + static_cast<int>(length) % 11, length);
      const double half_period = 0.5 * length / layout.wave_count;
      std::vector<double> places{0.0, length, 1e-12, length - 1e-12};
      std::uniform_real_distribution<double> along(0.0, length);
      for (int k = 0; k < 200; ++k) places.push_back(along(random));
      for (const WavePeak& peak : layout.peaks) places.push_back(peak.arc_length);
      std::vector<std::size_t> near;
      for (const double u : places) {
        for (const double window : {0.0, 1e-9, 0.3 * half_period, half_period, 2.5 * half_period,
                                    0.49 * length, 0.5 * length, length}) {
          // Windows that end exactly on a peak, too.
          for (const double w : {window, std::abs(layout.peaks[1].arc_length - u)}) {
            std::vector<std::size_t> expected;
            for (std::size_t i = 0; i < layout.peaks.size(); ++i) {
              if (cyclicDistance(layout.peaks[i].arc_length, u, length) <= w) {
                expected.push_back(i);
              }
            }
            peaksNear(layout, u, w, near);
            ASSERT_EQ(near, expected) << "L " << length << " u " << u << " window " << w;
          }
        }
      }
    }
  }
}

}  // namespace
}  // namespace pacemod
}  // namespace vicc_glyphs
