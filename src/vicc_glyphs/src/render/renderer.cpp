#include "vicc_glyphs/render/renderer.hpp"

#include <chrono>
#include <cstring>

#include "vicc_glyphs/render/curve_antialiasing.hpp"
#include "vicc_glyphs/render/variable_blur.hpp"

namespace vicc_glyphs {
namespace {

using Clock = std::chrono::steady_clock;

double millisecondsSince(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

bool hasBlurPoints(const DiffusionCurveImage& image) {
  for (const DiffusionCurve& curve : image.curves) {
    for (const BlurPoint& point : curve.blur_points) {
      if (point.sigma > 0.0) return true;
    }
  }
  return false;
}

}  // namespace

struct DiffusionCurveRenderer::Workspace {
  GridAssembler assembler;
  MultigridSolver solver;
  CurveAntialiasing antialiasing;
  std::vector<GridProblem> levels;
  std::vector<float> colors;
  std::vector<float> blended;
  std::vector<float> sigma;
  cv::Mat sigma_mat;
};

DiffusionCurveRenderer::DiffusionCurveRenderer() : workspace_(std::make_unique<Workspace>()) {}
DiffusionCurveRenderer::~DiffusionCurveRenderer() = default;

void DiffusionCurveRenderer::render(const DiffusionCurveImage& input, const RenderOptions& options,
                                    RenderResult& result) {
  const Clock::time_point start = Clock::now();
  const DiffusionCurveImage scaled = options.size > 0 ? scaledToWidth(input, options.size) : input;
  const DiffusionCurveImage& image = options.size > 0 ? scaled : input;
  result.report = RenderReport{};
  if (image.width <= 0 || image.height <= 0) {
    result.image.release();
    result.diffused.release();
    return;
  }
  Workspace& w = *workspace_;
  const int coarsest = options.multigrid.coarsest_size;

  Clock::time_point phase = Clock::now();
  assembleLevels(
      image.width, image.height, coarsest,
      [&](int width, int height, double scale, GridProblem& level) {
        w.assembler.assembleColor(image, width, height, scale, options.background, level);
      },
      w.levels);
  result.report.timings.assemble_ms = millisecondsSince(phase);

  phase = Clock::now();
  w.solver.solve(w.levels, options.multigrid, w.colors, &result.report.multigrid);
  result.report.timings.solve_ms = millisecondsSince(phase);
  valuesToMat(w.colors, image.width, image.height, 3, result.diffused);

  phase = Clock::now();
  if (options.antialias) {
    w.antialiasing.blend(image, image.width, image.height, 3, w.colors, w.blended);
    valuesToMat(w.blended, image.width, image.height, 3, result.image);
  } else {
    result.diffused.copyTo(result.image);
  }
  result.report.timings.antialias_ms = millisecondsSince(phase);

  if (options.blur && hasBlurPoints(image)) {
    phase = Clock::now();
    assembleLevels(
        image.width, image.height, coarsest,
        [&](int width, int height, double scale, GridProblem& level) {
          w.assembler.assembleBlur(image, width, height, scale, level);
        },
        w.levels);
    w.solver.solve(w.levels, options.multigrid, w.sigma, nullptr);
    valuesToMat(w.sigma, image.width, image.height, 1, w.sigma_mat);
    result.image = applyVariableBlur(result.image, w.sigma_mat);
    result.report.blurred = true;
    result.report.timings.blur_ms = millisecondsSince(phase);
  }
  result.report.timings.total_ms = millisecondsSince(start);
}

RenderResult renderDiffusionCurves(const DiffusionCurveImage& image, const RenderOptions& options) {
  RenderResult result;
  DiffusionCurveRenderer().render(image, options, result);
  return result;
}

std::vector<GridProblem> assembleColorLevels(const DiffusionCurveImage& image,
                                             const Color& background, int coarsest_size) {
  std::vector<GridProblem> levels;
  GridAssembler assembler;
  assembleLevels(
      image.width, image.height, coarsest_size,
      [&](int width, int height, double scale, GridProblem& level) {
        assembler.assembleColor(image, width, height, scale, background, level);
      },
      levels);
  return levels;
}

void valuesToMat(const std::vector<float>& values, int width, int height, int channels,
                 cv::Mat& mat) {
  mat.create(height, width, CV_32FC(channels));  // reuses the pixels when the size matches
  const size_t row = static_cast<size_t>(width) * channels;
  for (int y = 0; y < height; ++y) {
    std::memcpy(mat.ptr<float>(y), values.data() + y * row, row * sizeof(float));
  }
}

}  // namespace vicc_glyphs
