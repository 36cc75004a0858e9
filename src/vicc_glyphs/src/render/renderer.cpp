#include "vicc_glyphs/render/renderer.hpp"

#include <stdexcept>
#include <string>

#include <chrono>
#include <cstring>

#include "vicc_glyphs/render/curve_antialiasing.hpp"
#include "vicc_glyphs/render/pixel_buffer.hpp"
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

// Allocates the output Mats' pixels with PixelAllocator (2 MiB-aligned, huge-page advice):
// OpenCV's default allocator gives blocks that mostly fault in 4 KiB at a time.
class PixelMatAllocator : public cv::MatAllocator {
 public:
  cv::UMatData* allocate(int dims, const int* sizes, int type, void* data0, size_t* step,
                         cv::AccessFlag, cv::UMatUsageFlags) const override {
    size_t total = CV_ELEM_SIZE(type);
    for (int i = dims - 1; i >= 0; --i) {  // as OpenCV's own allocator: dense steps
      if (step) {
        if (data0 && step[i] != cv::Mat::AUTO_STEP) {
          CV_Assert(total <= step[i]);
          total = step[i];
        } else {
          step[i] = total;
        }
      }
      total *= sizes[i];
    }
    auto* u = new cv::UMatData(this);
    u->size = total;
    if (data0) {
      u->data = u->origdata = static_cast<uchar*>(data0);
      u->flags |= cv::UMatData::USER_ALLOCATED;
    } else {
      u->data = u->origdata = render_detail::PixelAllocator<uchar>().allocate(total);
    }
    return u;
  }

  bool allocate(cv::UMatData* u, cv::AccessFlag, cv::UMatUsageFlags) const override {
    return u != nullptr;
  }

  void deallocate(cv::UMatData* u) const override {
    if (!u) return;
    if (!(u->flags & cv::UMatData::USER_ALLOCATED)) {
      render_detail::PixelAllocator<uchar>().deallocate(u->origdata, u->size);
    }
    delete u;
  }
};

// Never destroyed: result Mats handed to the caller may outlive static destruction.
cv::MatAllocator* pixelMatAllocator() {
  static cv::MatAllocator* const allocator = new PixelMatAllocator;
  return allocator;
}

// Sizes `mat` (keeping its pixels when size and type already match) as one continuous block,
// which the solver and the anti-aliasing write directly.
float* prepareOutput(cv::Mat& mat, int rows, int cols, int type) {
  if (!mat.isContinuous() || mat.rows != rows || mat.cols != cols || mat.type() != type) {
    mat.release();
    mat.allocator = pixelMatAllocator();
  }
  mat.create(rows, cols, type);
  return mat.ptr<float>();
}

}  // namespace

struct DiffusionCurveRenderer::Workspace {
  GridAssembler assembler;
  MultigridSolver solver;
  CurveAntialiasing antialiasing;
  GridProblem problem;
  cv::Mat sigma;
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
  const double pixels = static_cast<double>(image.width) * image.height;
  if (pixels > kMaxRenderPixels) {
    throw std::length_error("image of " + std::to_string(image.width) + " x " +
                            std::to_string(image.height) + " pixels: more than the limit of " +
                            std::to_string(static_cast<long long>(kMaxRenderPixels)) +
                            " pixels per render");
  }
  Workspace& w = *workspace_;

  Clock::time_point phase = Clock::now();
  w.assembler.assembleColor(image, image.width, image.height, 1.0, options.background, w.problem);
  result.report.curve_pixels = w.problem.curve_pixels;
  result.report.timings.assemble_ms = millisecondsSince(phase);

  phase = Clock::now();
  float* diffused = prepareOutput(result.diffused, image.height, image.width, CV_32FC3);
  w.solver.solve(w.problem, options.multigrid, diffused, &result.report.multigrid);
  result.report.timings.solve_ms = millisecondsSince(phase);

  phase = Clock::now();
  if (options.antialias) {
    if (result.image.data == result.diffused.data) result.image.release();  // blend can't alias
    float* blended = prepareOutput(result.image, image.height, image.width, CV_32FC3);
    w.antialiasing.blend(w.assembler.colorCrossings(), image.width, image.height, 3, diffused,
                         blended);
  } else {
    result.diffused.copyTo(result.image);
  }
  result.report.timings.antialias_ms = millisecondsSince(phase);

  if (options.blur && hasBlurPoints(image)) {
    phase = Clock::now();
    w.assembler.assembleBlur(image, image.width, image.height, 1.0, w.problem);
    float* sigma = prepareOutput(w.sigma, image.height, image.width, CV_32FC1);
    w.solver.solve(w.problem, options.multigrid, sigma, nullptr);
    result.image = applyVariableBlur(result.image, w.sigma);
    result.report.blurred = true;
    result.report.timings.blur_ms = millisecondsSince(phase);
  }
  result.report.timings.total_ms = millisecondsSince(start);
}

void requireSomethingDrawn(const RenderReport& report, const std::string& what) {
  if (report.curve_pixels > 0) return;
  throw std::runtime_error(what +
                           ": nothing to draw: no curve with colours reaches the image (no "
                           "curves, curves outside the frame or without colour points, or a "
                           "picture too small for them), which would be only the background");
}

RenderResult renderDiffusionCurves(const DiffusionCurveImage& image, const RenderOptions& options) {
  RenderResult result;
  DiffusionCurveRenderer().render(image, options, result);
  return result;
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
