#include "vicc_glyphs/dci/flattening.hpp"

#include <algorithm>
#include <cmath>

namespace vicc_glyphs {

namespace {

constexpr double kFoldTurnCosine = -0.5;  // the curve turns by more than 120 degrees

// The first non-zero difference from a segment's end point towards its other points.
Point2 tangentAway(const Point2& end, const Point2& p1, const Point2& p2, const Point2& p3) {
  for (const Point2* p : {&p1, &p2, &p3}) {
    const Point2 d = *p - end;
    if (d.norm() > 1e-12) return d;
  }
  return Point2::Zero();
}

}  // namespace

bool meetAtFold(const Point2* before, const Point2* after) {
  const Point2 incoming = -tangentAway(before[3], before[2], before[1], before[0]);
  const Point2 outgoing = tangentAway(after[0], after[1], after[2], after[3]);
  const double lengths = incoming.norm() * outgoing.norm();
  return lengths > 0.0 && incoming.dot(outgoing) < kFoldTurnCosine * lengths;
}

std::vector<char> segmentsBesideFolds(const std::vector<Point2>& chain) {
  const int segments =
      chain.size() < 4 || (chain.size() - 1) % 3 != 0 ? 0 : static_cast<int>(chain.size() - 1) / 3;
  std::vector<char> beside(segments, 0);
  if (segments == 0) return beside;
  const bool closed = (chain.front() - chain.back()).norm() < 1e-9;
  // Each join once: segment k - 1 meets segment k (and the last the first on a closed chain).
  for (int k = closed ? 0 : 1; k < segments; ++k) {
    const int previous = k > 0 ? k - 1 : segments - 1;
    if (meetAtFold(&chain[3 * previous], &chain[3 * k])) beside[previous] = beside[k] = 1;
  }
  return beside;
}

bool segmentBesideFold(const DiffusionCurve& curve, int k) {
  const std::vector<char> beside = segmentsBesideFolds(curve.control_points);
  return k >= 0 && k < static_cast<int>(beside.size()) && beside[k];
}

int flatteningPieces(const Point2* b, bool beside_fold, const Flattening& flattening) {
  const double bend =
      std::max((b[0] - 2.0 * b[1] + b[2]).norm(), (b[1] - 2.0 * b[2] + b[3]).norm());
  const double polygon = (b[1] - b[0]).norm() + (b[2] - b[1]).norm() + (b[3] - b[2]).norm();
  const double by_flatness = std::sqrt(0.75 * bend / flattening.tolerance);
  const double by_length = polygon / flattening.max_piece_length;
  if (!std::isfinite(bend) || !std::isfinite(polygon)) return 1;
  const double at_least = beside_fold ? std::max(1, flattening.pieces_beside_fold) : 1;
  const double pieces = std::ceil(std::max({at_least, by_flatness, by_length}));
  return static_cast<int>(std::min(pieces, static_cast<double>(flattening.max_pieces)));
}

std::vector<Point2> flattenCurve(const DiffusionCurve& curve, std::vector<double>* positions,
                                 const Flattening& flattening) {
  std::vector<Point2> points;
  if (positions) positions->clear();
  const int segments = curve.segmentCount();
  const std::vector<char> beside_fold = segmentsBesideFolds(curve.control_points);
  for (int k = 0; k < segments; ++k) {
    const Point2* b = &curve.control_points[3 * k];
    if (k == 0) {
      points.push_back(b[0]);
      if (positions) positions->push_back(0.0);
    }
    const int pieces = flatteningPieces(b, beside_fold[k], flattening);
    for (int p = 1; p <= pieces; ++p) {
      const double t = static_cast<double>(p) / pieces;
      points.push_back(p == pieces ? b[3] : bezierPoint(b, t));
      if (positions) positions->push_back(k + t);
    }
  }
  return points;
}

}  // namespace vicc_glyphs
