#include "modify_request.hpp"

#include <cmath>
#include <stdexcept>

#include "vicc_glyphs/design/glyph_design.hpp"

namespace vicc_glyphs::tools {
namespace {

constexpr int kMaxSize = 16384;

// A finite number; `allow_zero` / `allow_negative` widen the range beyond > 0.
double parseNumber(const std::string& option, const std::string& text, bool allow_zero,
                   bool allow_negative) {
  size_t used = 0;
  double value = std::nan("");
  try {
    value = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  const bool in_range = allow_negative || value > 0.0 || (allow_zero && value == 0.0);
  if (used == 0 || used != text.size() || !std::isfinite(value) || !in_range) {
    const std::string range = allow_negative ? "a finite number"
                              : allow_zero   ? "a finite number >= 0"
                                             : "a finite number > 0";
    throw UsageError("option '--" + option + "' needs " + range + ", got '" + text + "'");
  }
  return value;
}

Color parseHexColor(const std::string& option, const std::string& text) {
  if (text.size() != 6 || text.find_first_not_of("0123456789abcdefABCDEF") != std::string::npos) {
    throw UsageError("option '--" + option + "' needs a colour RRGGBB (hex), got '" + text + "'");
  }
  Color rgb;
  for (int c = 0; c < 3; ++c) rgb[c] = std::stoi(text.substr(2 * c, 2), nullptr, 16) / 255.0;
  return rgb;
}

void parseWaves(const ParsedArguments& parsed, ModifyRequest& request) {
  const bool any = parsed.has("frequency") || parsed.has("amplitude") || parsed.has("waveform");
  if (!any) return;
  if (!parsed.has("frequency") || !parsed.has("amplitude")) {
    throw UsageError("a wave needs both --frequency and --amplitude");
  }
  pacemod::WaveSpec spec;
  const std::string name = parsed.value("waveform", "sine");
  const std::optional<pacemod::Waveform> waveform = pacemod::parseWaveform(name);
  if (!waveform) {
    throw UsageError("option '--waveform' must be sine, triangle, sawtooth or rectangle, got '" +
                     name + "'");
  }
  spec.waveform = *waveform;
  spec.waves_per_mm = parseNumber("frequency", parsed.value("frequency"), false, false) / 10.0;
  spec.amplitude_mm = parseNumber("amplitude", parsed.value("amplitude"), true, false);
  request.waves = spec;
}

void parseDashes(const ParsedArguments& parsed, ModifyRequest& request) {
  if (!parsed.has("dashes") && !parsed.has("dash-color")) return;
  if (!parsed.has("dashes") || !parsed.has("dash-color")) {
    throw UsageError("dashes need both --dashes N and --dash-color RRGGBB");
  }
  pacemod::DashSpec spec;
  spec.count = parseInteger("dashes", parsed.value("dashes"), 1, 10000);
  spec.color = parseHexColor("dash-color", parsed.value("dash-color"));
  request.dashes = spec;
}

}  // namespace

const std::vector<OptionSpec>& modifyOptions() {
  static const std::vector<OptionSpec> specs{
      {"out", "OUT.png", "PNG to write (required)"},
      {"dci", "OUT.xml", "also write the modified curves as Orzan XML (pixel frame of --size)"},
      {"size", "PX", "import and render width in pixels (default 512)"},
      {"size-mm", "MM", "the glyph's width in millimetres (default 50)"},
      {"waveform", "NAME", "sine (default), triangle, sawtooth or rectangle"},
      {"frequency", "F", "waves per 10 mm of contour (rounded to a whole count per contour)"},
      {"amplitude", "MM", "wave amplitude in millimetres (>= 0)"},
      {"curves", "SEL", "all (default), outer, or curve indices I,J,..."},
      {"dashes", "N", "colour dashes per contour (needs --dash-color)"},
      {"dash-color", "RRGGBB", "dash colour, hex"},
      {"inflate", "MM", "grow (> 0) or shrink (< 0) the selected contours by MM"},
      {"report", "OUT.json", "write what was applied per curve as JSON"},
      {"help", "", "show this help"},
  };
  return specs;
}

ModifyRequest parseModifyRequest(const std::vector<std::string>& args) {
  const ParsedArguments parsed = parseArguments(args, modifyOptions());
  ModifyRequest request;
  if (parsed.has("help")) {
    request.help = true;
    return request;
  }
  if (parsed.positional.size() != 1) {
    throw UsageError(parsed.positional.empty() ? "missing INPUT file"
                                               : "expected one INPUT file, got " +
                                                     std::to_string(parsed.positional.size()));
  }
  request.input = parsed.positional.front();
  request.output = parsed.value("out");
  if (request.output.empty()) throw UsageError("missing --out OUT.png");
  request.dci = parsed.value("dci");
  request.report = parsed.value("report");
  requireDistinctFiles({{"INPUT", request.input},
                        {"--out", request.output},
                        {"--dci", request.dci},
                        {"--report", request.report}});
  if (parsed.has("size")) {
    request.size = parseInteger("size", parsed.value("size"), design::kMinGlyphPixels, kMaxSize);
  }
  if (parsed.has("size-mm")) {
    request.size_mm = parseNumber("size-mm", parsed.value("size-mm"), false, false);
  }
  try {
    request.curves = pacemod::CurveSelection::parse(parsed.value("curves", "all"));
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string("option '--curves': ") + e.what());
  }
  parseWaves(parsed, request);
  parseDashes(parsed, request);
  if (parsed.has("inflate")) {
    request.inflate_mm = parseNumber("inflate", parsed.value("inflate"), true, true);
  }
  return request;
}

}  // namespace vicc_glyphs::tools
