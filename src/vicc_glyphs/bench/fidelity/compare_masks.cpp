// Compares a vicc_glyph render with a reference render (rsvg-convert) of the same icon:
// both are composited over white, converted to gray, and thresholded at 50 % into "dark"
// masks. Prints one line: IoU of the dark masks, mean absolute gray difference (0..1), and
// the dark pixel counts. Exit 2 when an image cannot be read or the sizes differ.
//   usage: vicc_glyph_fidelity_compare OURS.png REFERENCE.png

#include <iostream>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

namespace {

// Gray in [0, 1], transparent pixels composited over white.
cv::Mat grayOverWhite(const cv::Mat& image) {
  cv::Mat bgr, alpha;
  if (image.channels() == 4) {
    std::vector<cv::Mat> channels;
    cv::split(image, channels);
    channels[3].convertTo(alpha, CV_32F, 1.0 / 255.0);
    channels.pop_back();
    cv::merge(channels, bgr);
  } else if (image.channels() == 3) {
    bgr = image;
  } else {
    cv::cvtColor(image, bgr, cv::COLOR_GRAY2BGR);
  }
  cv::Mat gray;
  cv::cvtColor(bgr, gray, cv::COLOR_BGR2GRAY);
  gray.convertTo(gray, CV_32F, 1.0 / 255.0);
  if (!alpha.empty()) gray = gray.mul(alpha) + (1.0 - alpha);
  return gray;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::cerr << "usage: vicc_glyph_fidelity_compare OURS.png REFERENCE.png\n";
    return 2;
  }
  const cv::Mat ours = cv::imread(argv[1], cv::IMREAD_UNCHANGED);
  const cv::Mat reference = cv::imread(argv[2], cv::IMREAD_UNCHANGED);
  if (ours.empty() || reference.empty()) {
    std::cerr << "cannot read " << (ours.empty() ? argv[1] : argv[2]) << "\n";
    return 2;
  }
  if (ours.size() != reference.size()) {
    std::cerr << "size differs: " << ours.cols << "x" << ours.rows << " vs " << reference.cols
              << "x" << reference.rows << "\n";
    return 2;
  }
  const cv::Mat a = grayOverWhite(ours);
  const cv::Mat b = grayOverWhite(reference);
  const cv::Mat dark_a = a < 0.5;
  const cv::Mat dark_b = b < 0.5;
  const double intersection = cv::countNonZero(dark_a & dark_b);
  const double union_count = cv::countNonZero(dark_a | dark_b);
  const double iou = union_count > 0 ? intersection / union_count : 1.0;
  const double mean_abs = cv::mean(cv::abs(a - b))[0];
  std::cout << "iou " << iou << " mae " << mean_abs << " dark " << cv::countNonZero(dark_a) << " "
            << cv::countNonZero(dark_b) << "\n";
  return 0;
}
