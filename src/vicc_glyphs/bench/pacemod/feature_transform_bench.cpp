// Chooses the skeleton guard's nearest-point method by measurement: for every icon of
// data/icons at 512 px, the CPU time to build NearestCurvePoint with the bucketed segments,
// OpenCV's labelled distance transform and Maurer's exact transform, the time of 20000 queries
// at random points and of 20000 at 0.1-1.2 mm from the curves (where the guard asks), and the
// error of the distance to the returned point against the exact distance to the curves'
// polylines at the random points.
// Usage: vicc_glyphs_feature_transform_bench [ICON_DIR] (default: the vendored MDI icons)

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include "bench_timing.hpp"
#include "vicc_common/command_line.hpp"
#include "vicc_glyphs/io/load.hpp"
#include "vicc_glyphs/pacemod/nearest_curve_point.hpp"
#include "vicc_glyphs/pacemod/periodic_waves.hpp"
#include "vicc_glyphs/pacemod/polyline.hpp"

namespace fs = std::filesystem;
using namespace vicc_glyphs;
using namespace vicc_glyphs::pacemod;

namespace {

struct Result {
  std::vector<double> build_ms;
  std::vector<double> random_query_ms;
  std::vector<double> near_query_ms;
  double error_sum = 0.0;
  double error_max = 0.0;
  long queries = 0;
};

// Points 0.1-1.2 mm (at 512 px for 50 mm) from random polyline vertices, off to either side.
std::vector<Point2> pointsNearTheCurves(const std::vector<Polyline>& lines) {
  std::mt19937 random(11);
  std::vector<Point2> points;
  std::uniform_real_distribution<double> distance(1.024, 12.3), angle(0.0, 2.0 * M_PI);
  while (points.size() < 20000) {
    const Polyline& line = lines[random() % lines.size()];
    if (line.empty()) continue;
    const double a = angle(random);
    points.push_back(line[random() % line.size()] +
                     distance(random) * Point2(std::cos(a), std::sin(a)));
  }
  return points;
}

template <class Query>
double queryMilliseconds(const std::vector<Point2>& points, Query&& query) {
  double sum = 0.0;
  const double start = bench::threadCpuMilliseconds();
  for (const Point2& p : points) sum += query(p).x();
  const double elapsed = bench::threadCpuMilliseconds() - start;
  if (!std::isfinite(sum)) std::printf(" ");  // keeps the queries from being optimised away
  return elapsed;
}

void measure(const std::vector<Polyline>& lines, NearestPointMethod method, Result& result) {
  std::vector<double> times;
  for (int repeat = 0; repeat < 5; ++repeat) {
    const double start = bench::threadCpuMilliseconds();
    const NearestCurvePoint field(lines, 512, 512, 1.0, method);
    times.push_back(bench::threadCpuMilliseconds() - start);
  }
  result.build_ms.push_back(bench::median(times));
  const NearestCurvePoint field(lines, 512, 512, 1.0, method);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> coordinate(0.0, 512.0);
  std::vector<Point2> anywhere;
  for (int i = 0; i < 20000; ++i) anywhere.emplace_back(coordinate(random), coordinate(random));
  const auto nearest = [&](const Point2& p) { return field.nearest(p); };
  result.random_query_ms.push_back(queryMilliseconds(anywhere, nearest));
  result.near_query_ms.push_back(queryMilliseconds(pointsNearTheCurves(lines), nearest));
  for (const Point2& q : anywhere) {
    double exact = 1e300;
    for (const Polyline& line : lines) exact = std::min(exact, distanceToPolyline(q, line));
    const double error = (q - field.nearest(q)).norm() - exact;
    result.error_sum += error;
    result.error_max = std::max(result.error_max, error);
    ++result.queries;
  }
}

namespace cli = vicc_common::cli;

std::string usage() {
  return cli::helpText(
      "vicc_glyphs_feature_transform_bench [ICON_DIR]",
      "For every SVG icon of ICON_DIR (default: the vendored MDI icons) at 512 px: CPU time to "
      "build the skeleton guard's\nnearest-curve-point field with bucketed segments, OpenCV's "
      "labelled distance transform and Maurer's\ntransform, to answer 20000 queries at random "
      "points and 20000 near the curves, and the distance error\nat the random points "
      "(Markdown table on stdout). Exit code 0 on success, 1 on an error, 2 on a usage error.",
      {});
}

int run(const std::vector<std::string>& args) {
  const cli::ParsedArguments parsed = cli::parseArguments(args, {});
  if (parsed.positional.size() > 1) throw cli::UsageError("more than one ICON_DIR given");
  const fs::path dir = parsed.positional.empty() ? fs::path(VICC_GLYPHS_DATA_DIR "/icons")
                                                 : fs::path(parsed.positional[0]);
  if (!fs::is_directory(dir)) throw cli::UsageError("no directory " + dir.string());
  std::vector<fs::path> icons;
  for (const auto& entry : fs::directory_iterator(dir)) {
    if (entry.path().extension() == ".svg") icons.push_back(entry.path());
  }
  if (icons.empty()) throw cli::UsageError("no .svg icon in " + dir.string());
  std::sort(icons.begin(), icons.end());
  Result segments, opencv, maurer;
  for (const fs::path& icon : icons) {
    const DiffusionCurveImage image = loadDiffusionCurves(icon.string(), 512);
    const std::vector<Polyline> lines = skeletonGuardPolylines(image.curves);
    measure(lines, NearestPointMethod::ExactSegments, segments);
    measure(lines, NearestPointMethod::OpenCvLabels, opencv);
    measure(lines, NearestPointMethod::Maurer, maurer);
  }
  std::printf("%zu icons at 512 px, grid 520 x 520, 20000 random queries each\n\n", icons.size());
  std::printf(
      "| method | build ms (median over icons) | build ms (max) | 20000 random queries ms "
      "(median) | 20000 queries near the curves ms (median) | mean distance error px | max "
      "distance error px |\n|---|---|---|---|---|---|---|\n");
  for (const auto& [name, r] :
       {std::pair<const char*, const Result&>{"bucketed segments (exact)", segments},
        std::pair<const char*, const Result&>{"OpenCV DIST_LABEL_PIXEL, mask 5", opencv},
        std::pair<const char*, const Result&>{"Maurer et al. 2003", maurer}}) {
    std::printf("| %s | %.2f | %.2f | %.2f | %.2f | %.4f | %.3f |\n", name,
                bench::median(r.build_ms), bench::maximum(r.build_ms),
                bench::median(r.random_query_ms), bench::median(r.near_query_ms),
                r.error_sum / r.queries, r.error_max);
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return cli::runTool("vicc_glyphs_feature_transform_bench", argc, argv, usage(), run);
}
