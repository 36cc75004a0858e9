// The corner lookups by arc length (contour_corners.hpp) against looking at every corner.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <set>
#include <vector>

#include "vicc_glyphs/pacemod/contour_corners.hpp"
#include "vicc_glyphs/pacemod/polyline.hpp"

namespace vicc_glyphs {
namespace pacemod {
namespace {

// Corners at the given arc lengths (increasing, in [0, length)); only the arc length matters.
std::vector<ContourCorner> cornersAt(const std::vector<double>& arc_lengths) {
  std::vector<ContourCorner> corners(arc_lengths.size());
  for (std::size_t i = 0; i < arc_lengths.size(); ++i) corners[i].arc_length = arc_lengths[i];
  return corners;
}

// `count` corners at distinct random arc lengths in [0, length), one of them at 0 if `closing`,
// all at whole numbers if `whole`.
std::vector<ContourCorner> randomCorners(std::mt19937& random, int count, double length,
                                         bool closing, bool whole) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::set<double> arcs;
  if (closing) arcs.insert(0.0);
  while (static_cast<int>(arcs.size()) < count) {
    arcs.insert(whole ? std::floor(length * unit(random)) : length * unit(random));
  }
  return cornersAt({arcs.begin(), arcs.end()});
}

std::vector<int> visited(const std::vector<ContourCorner>& corners, double l, double reach,
                         double length) {
  std::vector<int> indices;
  forEachCornerNear(corners, l, reach, length, [&](int c) { indices.push_back(c); });
  return indices;
}

// The old loop of the offset fit: every corner, the closing one also at `length`.
int nearestByScan(const std::vector<ContourCorner>& corners, double l, double length) {
  int best = -1;
  double nearest = 0.0;
  for (std::size_t c = 0; c < corners.size(); ++c) {
    const double at =
        corners[c].arc_length == 0.0 && l > 0.5 * length ? length : corners[c].arc_length;
    if (best < 0 || std::abs(l - at) < nearest) {
      best = static_cast<int>(c);
      nearest = std::abs(l - at);
    }
  }
  return best;
}

TEST(ContourCornersTest, CornersNearAnArcLengthAreEveryOneWithinTheReachAcrossTheClosingPoint) {
  const double length = 100.0;
  const std::vector<ContourCorner> corners = cornersAt({0.0, 3.0, 10.0, 10.5, 50.0, 97.0, 99.5});
  EXPECT_EQ(visited(corners, 10.2, 0.4, length), (std::vector<int>{2, 3}));
  EXPECT_EQ(visited(corners, 30.0, 5.0, length), (std::vector<int>{}));
  // Around the closing point: the corners at 97 and 99.5 and those at 0 and 3, by index.
  EXPECT_EQ(visited(corners, 99.0, 4.0, length), (std::vector<int>{0, 1, 5, 6}));
  EXPECT_EQ(visited(corners, 1.0, 2.5, length), (std::vector<int>{0, 1, 6}));
  // Half the contour or more (and a NaN reach): all of them.
  EXPECT_EQ(visited(corners, 20.0, 50.0, length).size(), corners.size());
  EXPECT_EQ(visited(corners, 20.0, NAN, length).size(), corners.size());
  EXPECT_TRUE(visited({}, 20.0, 5.0, length).empty());

  std::mt19937 random(3);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int trial = 0; trial < 200; ++trial) {
    const std::vector<ContourCorner> random_corners =
        randomCorners(random, 1 + trial % 40, length, trial % 2 == 0, false);
    for (int query = 0; query < 20; ++query) {
      const double l = length * unit(random), reach = 30.0 * unit(random) * unit(random);
      std::vector<int> expected;
      for (std::size_t c = 0; c < random_corners.size(); ++c) {
        if (cyclicDistance(l, random_corners[c].arc_length, length) <= reach) {
          expected.push_back(static_cast<int>(c));
        }
      }
      // Every corner within the reach, by increasing index, each once, and none far beyond it.
      const std::vector<int> got = visited(random_corners, l, reach, length);
      std::vector<int> within;
      for (std::size_t k = 0; k < got.size(); ++k) {
        if (k > 0) {
          ASSERT_LT(got[k - 1], got[k]);
        }
        const double distance = cyclicDistance(l, random_corners[got[k]].arc_length, length);
        EXPECT_LE(distance, reach + 1e-6);
        if (distance <= reach) within.push_back(got[k]);
      }
      EXPECT_EQ(within, expected) << "l " << l << " reach " << reach;
    }
  }
}

int nearestCorner(const std::vector<ContourCorner>& corners, double l, double length) {
  return nearestCorners(corners, {l}, length).front();
}

TEST(ContourCornersTest, NearestCornersAreThoseTheScanOfAllCornersFinds) {
  const double length = 100.0;
  const std::vector<ContourCorner> corners = cornersAt({0.0, 20.0, 40.0, 90.0});
  EXPECT_EQ(nearestCorner(corners, 30.0, length), 1);  // a tie: the lower index
  EXPECT_EQ(nearestCorner(corners, 96.0, length), 0);  // the closing corner, at 100
  EXPECT_EQ(nearestCorner(corners, 94.0, length), 3);
  EXPECT_EQ(nearestCorner(corners, 95.0, length), 0);  // a tie across the closing point
  EXPECT_EQ(nearestCorner(corners, 4.0, length), 0);
  EXPECT_EQ(nearestCorner({}, 4.0, length), -1);
  // Without a closing corner the distance does not wrap: the one at 10 for l = 99.
  EXPECT_EQ(nearestCorner(cornersAt({10.0, 60.0}), 99.0, length), 1);

  std::mt19937 random(11);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int trial = 0; trial < 300; ++trial) {
    // Whole numbers now and then, so that ties occur.
    const std::vector<ContourCorner> random_corners =
        randomCorners(random, 1 + trial % 25, length, trial % 3 == 0, trial % 2 == 1);
    // Increasing arc lengths (the sweep), then a few out of order.
    std::vector<double> ls;
    for (int query = 0; query <= 100; ++query)
      ls.push_back(trial % 2 ? query : length * unit(random));
    if (trial % 2 == 0) std::sort(ls.begin(), ls.begin() + 80);
    const std::vector<int> nearest = nearestCorners(random_corners, ls, length);
    for (std::size_t k = 0; k < ls.size(); ++k) {
      ASSERT_EQ(nearest[k], nearestByScan(random_corners, ls[k], length))
          << "l " << ls[k] << " trial " << trial;
    }
  }
}

}  // namespace
}  // namespace pacemod
}  // namespace vicc_glyphs
