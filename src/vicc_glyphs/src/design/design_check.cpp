#include "vicc_glyphs/design/design_check.hpp"

#include <sstream>
#include <stdexcept>

#include "vicc_glyphs/dci/flattening.hpp"
#include "vicc_glyphs/design/design_builder.hpp"
#include "vicc_glyphs/pacemod/polygon_crossings.hpp"

namespace vicc_glyphs::design {
namespace {

std::vector<pacemod::Crossing> crossingsAsDrawn(const DiffusionCurveImage& image,
                                                std::vector<pacemod::Polyline>& lines) {
  lines.clear();
  for (const DiffusionCurve& curve : image.curves) lines.push_back(flattenCurve(curve));
  return pacemod::findCrossings(lines);
}

std::string crossingProblem(const std::vector<pacemod::Polyline>& lines,
                            const std::vector<pacemod::Crossing>& crossings) {
  std::ostringstream text;
  const pacemod::Crossing& first = crossings.front();
  const Point2 at = pacemod::crossingPoint(lines, first);
  text << crossings.size() << " crossing(s) as drawn, the first of curve " << first.a.line
       << " with curve " << first.b.line << " at (" << at.x() << ", " << at.y()
       << ") px: the renderer would smudge one side's colour into the other";
  return text.str();
}

}  // namespace

std::vector<std::vector<int>> allLevelCombinations(const GlyphDesign& design) {
  std::vector<std::vector<int>> all;
  std::vector<int> levels(design.variables.size(), 0);
  for (;;) {
    all.push_back(levels);
    std::size_t v = 0;
    while (v < levels.size() && ++levels[v] == design.variables[v].levelCount()) levels[v++] = 0;
    if (v == levels.size()) return all;
  }
}

std::string describeLevels(const GlyphDesign& design, const std::vector<int>& levels) {
  std::ostringstream text;
  for (std::size_t v = 0; v < design.variables.size() && v < levels.size(); ++v) {
    const DesignVariable& variable = design.variables[v];
    const int k = levels[v], last = variable.levelCount() - 1;
    const bool low_open = k > 0 && variable.edge_belongs_below[k - 1];
    const bool high_open = k < last && !variable.edge_belongs_below[k];
    text << (v > 0 ? ", " : "") << variable.name << " level " << k << " " << (low_open ? "]" : "[")
         << (k > 0 ? variable.edges[k - 1] : variable.lower) << ", "
         << (k < last ? variable.edges[k] : variable.upper) << (high_open ? "[" : "]");
  }
  return text.str();
}

DesignCheck checkDesign(const GlyphDesign& design, const perception::PerceptionModel& model,
                        int size_px, const std::function<void(int, int)>& progress) {
  DesignCheck check;
  const DiffusionCurveImage icon = loadIcon(design, size_px);
  check.size_px = icon.width;
  std::vector<pacemod::Polyline> lines;
  const std::size_t icon_crossings = crossingsAsDrawn(icon, lines).size();
  const std::vector<std::vector<int>> combinations = allLevelCombinations(design);
  check.combinations = static_cast<int>(combinations.size());
  for (std::size_t c = 0; c < combinations.size(); ++c) {
    try {
      const DiffusionCurveImage glyph = buildGlyph(design, combinations[c], model, icon);
      const std::vector<pacemod::Crossing> crossings = crossingsAsDrawn(glyph, lines);
      if (crossings.size() > icon_crossings) {
        check.problems.push_back({combinations[c], crossingProblem(lines, crossings)});
      }
    } catch (const std::exception& e) {
      check.problems.push_back({combinations[c], e.what()});
    }
    if (progress) progress(static_cast<int>(c) + 1, check.combinations);
  }
  return check;
}

}  // namespace vicc_glyphs::design
