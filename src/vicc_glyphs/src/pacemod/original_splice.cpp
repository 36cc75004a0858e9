#include "vicc_glyphs/pacemod/original_splice.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "vicc_glyphs/bspline/knot_insertion.hpp"

namespace vicc_glyphs {
namespace pacemod {
namespace {

using bspline::BSplineCurve;

// A stretch of a clamped cubic between two parameters where it has full multiplicity: the de
// Boor points from the one the curve passes through at `begin` to the one at `end`, and the
// knots strictly between.
struct Part {
  double begin = 0.0;
  double end = 0.0;
  std::vector<double> interior_knots;
  std::vector<Point2> points;
  bool original = false;
};

// A curve's breakpoints, to snap parameters to (no sliver pieces): computed once per splice,
// since a wave has thousands of them and a splice snaps four parameters per run.
class Breakpoints {
 public:
  explicit Breakpoints(const BSplineCurve& curve)
      : values_(curve.breakpoints()),
        tolerance_(1e-9 * (curve.domainEnd() - curve.domainBegin())) {}

  // `u`, or the first breakpoint within a relative 1e-9 of the domain of it. Breakpoints below
  // u - 2 * tolerance cannot be within the tolerance, whatever the rounding of their distance.
  double snap(double u) const {
    for (auto it = std::lower_bound(values_.begin(), values_.end(), u - 2.0 * tolerance_);
         it != values_.end() && *it <= u + 2.0 * tolerance_; ++it) {
      if (std::abs(*it - u) <= tolerance_) return *it;
    }
    return u;
  }

 private:
  std::vector<double> values_;
  double tolerance_;
};

// The curve with each of `cuts` (snapped by the caller) at full multiplicity, as the parts
// between consecutive cuts (and the domain ends).
std::vector<Part> splitAt(const BSplineCurve& curve, std::vector<double> cuts, bool original) {
  std::sort(cuts.begin(), cuts.end());
  cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
  std::vector<double> bounds{curve.domainBegin()};
  std::vector<double> inserted;  // each cut as often as it lacks multiplicity, in one pass
  for (double u : cuts) {
    if (u <= curve.domainBegin() || u >= curve.domainEnd()) continue;
    const int missing = curve.degree() - curve.multiplicity(u);
    if (missing > 0) inserted.insert(inserted.end(), missing, u);
    bounds.push_back(u);
  }
  bounds.push_back(curve.domainEnd());
  const BSplineCurve refined = inserted.empty() ? curve : bspline::insertKnots(curve, inserted);
  const std::vector<double>& knots = refined.knots();
  const std::vector<Point2>& points = refined.controlPoints();
  std::vector<Part> parts;
  std::size_t k = 4;  // knots[0..3] are the domain begin
  int first_point = 0;
  for (std::size_t b = 1; b < bounds.size(); ++b) {
    Part part{bounds[b - 1], bounds[b], {}, {}, original};
    while (knots[k] < part.end) part.interior_knots.push_back(knots[k++]);
    // The curve passes through de Boor point (index of the bound's first copy) - 1.
    const int last_point = static_cast<int>(k) - 1;
    part.points.assign(points.begin() + first_point, points.begin() + last_point + 1);
    parts.push_back(std::move(part));
    first_point = last_point;
    k += 3;  // the bound itself, at full multiplicity
  }
  return parts;
}

bool inside(double u, const ArcInterval& interval) {
  return u > interval.begin && u < interval.end;
}

// The original's parts over `spans` (its parameters at the runs' ends), their knots mapped
// affinely onto the runs' arc-length intervals.
std::vector<Part> originalParts(const BSplineCurve& original, const std::vector<ArcInterval>& runs,
                                const std::vector<ArcInterval>& spans) {
  std::vector<double> cuts;
  for (const ArcInterval& span : spans) cuts.insert(cuts.end(), {span.begin, span.end});
  const std::vector<Part> parts = splitAt(original, cuts, true);
  std::vector<Part> joined;
  for (std::size_t r = 0; r < runs.size(); ++r) {
    Part run{runs[r].begin, runs[r].end, {}, {}, true};
    const double scale = (runs[r].end - runs[r].begin) / (spans[r].end - spans[r].begin);
    const auto map = [&](double u) { return runs[r].begin + (u - spans[r].begin) * scale; };
    for (const Part& part : parts) {  // the span may cover several parts: join them
      if (!inside(0.5 * (part.begin + part.end), spans[r])) continue;
      if (!run.points.empty()) {
        run.interior_knots.insert(run.interior_knots.end(), 3, map(part.begin));
        run.points.pop_back();
      }
      for (double knot : part.interior_knots) run.interior_knots.push_back(map(knot));
      run.points.insert(run.points.end(), part.points.begin(), part.points.end());
    }
    joined.push_back(std::move(run));
  }
  return joined;
}

// A clamped cubic from parts that follow each other on the parameter axis; where the wave and
// the original meet, the original's point is the join.
BSplineCurve joinParts(const std::vector<Part>& parts) {
  std::vector<double> knots(4, parts.front().begin);
  std::vector<Point2> points;
  for (std::size_t k = 0; k < parts.size(); ++k) {
    const Part& part = parts[k];
    if (k > 0) {
      knots.insert(knots.end(), 3, part.begin);
      if (part.original) points.back() = part.points.front();
    }
    knots.insert(knots.end(), part.interior_knots.begin(), part.interior_knots.end());
    points.insert(points.end(), part.points.begin() + (k > 0 ? 1 : 0), part.points.end());
  }
  knots.insert(knots.end(), 4, parts.back().end);
  return BSplineCurve(3, std::move(knots), std::move(points));
}

}  // namespace

std::vector<ArcInterval> flatRuns(const std::vector<double>& parameters,
                                  const std::vector<double>& translations,
                                  const std::vector<bool>& unmet) {
  const std::size_t count = parameters.size();
  if (translations.size() != count || unmet.size() != count) {
    throw std::invalid_argument("flatRuns: inputs of different lengths");
  }
  std::vector<ArcInterval> runs;
  std::size_t i = 0;
  while (i < count) {
    if (translations[i] != 0.0 || unmet[i]) {
      ++i;
      continue;
    }
    std::size_t j = i;
    while (j + 1 < count && translations[j + 1] == 0.0 && parameters[j + 1] > parameters[j]) ++j;
    std::size_t end = j;
    while (end > i && unmet[end]) --end;  // the curve must meet both ends
    // Increasing and disjoint: a run that starts behind the last one's end (a knot point moved
    // onto a corner behind it) is left out rather than made an error.
    if (end > i && (runs.empty() || parameters[i] >= runs.back().end)) {
      runs.push_back({parameters[i], parameters[end]});
    }
    i = std::max(end, i) + 1;
  }
  return runs;
}

BSplineCurve spliceOriginal(const BSplineCurve& wave, const BSplineCurve& original,
                            const bspline::ArcLengthTable& table,
                            const std::vector<ArcInterval>& runs_in) {
  std::vector<ArcInterval> runs, spans;  // spans: the runs as the original's parameters
  std::vector<double> cuts;
  const Breakpoints wave_breaks(wave), original_breaks(original);
  for (const ArcInterval& run : runs_in) {
    if (!(run.end >= run.begin) || run.begin < wave.domainBegin() || run.end > wave.domainEnd() ||
        (!runs.empty() && run.begin < runs.back().end)) {
      throw std::invalid_argument("spliceOriginal: runs must be increasing and in the domain");
    }
    const ArcInterval snapped{wave_breaks.snap(run.begin), wave_breaks.snap(run.end)};
    const ArcInterval span{original_breaks.snap(table.parameterAt(snapped.begin)),
                           original_breaks.snap(table.parameterAt(snapped.end))};
    // Shorter than the snapping tolerance on either curve: nothing to splice.
    if (!(snapped.end > snapped.begin) || !(span.end > span.begin)) continue;
    runs.push_back(snapped);
    spans.push_back(span);
    cuts.insert(cuts.end(), {snapped.begin, snapped.end});
  }
  if (runs.empty()) return wave;
  std::vector<Part> parts = originalParts(original, runs, spans);
  for (Part& part : splitAt(wave, cuts, false)) {
    const double middle = 0.5 * (part.begin + part.end);
    if (std::none_of(runs.begin(), runs.end(),
                     [&](const ArcInterval& run) { return inside(middle, run); })) {
      parts.push_back(std::move(part));
    }
  }
  std::sort(parts.begin(), parts.end(),
            [](const Part& a, const Part& b) { return a.begin < b.begin; });
  return joinParts(parts);
}

}  // namespace pacemod
}  // namespace vicc_glyphs
