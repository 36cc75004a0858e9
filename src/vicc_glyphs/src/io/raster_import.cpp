// Raster icons to diffusion curves: quantise to a few colours, trace every non-background
// colour region with potrace, and take each curve's side colours from the image itself.

#include "vicc_glyphs/io/raster_import.hpp"

#include <algorithm>
#include <opencv2/imgproc.hpp>
#include <stdexcept>

#include "color_quantization.hpp"
#include "potrace_tracing.hpp"
#include "side_colors.hpp"
#include "vicc_glyphs/io/png_codec.hpp"

namespace vicc_glyphs {
namespace {

constexpr int kMaxRasterSide = 4096;
constexpr std::size_t kMaxSamplesPerCurve = 4096;

// 8-bit BGR from 8-bit BGRA, transparency composited onto `background` (RGB in [0, 1]).
cv::Mat3b toOpaqueBgr(const cv::Mat4b& bgra, const Color& background) {
  cv::Mat3b bgr(bgra.size());
  const cv::Vec3d back(background[2] * 255.0, background[1] * 255.0, background[0] * 255.0);
  for (int y = 0; y < bgra.rows; ++y) {
    for (int x = 0; x < bgra.cols; ++x) {
      const cv::Vec4b p = bgra(y, x);
      const double alpha = p[3] / 255.0;
      for (int c = 0; c < 3; ++c) {
        bgr(y, x)[c] = cv::saturate_cast<uchar>(alpha * p[c] + (1.0 - alpha) * back[c]);
      }
    }
  }
  return bgr;
}

// The cluster seen most along the image border.
int backgroundLabel(const io_detail::QuantizedImage& q) {
  std::vector<int> counts(q.palette.size(), 0);
  const cv::Mat1i& l = q.labels;
  for (int x = 0; x < l.cols; ++x) {
    ++counts[l(0, x)];
    ++counts[l(l.rows - 1, x)];
  }
  for (int y = 0; y < l.rows; ++y) {
    ++counts[l(y, 0)];
    ++counts[l(y, l.cols - 1)];
  }
  return static_cast<int>(std::max_element(counts.begin(), counts.end()) - counts.begin());
}

// Bilinear colour at image coordinates (pixel centres at +0.5), clamped to the image.
Color sampleBilinear(const cv::Mat3b& bgr, const Point2& p) {
  const double x = std::clamp(p.x() - 0.5, 0.0, bgr.cols - 1.0);
  const double y = std::clamp(p.y() - 0.5, 0.0, bgr.rows - 1.0);
  const int x0 = static_cast<int>(x), y0 = static_cast<int>(y);
  const int x1 = std::min(x0 + 1, bgr.cols - 1), y1 = std::min(y0 + 1, bgr.rows - 1);
  const double fx = x - x0, fy = y - y0;
  Color rgb = Color::Zero();
  const double weights[4] = {(1 - fx) * (1 - fy), fx * (1 - fy), (1 - fx) * fy, fx * fy};
  const cv::Vec3b pixels[4] = {bgr(y0, x0), bgr(y0, x1), bgr(y1, x0), bgr(y1, x1)};
  for (int i = 0; i < 4; ++i) rgb += weights[i] * Color(pixels[i][2], pixels[i][1], pixels[i][0]);
  return (rgb / 255.0).cwiseMax(0.0).cwiseMin(1.0);
}

DiffusionCurveImage traceImage(const cv::Mat3b& bgr, const RasterImportOptions& options) {
  const io_detail::QuantizedImage q =
      io_detail::quantizeColors(bgr, options.max_colors, options.min_color_fraction);
  const int background = backgroundLabel(q);
  io_detail::PointBudget budget(kMaxControlPointsPerFile);
  const io_detail::TraceOptions trace{options.min_region_area, options.corner_threshold};
  DiffusionCurveImage image;
  image.width = bgr.cols;
  image.height = bgr.rows;
  auto color_at = [&](const Point2& p) { return sampleBilinear(bgr, p); };
  auto offset = [&](double) { return options.sample_offset; };
  for (int label = 0; label < static_cast<int>(q.palette.size()); ++label) {
    if (label == background) continue;
    const cv::Mat1b mask = q.labels == label;
    for (io_detail::Contour& contour : io_detail::traceMask(mask, trace, budget)) {
      DiffusionCurve curve;
      curve.control_points = std::move(contour);
      const auto samples = io_detail::sideSamples(curve, options.color_samples_per_segment,
                                                  kMaxSamplesPerCurve, offset);
      io_detail::assignSideColors(curve, samples, color_at, q.palette[label]);
      image.curves.push_back(std::move(curve));
    }
  }
  return image;
}

}  // namespace

DiffusionCurveImage importRaster(const std::string& path, const RasterImportOptions& options) {
  if (options.max_colors < 1 || options.sample_offset <= 0.0 || options.min_region_area < 0 ||
      options.color_samples_per_segment < 1) {
    throw FormatError(path, "", "invalid raster import options");
  }
  cv::Mat input;
  try {
    input = readPngBgra(path, kMaxRasterSide);  // the size is checked before decoding
  } catch (const std::runtime_error& e) {
    throw FormatError(path, "", std::string("cannot read image: ") + e.what());
  }
  DiffusionCurveImage image;
  try {
    image = traceImage(toOpaqueBgr(input, options.alpha_background), options);
  } catch (const std::invalid_argument& e) {
    throw FormatError(path, "", e.what());
  } catch (const std::length_error& e) {
    throw FormatError(path, "", e.what());
  } catch (const std::runtime_error& e) {
    throw FormatError(path, "", e.what());
  } catch (const cv::Exception& e) {
    throw FormatError(path, "", std::string("image processing failed: ") + e.what());
  }
  const std::string problem = validate(image);
  if (!problem.empty()) throw FormatError(path, "", problem);
  return image;
}

}  // namespace vicc_glyphs
