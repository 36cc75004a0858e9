// Spike removal on region boundaries: out-and-back runs go (also when a unit off the line),
// real sharp wedges stay, and both directions of a shared boundary lose the same vertices.
#include <gtest/gtest.h>

#include <algorithm>

#include "clipper_geometry.hpp"

namespace vicc_glyphs {
namespace io_detail {
namespace {

// A 1000-unit square whose top edge runs out to (500, -`length`) and back (the return point
// `skew` units to the side).
Path squareWithSpike(long long length, long long skew) {
  return {{0, 0}, {480, 0}, {500, -length}, {520 + skew, 0}, {1000, 0}, {1000, 1000}, {0, 1000}};
}

TEST(ClipperGeometry, SpikesGoWedgesStay) {
  // Out and back along one line: (480, 0) -> (500, -400) -> (480 + 2 * 20, 0) is a wedge, not a
  // spike; a spike returns along the same line.
  const Path spike = {{0, 0}, {500, 0}, {500, -400}, {500, 1}, {1000, 0}, {1000, 1000}, {0, 1000}};
  const Paths cleaned = withoutSpikes({spike}, 2.0);
  ASSERT_EQ(cleaned.size(), 1u);
  EXPECT_EQ(cleaned[0].size(), 5u);  // the tip and the doubled point at the base are gone
  EXPECT_EQ(std::count(cleaned[0].begin(), cleaned[0].end(), IntPoint(500, -400)), 0);
  EXPECT_NEAR(ClipperLib::Area(cleaned[0]), ClipperLib::Area(spike), 1000.0);

  // A wedge 40 units wide at its base, 400 long: its tip is far from the line through its
  // neighbours, so it stays whatever the width.
  const Path wedge = squareWithSpike(400, 0);
  EXPECT_EQ(withoutSpikes({wedge}, 2.0)[0].size(), wedge.size());
  // Repeated vertices go.
  const Path repeated = {{0, 0}, {1000, 0}, {1000, 0}, {1000, 1000}, {0, 1000}};
  EXPECT_EQ(withoutSpikes({repeated}, 2.0)[0].size(), 4u);
  // A spike that is all there is leaves nothing.
  EXPECT_TRUE(withoutSpikes({{{0, 0}, {100, 100}, {0, 0}}}, 2.0).empty());
}

TEST(ClipperGeometry, BothDirectionsOfABoundaryLoseTheSameVertices) {
  const Path spike = {{0, 0}, {500, 0}, {500, -400}, {501, 1}, {1000, 0}, {1000, 1000}, {0, 1000}};
  Path reversed = spike;
  std::reverse(reversed.begin(), reversed.end());
  Path forward = withoutSpikes({spike}, 2.0)[0];
  Path backward = withoutSpikes({reversed}, 2.0)[0];
  std::reverse(backward.begin(), backward.end());
  std::sort(forward.begin(), forward.end(), [](const IntPoint& a, const IntPoint& b) {
    return a.X != b.X ? a.X < b.X : a.Y < b.Y;
  });
  std::sort(backward.begin(), backward.end(), [](const IntPoint& a, const IntPoint& b) {
    return a.X != b.X ? a.X < b.X : a.Y < b.Y;
  });
  EXPECT_EQ(forward, backward);
  EXPECT_LT(forward.size(), spike.size());
}

}  // namespace
}  // namespace io_detail
}  // namespace vicc_glyphs
