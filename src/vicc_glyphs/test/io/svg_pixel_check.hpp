#pragma once
// Renders a small SVG through the importer and the renderer and compares it with an expected
// picture given as a function of the position: pixels whose square lies wholly on one side of
// the expected boundary (all 4 corners and the centre agree) must match; pixels the boundary
// crosses are anti-aliased and skipped.

#include <gtest/gtest.h>

#include <functional>
#include <string>

#include "vicc_glyphs/io/svg_import.hpp"
#include "vicc_glyphs/render/renderer.hpp"

namespace vicc_glyphs {
namespace test {

/// Expected colour at a point in SVG user units (the viewBox is 0 0 size size).
using ExpectedPicture = std::function<Color(double x, double y)>;

struct PixelComparison {
  int checked = 0;     ///< pixels wholly inside one expected colour
  int wrong = 0;       ///< of those, pixels off by more than the tolerance
  double worst = 0.0;  ///< largest channel difference among the checked pixels
};

inline cv::Mat renderSvgText(const std::string& svg, int pixels,
                             const SvgImportOptions& base = {}) {
  SvgImportOptions options = base;
  options.size = pixels;
  return renderDiffusionCurves(parseSvg(svg, options)).image;
}

/// `view_size`: the viewBox side in user units; the image is `pixels` wide and square.
inline PixelComparison comparePixels(const cv::Mat& image, double view_size,
                                     const ExpectedPicture& expected, double tolerance = 0.03) {
  PixelComparison result;
  const double scale = view_size / image.cols;
  for (int y = 0; y < image.rows; ++y) {
    for (int x = 0; x < image.cols; ++x) {
      const Color centre = expected((x + 0.5) * scale, (y + 0.5) * scale);
      bool uniform = true;
      for (double dy : {0.0, 1.0}) {
        for (double dx : {0.0, 1.0}) {
          uniform &= (expected((x + dx) * scale, (y + dy) * scale) - centre).norm() < 1e-9;
        }
      }
      if (!uniform) continue;
      const cv::Vec3f& v = image.at<cv::Vec3f>(y, x);
      const double difference = (Color(v[0], v[1], v[2]) - centre).cwiseAbs().maxCoeff();
      ++result.checked;
      result.worst = std::max(result.worst, difference);
      if (difference > tolerance) ++result.wrong;
    }
  }
  return result;
}

/// Expects every wholly covered pixel to match (a minimal SVG has no excuse for a wrong one).
inline void expectPicture(const std::string& svg, double view_size, int pixels,
                          const ExpectedPicture& expected, const SvgImportOptions& options = {},
                          double tolerance = 0.03) {
  const PixelComparison c =
      comparePixels(renderSvgText(svg, pixels, options), view_size, expected, tolerance);
  EXPECT_GT(c.checked, pixels * pixels / 2) << svg;
  EXPECT_EQ(c.wrong, 0) << "worst difference " << c.worst << " in " << svg;
}

inline Color gray(double v) { return Color(v, v, v); }

}  // namespace test
}  // namespace vicc_glyphs
