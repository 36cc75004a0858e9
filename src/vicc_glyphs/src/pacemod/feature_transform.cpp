// Feature transforms: nearest feature pixel for every pixel of a grid.
#include <opencv2/imgproc.hpp>

#include "vicc_glyphs/pacemod/nearest_curve_point.hpp"

namespace vicc_glyphs {
namespace pacemod {
namespace {

// Maurer's "RemoveFT": with candidate features u, v (rows ordered) and w on lines through
// the column at rows ru < rv < rw and horizontal offsets du, dv, dw, v can never be the nearest
// on this column when the Voronoi boundaries of u|v and v|w cross before v's row range. In
// integers: exact (products of three pixel distances, far below 2^63), and cheaper than
// converting every operand to double.
bool removable(long long du, long long dv, long long dw, long long ru, long long rv, long long rw) {
  const long long a = rv - ru;
  const long long b = rw - rv;
  const long long c = a + b;
  return c * dv * dv - b * du * du - a * dw * dw - a * b * c > 0;
}

}  // namespace

std::vector<int> maurerFeatureTransform(const cv::Mat& mask) {
  std::vector<int> result, row_feature;
  maurerFeatureTransform(mask, result, row_feature);
  return result;
}

void maurerFeatureTransform(const cv::Mat& mask, std::vector<int>& result,
                            std::vector<int>& row_feature) {
  const int width = mask.cols;
  const int height = mask.rows;
  // Pass 1: nearest feature column within each row (two sweeps; every element is written).
  row_feature.resize(static_cast<std::size_t>(width) * height);
  for (int y = 0; y < height; ++y) {
    const unsigned char* row = mask.ptr<unsigned char>(y);
    int* out = &row_feature[static_cast<std::size_t>(y) * width];
    int last = -1;
    for (int x = 0; x < width; ++x) {
      if (row[x]) last = x;
      out[x] = last;
    }
    last = -1;
    for (int x = width - 1; x >= 0; --x) {
      if (row[x]) last = x;
      if (last >= 0 && (out[x] < 0 || last - x < x - out[x])) out[x] = last;
    }
  }
  // Pass 2: per column, the lower envelope of the row candidates (partial Voronoi diagram).
  result.assign(row_feature.size(), -1);
  std::vector<int> stack_row(height), stack_col(height);
  std::vector<long long> stack_dx2(height);  // squared horizontal offset of each candidate
  for (int x = 0; x < width; ++x) {
    int top = 0;
    for (int y = 0; y < height; ++y) {
      const int fx = row_feature[static_cast<std::size_t>(y) * width + x];
      if (fx < 0) continue;
      while (top >= 2 && removable(stack_col[top - 2] - x, stack_col[top - 1] - x, fx - x,
                                   stack_row[top - 2], stack_row[top - 1], y)) {
        --top;
      }
      stack_row[top] = y;
      stack_col[top] = fx;
      ++top;
    }
    if (top == 0) continue;
    for (int i = 0; i < top; ++i) {
      const long long dx = stack_col[i] - x;
      stack_dx2[i] = dx * dx;
    }
    int k = 0;
    for (int y = 0; y < height; ++y) {
      auto distance2 = [&](int i) {
        const long long dy = stack_row[i] - y;
        return stack_dx2[i] + dy * dy;
      };
      while (k + 1 < top && distance2(k + 1) <= distance2(k)) ++k;
      result[static_cast<std::size_t>(y) * width + x] = stack_row[k] * width + stack_col[k];
    }
  }
}

std::vector<int> openCvFeatureTransform(const cv::Mat& mask) {
  cv::Mat source(mask.size(), CV_8U);
  source.setTo(255);
  source.setTo(0, mask);
  cv::Mat distances, labels;
  cv::distanceTransform(source, distances, labels, cv::DIST_L2, cv::DIST_MASK_5,
                        cv::DIST_LABEL_PIXEL);
  // Every feature pixel has its own label; map labels back to the pixels that carry them.
  std::vector<int> label_pixel(static_cast<std::size_t>(mask.total()) + 1, -1);
  for (int y = 0; y < mask.rows; ++y) {
    for (int x = 0; x < mask.cols; ++x) {
      if (mask.at<unsigned char>(y, x)) label_pixel[labels.at<int>(y, x)] = y * mask.cols + x;
    }
  }
  std::vector<int> result(mask.total(), -1);
  for (int y = 0; y < mask.rows; ++y) {
    for (int x = 0; x < mask.cols; ++x) {
      result[static_cast<std::size_t>(y) * mask.cols + x] = label_pixel[labels.at<int>(y, x)];
    }
  }
  return result;
}

}  // namespace pacemod
}  // namespace vicc_glyphs
