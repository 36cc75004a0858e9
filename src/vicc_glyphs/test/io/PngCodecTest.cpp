// libpng reader and writer: exact round trips in both channel orders, every colour type and
// depth OpenCV's encoder writes (an independent encoder), and clear errors for missing,
// foreign, truncated and oversized files.
#include <gtest/gtest.h>
#include <png.h>

#include <filesystem>
#include <fstream>
#include <opencv2/imgcodecs.hpp>
#include <stdexcept>

#include "vicc_glyphs/io/png_codec.hpp"

namespace vicc_glyphs {
namespace {

std::string tempPath(const std::string& name) { return ::testing::TempDir() + "/" + name; }

// Every pixel different: channel c of (x, y) is (x * 7 + y * 13 + c * 101) mod 256.
cv::Mat3b gradient(int width, int height) {
  cv::Mat3b image(height, width);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      for (int c = 0; c < 3; ++c)
        image(y, x)[c] = static_cast<uchar>((x * 7 + y * 13 + c * 101) % 256);
    }
  }
  return image;
}

std::string errorOf(const std::function<void()>& action) {
  try {
    action();
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

TEST(PngCodecTest, RgbRoundTripIsExact) {
  const cv::Mat3b rgb = gradient(37, 23);  // odd sizes: row padding must not matter
  const std::string path = tempPath("round_trip_rgb.png");
  writePng8(rgb, ChannelOrder::kRgb, path);
  const cv::Mat4b bgra = readPngBgra(path);
  ASSERT_EQ(bgra.size(), rgb.size());
  for (int y = 0; y < rgb.rows; ++y) {
    for (int x = 0; x < rgb.cols; ++x) {
      ASSERT_EQ(bgra(y, x), cv::Vec4b(rgb(y, x)[2], rgb(y, x)[1], rgb(y, x)[0], 255))
          << x << "," << y;
    }
  }
}

TEST(PngCodecTest, BgrOrderAndMemoryEncodingMatchOpenCv) {
  const cv::Mat3b bgr = gradient(40, 31);
  const std::vector<std::uint8_t> bytes = encodePng8(bgr, ChannelOrder::kBgr);
  ASSERT_GT(bytes.size(), 8u);
  EXPECT_EQ(bytes[1], 'P');
  EXPECT_EQ(bytes[2], 'N');
  EXPECT_EQ(bytes[3], 'G');
  const cv::Mat decoded = cv::imdecode(bytes, cv::IMREAD_COLOR);  // OpenCV reads BGR
  ASSERT_EQ(decoded.type(), CV_8UC3);
  EXPECT_EQ(cv::norm(decoded, bgr, cv::NORM_INF), 0.0);
  // A region of interest (not continuous) is encoded as its own pixels.
  const cv::Mat3b part = bgr(cv::Rect(3, 5, 20, 10));
  const cv::Mat part_decoded = cv::imdecode(encodePng8(part, ChannelOrder::kBgr), cv::IMREAD_COLOR);
  EXPECT_EQ(cv::norm(part_decoded, part, cv::NORM_INF), 0.0);
}

// A two-colour palette PNG, 3 x 2, written with libpng's colour-map format (OpenCV cannot).
std::string writePalettePng() {
  const std::string path = tempPath("palette.png");
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  image.width = 3;
  image.height = 2;
  image.format = PNG_FORMAT_RGB_COLORMAP;
  image.colormap_entries = 2;
  const std::uint8_t indices[] = {0, 1, 0, 1, 1, 0};
  const std::uint8_t colormap[] = {200, 100, 50, 5, 15, 25};
  EXPECT_TRUE(png_image_write_to_file(&image, path.c_str(), 0, indices, 0, colormap));
  return path;
}

TEST(PngCodecTest, ReadsGreyPaletteSixteenBitAndAlpha) {
  const std::string grey = tempPath("grey.png"), deep = tempPath("deep.png"),
                    alpha = tempPath("alpha.png");
  cv::Mat1b grey_image(4, 5);
  for (int i = 0; i < 20; ++i) grey_image(i / 5, i % 5) = static_cast<uchar>(i * 12);
  ASSERT_TRUE(cv::imwrite(grey, grey_image));
  cv::Mat_<cv::Vec3w> deep_image(3, 3, cv::Vec3w(0, 257 * 128, 65535));
  ASSERT_TRUE(cv::imwrite(deep, deep_image));
  cv::Mat4b alpha_image(2, 2, cv::Vec4b(10, 20, 30, 0));
  alpha_image(1, 1) = cv::Vec4b(40, 50, 60, 128);
  ASSERT_TRUE(cv::imwrite(alpha, alpha_image));

  const cv::Mat4b g = readPngBgra(grey);
  EXPECT_EQ(g(3, 4), cv::Vec4b(228, 228, 228, 255));
  EXPECT_EQ(g(0, 1), cv::Vec4b(12, 12, 12, 255));
  const cv::Mat4b d = readPngBgra(deep);  // 16 bits scaled to 8 (v / 257), no gamma change
  EXPECT_EQ(d(2, 2), cv::Vec4b(0, 128, 255, 255));
  const cv::Mat4b p = readPngBgra(writePalettePng());
  EXPECT_EQ(p(0, 0), cv::Vec4b(50, 100, 200, 255));
  EXPECT_EQ(p(1, 0), cv::Vec4b(25, 15, 5, 255));
  const cv::Mat4b a = readPngBgra(alpha);  // not premultiplied
  EXPECT_EQ(a(1, 1), cv::Vec4b(40, 50, 60, 128));
  EXPECT_EQ(a(0, 0)[3], 0);
}

TEST(PngCodecTest, ErrorsSayWhatIsWrong) {
  EXPECT_NE(errorOf([] { readPngBgra(tempPath("no_such.png")); }).find("not a readable PNG"),
            std::string::npos);
  const std::string text = tempPath("text.png");
  std::ofstream(text) << "this is not a PNG";
  EXPECT_NE(errorOf([&] { readPngBgra(text); }).find("not a readable PNG"), std::string::npos);

  const std::string whole = tempPath("whole.png"), cut = tempPath("cut.png");
  writePng8(gradient(64, 64), ChannelOrder::kRgb, whole);
  std::filesystem::copy_file(whole, cut, std::filesystem::copy_options::overwrite_existing);
  std::filesystem::resize_file(cut, std::filesystem::file_size(whole) / 2);
  EXPECT_NE(errorOf([&] { readPngBgra(cut); }).find("corrupt PNG"), std::string::npos);

  // The size limit is checked on the header, before any pixel memory.
  const std::string big = errorOf([&] { readPngBgra(whole, 32); });
  EXPECT_NE(big.find("64 x 64"), std::string::npos) << big;
  EXPECT_NE(big.find("at most 32"), std::string::npos) << big;

  const std::string unwritable =
      errorOf([] { writePng8(gradient(4, 4), ChannelOrder::kRgb, "/nonexistent_dir/x.png"); });
  EXPECT_NE(unwritable.find("cannot write /nonexistent_dir/x.png"), std::string::npos);
  const std::string wrong_type =
      errorOf([] { encodePng8(cv::Mat(4, 4, CV_32FC3, cv::Scalar(0.5)), ChannelOrder::kRgb); });
  EXPECT_NE(wrong_type.find("8-bit 3-channel"), std::string::npos);
  EXPECT_NE(errorOf([] { encodePng8(cv::Mat(), ChannelOrder::kRgb); }).find("empty"),
            std::string::npos);
}

}  // namespace
}  // namespace vicc_glyphs
