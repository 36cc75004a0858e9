#pragma once
// 8-bit PNG files and buffers through libpng's simplified API. Not OpenCV's imgcodecs: Debian
// builds it with GDAL, poppler, HDF5 and ~150 other libraries, whose loading cost every process
// that links it about 0.1 s at start (a `vicc_glyph` run took 0.23 s, of which 0.1 s was that).

#include <cstdint>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

namespace vicc_glyphs {

enum class ChannelOrder { kRgb, kBgr };

/// Largest width or height readPngBgra accepts by default: the header is checked before any
/// pixel memory is allocated.
constexpr int kMaxPngSide = 16384;

/// Reads a PNG of any colour type and bit depth (grey, palette, alpha, 16 bits: scaled as sRGB)
/// as 8-bit BGRA, alpha not premultiplied (CV_8UC4). Throws std::runtime_error with the reason
/// (missing, not a PNG, corrupt, wider or taller than `max_side`); the caller names the file.
cv::Mat readPngBgra(const std::string& path, int max_side = kMaxPngSide);

/// Writes an 8-bit 3-channel image (CV_8UC3, channels in `order`) as an RGB PNG (compressed
/// for speed). Throws std::runtime_error naming the file and the reason.
void writePng8(const cv::Mat& image, ChannelOrder order, const std::string& path);

/// The PNG file writePng8 would write, in memory.
std::vector<std::uint8_t> encodePng8(const cv::Mat& image, ChannelOrder order);

}  // namespace vicc_glyphs
