#include "vicc_glyphs/render/grid_problem.hpp"

#include <algorithm>
#include <functional>
#include <limits>

#include "vicc_glyphs/render/lattice_crossings.hpp"

namespace vicc_glyphs {
namespace {

// Writes a side's constraint value at curve parameter s into `out` (one entry per channel);
// returns false when that side adds no constraint (a barrier side).
using SideSampler =
    std::function<bool(const DiffusionCurve& curve, bool left_side, double s, double* out)>;

void cutLink(GridProblem& problem, const GridPixel& a, const GridPixel& b) {
  const GridPixel& first = (a.x < b.x || a.y < b.y) ? a : b;
  if (first.x < 0 || first.y < 0) return;  // the link leaves the grid: there is none to cut
  const int index = first.y * problem.width + first.x;
  if (a.y == b.y) {
    if (first.x + 1 < problem.width) problem.couples_right[index] = 0;
  } else if (first.y + 1 < problem.height) {
    problem.couples_down[index] = 0;
  }
}

// Marks pixels reachable over links from an already reached one by a forward and a backward
// raster pass; returns whether every pixel is reached (the usual case, so the exact search
// below rarely runs).
bool propagateByRasterPasses(const GridProblem& problem,
                             render_detail::PixelVector<std::uint8_t>& reached) {
  const int w = problem.width, h = problem.height;
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const int p = y * w + x;
      if (reached[p]) continue;
      reached[p] = (x > 0 && problem.couples_right[p - 1] && reached[p - 1]) ||
                   (y > 0 && problem.couples_down[p - w] && reached[p - w]);
    }
  }
  bool all = true;
  for (int y = h - 1; y >= 0; --y) {
    for (int x = w - 1; x >= 0; --x) {
      const int p = y * w + x;
      if (!reached[p]) {
        reached[p] = (problem.couples_right[p] && reached[p + 1]) ||
                     (problem.couples_down[p] && reached[p + w]);
      }
      all = all && reached[p];
    }
  }
  return all;
}

// Whether test(q) holds for a pixel q linked to pixel p, trying right, down, left and up in
// that order and stopping at the first that passes.
template <class Test>
bool anyLinkedPixel(const GridProblem& problem, int p, Test&& test) {
  const int w = problem.width;
  return (problem.couples_right[p] && test(p + 1)) || (problem.couples_down[p] && test(p + w)) ||
         (p % w > 0 && problem.couples_right[p - 1] && test(p - 1)) ||
         (p >= w && problem.couples_down[p - w] && test(p - w));
}

// Fixes every free pixel that links cannot connect to a Dirichlet pixel to `background`.
void fixUnreachedPixels(GridProblem& problem, const std::vector<double>& background,
                        render_detail::PixelVector<std::uint8_t>& reached,
                        std::vector<int>& queue) {
  const int n = problem.pixelCount();
  reached.assign(problem.fixed.begin(), problem.fixed.end());
  if (propagateByRasterPasses(problem, reached)) return;
  spreadLabelsOverLinks(problem, reached.data(), queue);
  for (int p = 0; p < n; ++p) {
    if (reached[p]) continue;
    problem.fixed[p] = 1;
    for (int c = 0; c < problem.channels; ++c) {
      problem.values[p * problem.channels + c] = static_cast<float>(background[c]);
    }
  }
}

void resetProblem(GridProblem& problem, int width, int height, int channels) {
  problem.width = std::max(width, 0);
  problem.height = std::max(height, 0);
  problem.curve_pixels = 0;
  problem.channels = channels;
  const int n = problem.pixelCount();
  for (auto* flags : {&problem.couples_right, &problem.couples_down, &problem.fixed}) {
    render_detail::reserveWithHugePages(*flags, n);
  }
  render_detail::reserveWithHugePages(problem.values, static_cast<size_t>(channels) * n);
  problem.couples_right.assign(n, 1);
  problem.couples_down.assign(n, 1);
  for (int y = 0; y < problem.height; ++y) {
    problem.couples_right[y * width + width - 1] = 0;  // Neumann border
  }
  for (int x = 0; x < problem.width; ++x) problem.couples_down[(height - 1) * width + x] = 0;
  problem.fixed.assign(n, 0);
  problem.values.assign(static_cast<size_t>(channels) * n, 0.0f);
}

void assembleGridProblem(const DiffusionCurveImage& image, double scale, const SideSampler& sample,
                         const std::vector<double>& background, GridProblem& problem,
                         render_detail::PixelVector<int>& counts,
                         render_detail::PixelVector<float>& nearest,
                         render_detail::PixelVector<std::uint8_t>& reached, std::vector<int>& queue,
                         LatticeCrossingList* visited) {
  const int n = problem.pixelCount();
  const int width = problem.width, height = problem.height, channels = problem.channels;
  if (n == 0) return;
  // A pixel takes its value from the nearest curve crossing on its links, measured along the
  // link (equally near ones are averaged: sums accumulate in `values`, divided by the counts
  // afterwards). Averaging all crossings instead would mix both sides' colours where a thin
  // wedge of one side ends between two pixel centres of the other (every sharp corner of an
  // icon). Along the link, not from the crossing piece's line: where a sharp tip crosses a
  // link twice, the far flank's line can pass closer to the pixel centre than the near one's,
  // and the pixel took the tip's colour (dark smudges beside the wave tips of PACEMOD glyphs).
  constexpr float kSameDistance = 1e-4f;
  counts.assign(n, 0);
  nearest.assign(n, std::numeric_limits<float>::infinity());
  std::vector<double> sample_value(channels);
  const auto constrain = [&](const DiffusionCurve& curve, bool left_side, double s,
                             const GridPixel& pixel, double distance) {
    if (pixel.x < 0 || pixel.y < 0 || pixel.x >= width || pixel.y >= height) return;
    const int p = pixel.y * width + pixel.x;
    const float d = static_cast<float>(distance);
    if (d > nearest[p] + kSameDistance) return;
    if (!sample(curve, left_side, s, sample_value.data())) return;
    if (d < nearest[p] - kSameDistance) {
      counts[p] = 0;
      std::fill_n(problem.values.begin() + static_cast<long>(p) * channels, channels, 0.0f);
      nearest[p] = d;
    }
    ++counts[p];
    for (int c = 0; c < channels; ++c) {
      problem.values[p * channels + c] += static_cast<float>(sample_value[c]);
    }
  };
  forEachLatticeCrossing(image, scale, width, height, [&](const LatticeCrossing& crossing) {
    if (visited) visited->push_back(crossing);
    const DiffusionCurve& curve = image.curves[crossing.curve];
    cutLink(problem, crossing.left_pixel, crossing.right_pixel);
    constrain(curve, true, crossing.position, crossing.left_pixel, crossing.left_link_distance);
    constrain(curve, false, crossing.position, crossing.right_pixel, crossing.right_link_distance);
  });
  for (int p = 0; p < n; ++p) {
    if (counts[p] == 0) continue;
    problem.fixed[p] = 1;
    ++problem.curve_pixels;
    const float share = 1.0f / static_cast<float>(counts[p]);
    for (int c = 0; c < channels; ++c) problem.values[p * channels + c] *= share;
  }
  fixUnreachedPixels(problem, background, reached, queue);
}

}  // namespace

void spreadLabelsOverLinks(const GridProblem& problem, std::uint8_t* labels,
                           std::vector<int>& queue) {
  // The search starts from the labelled pixels linked to an unlabelled one: the rest have
  // nothing left to reach.
  queue.clear();
  for (int p = 0; p < problem.pixelCount(); ++p) {
    if (!labels[p]) continue;
    if (anyLinkedPixel(problem, p, [&](int q) { return !labels[q]; })) queue.push_back(p);
  }
  for (size_t head = 0; head < queue.size(); ++head) {
    const int p = queue[head];
    anyLinkedPixel(problem, p, [&](int q) {
      if (!labels[q]) {
        labels[q] = labels[p];
        queue.push_back(q);
      }
      return false;  // visit every linked pixel
    });
  }
}

void GridAssembler::assembleColor(const DiffusionCurveImage& image, int width, int height,
                                  double scale, const Color& background, GridProblem& problem) {
  const SideSampler sample = [](const DiffusionCurve& curve, bool left_side, double s,
                                double* out) {
    if (!(left_side ? curve.left_emits : curve.right_emits)) return false;
    const Color color = left_side ? curve.leftColorAt(s) : curve.rightColorAt(s);
    for (int c = 0; c < 3; ++c) out[c] = color[c];
    return true;
  };
  resetProblem(problem, width, height, 3);
  color_crossings_.clear();
  assembleGridProblem(image, scale, sample, {background[0], background[1], background[2]}, problem,
                      counts_, nearest_, reached_, queue_, &color_crossings_);
}

void GridAssembler::assembleBlur(const DiffusionCurveImage& image, int width, int height,
                                 double scale, GridProblem& problem) {
  const SideSampler sample = [scale](const DiffusionCurve& curve, bool, double s, double* out) {
    out[0] = scale * curve.blurAt(s);
    return true;
  };
  resetProblem(problem, width, height, 1);
  assembleGridProblem(image, scale, sample, {0.0}, problem, counts_, nearest_, reached_, queue_,
                      nullptr);
}

GridProblem assembleColorProblem(const DiffusionCurveImage& image, int width, int height,
                                 double scale, const Color& background) {
  GridProblem problem;
  GridAssembler().assembleColor(image, width, height, scale, background, problem);
  return problem;
}

GridProblem assembleBlurProblem(const DiffusionCurveImage& image, int width, int height,
                                double scale) {
  GridProblem problem;
  GridAssembler().assembleBlur(image, width, height, scale, problem);
  return problem;
}

}  // namespace vicc_glyphs
