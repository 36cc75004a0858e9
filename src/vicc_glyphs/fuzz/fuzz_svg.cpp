// libFuzzer target: SVG import must either give a valid image or throw FormatError.
#include <cstdint>
#include <cstdlib>
#include <string>

#include "vicc_glyphs/io/svg_import.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const vicc_glyphs::DiffusionCurveImage image = vicc_glyphs::parseSvg(text);
    if (!vicc_glyphs::validate(image).empty()) std::abort();
  } catch (const vicc_glyphs::FormatError&) {
  }
  return 0;
}
