#include "check_design_command.hpp"

#include "command_line.hpp"
#include "model_path.hpp"
#include "vicc_glyphs/design/design_check.hpp"
#include "vicc_glyphs/perception/perception_model_yaml.hpp"

namespace vicc_glyphs::tools {
namespace {

const std::vector<OptionSpec>& checkDesignOptions() {
  static const std::vector<OptionSpec> specs{
      {"size", "PX", "glyph width in pixels (default: the design's size_px)"},
      perceptionModelOption(),
      {"help", "", "show this help"},
  };
  return specs;
}

void printUsage(std::ostream& out) {
  out << "usage: vicc_glyph check-design DESIGN.yaml [--size PX] [--model MODEL.yaml]\n\n"
         "Builds the glyph of every combination of data levels and lists those that cannot be\n"
         "built or whose curves cross as drawn. Exit code 0: all good; 1: some fail (listed on\n"
         "stdout) or the design does not load; 2: usage error.\n\n"
      << formatOptions(checkDesignOptions());
}

}  // namespace

int runCheckDesignCommand(const std::vector<std::string>& args, std::ostream& out,
                          std::ostream& err) {
  std::string design_path, model_path;
  int size = 0;
  const auto read = [&](const ParsedArguments& parsed) {
    if (parsed.positional.size() != 1) throw UsageError("expected one DESIGN.yaml");
    design_path = parsed.positional.front();
    if (parsed.has("size")) {
      size = parseInteger("size", parsed.value("size"), design::kMinGlyphPixels,
                          design::kMaxGlyphPixels);
    }
    if (parsed.has("model")) model_path = parsed.value("model");
  };
  const std::optional<int> done =
      readCommandLine("check-design", args, checkDesignOptions(), printUsage, out, err, read);
  if (done) return *done;
  try {
    const perception::PerceptionModel model =
        perception::loadPerceptionModel(perceptionModelPathOrDefault(model_path));
    const design::GlyphDesign glyph = design::loadDesign(design_path, model);
    // Progress on stderr for designs with many combinations (COVID-19: 900, a few seconds).
    const auto progress = [&err](int done, int total) {
      if (total >= 100 && done % 100 == 0) {
        err << "vicc_glyph check-design: " << done << " of " << total << " built\n";
      }
    };
    const design::DesignCheck check = design::checkDesign(glyph, model, size, progress);
    out << glyph.name << " at " << check.size_px << " px: ";
    if (check.problems.empty()) {
      out << "all " << check.combinations << " level combinations build, none crosses itself\n";
      return 0;
    }
    out << check.problems.size() << " of " << check.combinations << " level combinations fail\n";
    for (const design::LevelProblem& problem : check.problems) {
      out << "  " << design::describeLevels(glyph, problem.levels) << ": " << problem.problem
          << "\n";
    }
    return 1;
  } catch (const std::exception& e) {
    err << "vicc_glyph check-design: " << e.what() << "\n";
    return 1;
  }
}

}  // namespace vicc_glyphs::tools
