#include "vicc_glyphs/io/png_codec.hpp"

#include <png.h>

#include <cstring>
#include <stdexcept>

namespace vicc_glyphs {
namespace {

// Frees libpng's state on every path out (png_image_free is a no-op once finished).
struct ImageGuard {
  png_image image;
  ImageGuard() {
    std::memset(&image, 0, sizeof image);
    image.version = PNG_IMAGE_VERSION;
  }
  ~ImageGuard() { png_image_free(&image); }
  ImageGuard(const ImageGuard&) = delete;
  ImageGuard& operator=(const ImageGuard&) = delete;
};

std::string reasonOf(const png_image& image, const char* fallback) {
  return image.message[0] != '\0' ? std::string(image.message) : std::string(fallback);
}

// A continuous 8-bit 3-channel image and the simplified API's description of it.
cv::Mat checkedRgb8(const cv::Mat& image, ChannelOrder order, png_image& description) {
  if (image.empty()) throw std::runtime_error("empty image");
  if (image.type() != CV_8UC3) throw std::runtime_error("expects an 8-bit 3-channel image");
  description.width = static_cast<png_uint_32>(image.cols);
  description.height = static_cast<png_uint_32>(image.rows);
  description.format = order == ChannelOrder::kRgb ? PNG_FORMAT_RGB : PNG_FORMAT_BGR;
  description.flags = PNG_IMAGE_FLAG_FAST;  // zlib's fast level: these are small flat images
  return image.isContinuous() ? image : image.clone();
}

}  // namespace

cv::Mat readPngBgra(const std::string& path, int max_side) {
  ImageGuard guard;
  png_image& image = guard.image;
  if (!png_image_begin_read_from_file(&image, path.c_str())) {
    throw std::runtime_error("not a readable PNG (" + reasonOf(image, "missing") + ")");
  }
  if (image.width == 0 || image.height == 0 || image.width > static_cast<png_uint_32>(max_side) ||
      image.height > static_cast<png_uint_32>(max_side)) {
    throw std::runtime_error("image of " + std::to_string(image.width) + " x " +
                             std::to_string(image.height) + " pixels: at most " +
                             std::to_string(max_side) + " per side");
  }
  image.format = PNG_FORMAT_BGRA;
  image.flags |= PNG_IMAGE_FLAG_16BIT_sRGB;  // 16-bit data without gAMA: sRGB, as 8-bit files
  cv::Mat bgra(static_cast<int>(image.height), static_cast<int>(image.width), CV_8UC4);
  if (!png_image_finish_read(&image, nullptr, bgra.data, static_cast<png_int_32>(bgra.step[0]),
                             nullptr)) {
    throw std::runtime_error("corrupt PNG (" + reasonOf(image, "decoding failed") + ")");
  }
  return bgra;
}

void writePng8(const cv::Mat& image, ChannelOrder order, const std::string& path) {
  ImageGuard guard;
  try {
    const cv::Mat pixels = checkedRgb8(image, order, guard.image);
    if (!png_image_write_to_file(&guard.image, path.c_str(), 0, pixels.data,
                                 static_cast<png_int_32>(pixels.step[0]), nullptr)) {
      throw std::runtime_error(reasonOf(guard.image, "write failed"));
    }
  } catch (const std::runtime_error& e) {
    throw std::runtime_error("cannot write " + path + ": " + e.what());
  }
}

std::vector<std::uint8_t> encodePng8(const cv::Mat& image, ChannelOrder order) {
  ImageGuard guard;
  const cv::Mat pixels = checkedRgb8(image, order, guard.image);
  const png_int_32 stride = static_cast<png_int_32>(pixels.step[0]);
  // Room for the largest PNG the image can give, so that it is compressed once.
  png_alloc_size_t size = PNG_IMAGE_PNG_SIZE_MAX(guard.image);
  std::vector<std::uint8_t> bytes(size);
  if (!png_image_write_to_memory(&guard.image, bytes.data(), &size, 0, pixels.data, stride,
                                 nullptr)) {
    throw std::runtime_error("cannot encode PNG: " + reasonOf(guard.image, "encoder failed"));
  }
  bytes.resize(size);
  return bytes;
}

}  // namespace vicc_glyphs
