// libFuzzer target: Orzan XML parsing must either succeed with a valid image that survives a
// write/read round trip, or throw FormatError; anything else (crash, other exception) is a bug.
#include <cstdint>
#include <cstdlib>
#include <string>

#include "vicc_glyphs/io/orzan_xml.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  vicc_glyphs::DiffusionCurveImage image;
  try {
    image = vicc_glyphs::parseOrzanXml(text);
  } catch (const vicc_glyphs::FormatError&) {
    return 0;
  }
  if (!vicc_glyphs::validate(image).empty()) std::abort();
  const vicc_glyphs::DiffusionCurveImage again =
      vicc_glyphs::parseOrzanXml(vicc_glyphs::formatOrzanXml(image));
  if (again.curves.size() != image.curves.size()) std::abort();
  return 0;
}
