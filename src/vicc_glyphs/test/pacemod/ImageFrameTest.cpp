// Curves carried out of the image frame by a modification (pacemod/image_frame.hpp).
#include <gtest/gtest.h>

#include "../support/straight_chain.hpp"
#include "vicc_glyphs/pacemod/image_frame.hpp"

namespace vicc_glyphs {
namespace pacemod {
namespace {

DiffusionCurve square(double x0, double y0, double side) {
  DiffusionCurve curve;
  curve.control_points = test::closedStraightChain(
      {Point2(x0, y0), Point2(x0 + side, y0), Point2(x0 + side, y0 + side), Point2(x0, y0 + side)});
  return curve;
}

DiffusionCurveImage imageOf(std::vector<DiffusionCurve> curves) {
  DiffusionCurveImage image;
  image.width = 100;
  image.height = 80;
  image.curves = std::move(curves);
  return image;
}

TEST(ImageFrameTest, ReachIsTheLargestOvershootOfAnySide) {
  EXPECT_NEAR(reachBeyondFrame(square(10, 10, 20), 100, 80), -10.0, 1e-9);
  EXPECT_NEAR(reachBeyondFrame(square(90, 10, 20), 100, 80), 10.0, 1e-9);  // right
  EXPECT_NEAR(reachBeyondFrame(square(10, 63, 20), 100, 80), 3.0, 1e-9);   // bottom
  EXPECT_NEAR(reachBeyondFrame(square(-4, 10, 20), 100, 80), 4.0, 1e-9);   // left
}

TEST(ImageFrameTest, OnlyCurvesThatWereInsideAndNowReachOutAreReported) {
  const DiffusionCurveImage before =
      imageOf({square(10, 10, 20), square(50, 10, 20), square(-10, 10, 20)});
  // Curve 0 moves 0.4 px out (within half a pixel), curve 1 moves 2 px out, curve 2 was out.
  const DiffusionCurveImage after =
      imageOf({square(-0.4, 10, 20), square(82, 10, 20), square(-12, 10, 20)});
  EXPECT_EQ(curveCarriedOutOfFrame(before, after, {0, 1, 2}), std::optional<int>(1));
  EXPECT_EQ(curveCarriedOutOfFrame(before, after, {0, 2}), std::nullopt);
  EXPECT_EQ(curveCarriedOutOfFrame(before, after, {5}), std::nullopt);  // no such curve
}

}  // namespace
}  // namespace pacemod
}  // namespace vicc_glyphs
