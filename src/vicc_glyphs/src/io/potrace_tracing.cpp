#include "potrace_tracing.hpp"

#include <potracelib.h>

#include <climits>
#include <memory>
#include <stdexcept>
#include <vector>

namespace vicc_glyphs {
namespace io_detail {
namespace {

constexpr int kBitsPerWord = static_cast<int>(sizeof(potrace_word) * CHAR_BIT);

struct ParamDeleter {
  void operator()(potrace_param_t* p) const { potrace_param_free(p); }
};
struct StateDeleter {
  void operator()(potrace_state_t* s) const { potrace_state_free(s); }
};

Point2 toPoint(const potrace_dpoint_t& p) { return Point2(p.x, p.y); }

// Potrace curves start at the end point of their last segment; corners are two straight lines.
Contour toContour(const potrace_curve_t& curve, PointBudget& budget) {
  ContourBuilder builder(budget);
  builder.moveTo(toPoint(curve.c[curve.n - 1][2]));
  for (int i = 0; i < curve.n; ++i) {
    const auto& c = curve.c[i];
    if (curve.tag[i] == POTRACE_CORNER) {
      builder.lineTo(toPoint(c[1]));
      builder.lineTo(toPoint(c[2]));
    } else {
      builder.cubicTo(toPoint(c[0]), toPoint(c[1]), toPoint(c[2]));
    }
  }
  std::vector<Contour> contours = builder.finish();
  return contours.empty() ? Contour{} : contours.front();
}

}  // namespace

std::vector<Contour> traceMask(const cv::Mat1b& mask, const TraceOptions& options,
                               PointBudget& budget) {
  // Scanline j of the potrace bitmap is image row j, so potrace's coordinates are ours.
  const int words_per_line = (mask.cols + kBitsPerWord - 1) / kBitsPerWord;
  std::vector<potrace_word> words(static_cast<std::size_t>(words_per_line) * mask.rows, 0);
  for (int y = 0; y < mask.rows; ++y) {
    for (int x = 0; x < mask.cols; ++x) {
      if (mask(y, x)) {
        words[static_cast<std::size_t>(y) * words_per_line + x / kBitsPerWord] |=
            potrace_word(1) << (kBitsPerWord - 1 - x % kBitsPerWord);
      }
    }
  }
  potrace_bitmap_t bitmap{mask.cols, mask.rows, words_per_line, words.data()};

  std::unique_ptr<potrace_param_t, ParamDeleter> param(potrace_param_default());
  if (!param) throw std::runtime_error("potrace: cannot allocate parameters");
  param->turdsize = options.min_region_area;
  param->alphamax = options.corner_threshold;
  std::unique_ptr<potrace_state_t, StateDeleter> state(potrace_trace(param.get(), &bitmap));
  if (!state || state->status != POTRACE_STATUS_OK)
    throw std::runtime_error("potrace: tracing failed");

  std::vector<Contour> contours;
  for (const potrace_path_t* path = state->plist; path; path = path->next) {
    if (path->curve.n <= 0) continue;
    Contour contour = toContour(path->curve, budget);
    if (!contour.empty()) contours.push_back(std::move(contour));
  }
  return contours;
}

}  // namespace io_detail
}  // namespace vicc_glyphs
