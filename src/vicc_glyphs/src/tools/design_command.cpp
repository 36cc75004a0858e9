#include "design_command.hpp"

#include "command_line.hpp"
#include "model_path.hpp"
#include "vicc_glyphs/design/design_builder.hpp"
#include "vicc_glyphs/design/design_values.hpp"
#include "vicc_glyphs/io/orzan_xml.hpp"
#include "vicc_glyphs/perception/perception_model_yaml.hpp"
#include "vicc_glyphs/render/png_output.hpp"
#include "vicc_glyphs/render/renderer.hpp"

namespace vicc_glyphs::tools {
namespace {

const std::vector<OptionSpec>& designOptions() {
  static const std::vector<OptionSpec> specs{
      {"values", "K=V,...", "data values, one per design variable (required)"},
      {"out", "OUT.png", "PNG to write (required)"},
      {"dci", "OUT.xml", "also write the modified curves as Orzan XML"},
      {"size", "PX", "output width in pixels (default: the design's size_px)"},
      perceptionModelOption(),
      {"help", "", "show this help"},
  };
  return specs;
}

void printUsage(std::ostream& out) {
  out << "usage: vicc_glyph design DESIGN.yaml --values K=V,... --out OUT.png [--dci OUT.xml]\n"
         "                        [--size PX] [--model MODEL.yaml]\n\n"
         "Renders a glyph design (icon + encodings, see docs/glyphs/README.md) for data values.\n\n"
      << formatOptions(designOptions());
}

}  // namespace

int runDesignCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  std::string design_path, values, output, dci, model_path;  // model: empty for the default
  int size = 0;
  const auto read = [&](const ParsedArguments& parsed) {
    if (parsed.positional.size() != 1) throw UsageError("expected one DESIGN.yaml");
    design_path = parsed.positional.front();
    values = parsed.value("values");
    output = parsed.value("out");
    if (values.empty()) throw UsageError("missing --values K=V,...");
    if (output.empty()) throw UsageError("missing --out OUT.png");
    if (parsed.has("size"))
      size = parseInteger("size", parsed.value("size"), design::kMinGlyphPixels,
                          design::kMaxGlyphPixels);
    if (parsed.has("model")) model_path = parsed.value("model");
    dci = parsed.value("dci");
    requireDistinctFiles(
        {{"DESIGN", design_path}, {"--model", model_path}, {"--out", output}, {"--dci", dci}});
  };
  const std::optional<int> done =
      readCommandLine("design", args, designOptions(), printUsage, out, err, read);
  if (done) return *done;
  try {
    const perception::PerceptionModel model =
        perception::loadPerceptionModel(perceptionModelPathOrDefault(model_path));
    const design::GlyphDesign glyph = design::loadDesign(design_path, model);
    const std::vector<int> levels = glyph.levelsFor(design::parseValueList(values));
    const DiffusionCurveImage image = design::buildGlyph(glyph, levels, model, size);
    RenderOptions options;
    options.background = glyph.background;
    const RenderResult result = renderDiffusionCurves(image, options);
    requireSomethingDrawn(result.report, glyph.name);
    if (!dci.empty()) writeOrzanXml(image, dci);
    writePng(result.image, output);
  } catch (const design::DesignValueError& e) {
    err << "vicc_glyph design: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    err << "vicc_glyph design: " << e.what() << "\n";
    return 1;
  }
  return 0;
}

}  // namespace vicc_glyphs::tools
