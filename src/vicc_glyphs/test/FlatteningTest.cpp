// How curves become the straight pieces that the renderer draws and the polygon checks search.
#include <gtest/gtest.h>

#include <cmath>

#include "vicc_glyphs/dci/flattening.hpp"

using namespace vicc_glyphs;

namespace {

// The largest distance of the Bezier segment from the chords of its flattening (sampled).
double largestChordDistance(const Point2* b, int pieces) {
  double worst = 0.0;
  for (int p = 0; p < pieces; ++p) {
    const Point2 a = bezierPoint(b, double(p) / pieces), c = bezierPoint(b, double(p + 1) / pieces);
    for (int k = 1; k < 20; ++k) {
      const double t = (p + k / 20.0) / pieces;
      const Point2 q = bezierPoint(b, t);
      const double s = std::clamp((q - a).dot(c - a) / (c - a).squaredNorm(), 0.0, 1.0);
      worst = std::max(worst, (q - (a + s * (c - a))).norm());
    }
  }
  return worst;
}

}  // namespace

TEST(Flattening, AStraightSegmentIsCutIntoPiecesOfAtMostTwoPixels) {
  const Point2 b[4] = {{0, 0}, {3, 0}, {6, 0}, {9, 0}};
  EXPECT_EQ(flatteningPieces(b, false), 5);  // 9 px / 2 px, rounded up
  const Point2 dot[4] = {{1, 1}, {1, 1}, {1, 1}, {1, 1}};
  EXPECT_EQ(flatteningPieces(dot, false), 1);
}

TEST(Flattening, ABentSegmentStaysWithinTheToleranceOfItsChords) {
  const Point2 b[4] = {{0, 0}, {0, 10}, {10, 10}, {10, 0}};
  const int pieces = flatteningPieces(b, false);
  // 0.75 * bend / n^2 <= 0.02 with bend = |(0,0) - 2 (0,10) + (10,10)| = 14.14: n >= 23.03.
  EXPECT_EQ(pieces, 24);
  EXPECT_LE(largestChordDistance(b, pieces), 0.02);
  EXPECT_GT(largestChordDistance(b, pieces / 2), 0.02);  // half as many would not do
}

TEST(Flattening, SegmentsBesideAFoldGetSixteenPiecesAtLeast) {
  const Point2 in[4] = {{0, 0}, {0.1, 0.05}, {0.2, 0.1}, {0.3, 0.1}};
  const Point2 back[4] = {{0.3, 0.1}, {0.2, 0.12}, {0.1, 0.15}, {0, 0.2}};  // turns ~170 deg
  const Point2 on[4] = {{0.3, 0.1}, {0.3, 0.2}, {0.3, 0.3}, {0.3, 0.4}};    // turns ~90 deg
  EXPECT_TRUE(meetAtFold(in, back));
  EXPECT_FALSE(meetAtFold(in, on));
  EXPECT_EQ(flatteningPieces(back, true), 16);
  EXPECT_EQ(flatteningPieces(back, false), 1);

  DiffusionCurve curve;
  curve.control_points = {in[0], in[1], in[2], in[3], back[1], back[2], back[3]};
  EXPECT_TRUE(segmentBesideFold(curve, 0));
  EXPECT_TRUE(segmentBesideFold(curve, 1));
  std::vector<double> positions;
  const std::vector<Point2> line = flattenCurve(curve, &positions);
  ASSERT_EQ(line.size(), 33u);  // 16 + 16 pieces
  EXPECT_EQ(positions.size(), line.size());
  EXPECT_DOUBLE_EQ(positions[16], 1.0);
  EXPECT_EQ(line[16], in[3]);
  EXPECT_EQ(line.back(), back[3]);
}

TEST(Flattening, NonFiniteControlPointsGiveOnePiece) {
  const Point2 b[4] = {{0, 0}, {NAN, 0}, {1, 1}, {2, 2}};
  EXPECT_EQ(flatteningPieces(b, true), 1);
}
