// Design files: the shipped designs load; malformed ones fail naming the key; data values map
// to levels by the bin edges and bad values fail naming the variable.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "vicc_glyphs/design/design_values.hpp"
#include "vicc_glyphs/design/glyph_design.hpp"
#include "vicc_glyphs/perception/perception_model_yaml.hpp"

using namespace vicc_glyphs::design;

namespace {

const vicc_glyphs::perception::PerceptionModel& model() {
  static const auto loaded = vicc_glyphs::perception::loadPerceptionModel(
      std::string(VICC_GLYPHS_CONFIG_DIR) + "/perception_model.yaml");
  return loaded;
}

const char* const kMinimal = R"(
name: test
icon: icon.svg
size_mm: 50
variables:
  - name: p
    domain: [0, 100]
    edges: [50]
    encodings:
      - channel: geometric_frequency
        levels: [0, 4]
)";

std::string errorOf(const std::string& text) {
  try {
    parseDesign(text, "/base", model());
  } catch (const DesignError& e) {
    return e.what();
  }
  return "";
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return at == std::string::npos ? text : text.replace(at, from.size(), to);
}

}  // namespace

TEST(GlyphDesign, ShippedDesignsLoad) {
  int count = 0;
  for (const auto& entry : std::filesystem::directory_iterator(VICC_GLYPHS_DESIGNS_DIR)) {
    if (entry.path().extension() != ".yaml") continue;
    const GlyphDesign design = loadDesign(entry.path().string(), model());
    EXPECT_EQ(design.name, entry.path().stem().string());
    EXPECT_TRUE(std::filesystem::exists(design.icon_path)) << design.icon_path;
    ++count;
  }
  EXPECT_GE(count, 3);
}

TEST(GlyphDesign, MinimalDesignParsesAndResolvesTheIcon) {
  const GlyphDesign design = parseDesign(kMinimal, "/base", model());
  EXPECT_EQ(design.icon_path, "/base/icon.svg");
  ASSERT_EQ(design.variables.size(), 1u);
  EXPECT_EQ(design.variables[0].levelCount(), 2);
  EXPECT_EQ(design.variables[0].encodings[0].channel, Channel::GeometricFrequency);
}

TEST(GlyphDesign, ErrorsNameTheKey) {
  const std::string text = kMinimal;
  EXPECT_NE(errorOf(replaced(text, "geometric_frequency", "wobble"))
                .find("variables[0].encodings[0].channel: unknown channel 'wobble'"),
            std::string::npos);
  EXPECT_NE(errorOf(replaced(text, "levels: [0, 4]", "levels: [0]"))
                .find("variables[0].encodings[0].levels needs one entry per data level (2)"),
            std::string::npos);
  EXPECT_NE(errorOf(replaced(text, "levels: [0, 4]", "levels: [0, 5]"))
                .find("level 5 of geometric_frequency does not exist"),
            std::string::npos);
  // At 20 mm the geometric frequency has 4 levels: level 4 is gone.
  EXPECT_NE(errorOf(replaced(text, "size_mm: 50", "size_mm: 20")).find("(4 levels)"),
            std::string::npos);
  EXPECT_NE(errorOf(replaced(text, "edges: [50]", "edges: [150]"))
                .find("variables[0].edges must increase strictly inside the domain"),
            std::string::npos);
  EXPECT_NE(errorOf(replaced(text, "domain: [0, 100]", "domain: [100, 0]"))
                .find("variables[0].domain must be [lower, upper]"),
            std::string::npos);
  EXPECT_NE(errorOf(replaced(text, "name: p", "nam: p")).find("unknown key variables[0].nam"),
            std::string::npos);
  EXPECT_NE(errorOf(replaced(text, "icon: icon.svg\n", "")).find("missing key icon"),
            std::string::npos);
  EXPECT_NE(errorOf(replaced(text, "levels: [0, 4]", "levels: [0, 4]\n        waveform: zigzag"))
                .find("unknown waveform 'zigzag'"),
            std::string::npos);
  EXPECT_NE(errorOf(replaced(text, "levels: [0, 4]", "levels: [0, 4]\n        curves: \"1,x\""))
                .find("variables[0].encodings[0].curves"),
            std::string::npos);
  const std::string fill = replaced(text, "channel: geometric_frequency\n        levels: [0, 4]",
                                    "channel: fill_color\n        replace: \"000000\"\n"
                                    "        colors: [\"ff0000\", \"00ff\"]");
  EXPECT_NE(errorOf(fill).find("colors[1] must be an RRGGBB colour"), std::string::npos)
      << errorOf(fill);
  EXPECT_NE(errorOf("- 1").find("the design must be a map"), std::string::npos);
  EXPECT_NE(errorOf(replaced(text, "size_mm: 50", "size_mm: 50\nsize_mm: 20"))
                .find("key size_mm is given twice"),
            std::string::npos);
  // Flat waves show no frequency: the fixed amplitude of geometric_frequency must reach the
  // model's smallest geometric amplitude (0.1 mm at 50 mm), or every level looks the same.
  const std::string flat =
      replaced(text, "levels: [0, 4]", "levels: [0, 4]\n        amplitude_mm: 0");
  EXPECT_NE(errorOf(flat).find("amplitude_mm = 0 mm is below the smallest perceptible geometric "
                               "amplitude of a 50 mm glyph, 0.1 mm"),
            std::string::npos)
      << errorOf(flat);
  EXPECT_NE(errorOf(replaced(flat, "amplitude_mm: 0", "amplitude_mm: 0.09")).find("below"),
            std::string::npos);
  EXPECT_NO_THROW(
      parseDesign(replaced(flat, "amplitude_mm: 0", "amplitude_mm: 0.1"), "/base", model()));
}

TEST(GlyphDesign, ValuesMapToLevelsByTheEdges) {
  GlyphDesign design = parseDesign(kMinimal, "/base", model());
  EXPECT_EQ(design.levelsFor({{"p", 0.0}}), std::vector<int>{0});
  EXPECT_EQ(design.levelsFor({{"p", 49.9}}), std::vector<int>{0});
  EXPECT_EQ(design.levelsFor({{"p", 50.0}}), std::vector<int>{1});
  EXPECT_EQ(design.levelsFor({{"p", 100.0}}), std::vector<int>{1});
  design.variables[0].edge_belongs_below = {true};  // ]a, b] bins
  EXPECT_EQ(design.levelsFor({{"p", 50.0}}), std::vector<int>{0});
}

TEST(GlyphDesign, MixedBinsFollowTheTable) {
  // Table 6.8: < 50, [50, 100[, [100, 250], ]250, 500], ]500, 1000], > 1000.
  const GlyphDesign design =
      loadDesign(std::string(VICC_GLYPHS_DESIGNS_DIR) + "/covid19_gradient.yaml", model());
  const auto incidence = [&](double value) {
    return design.levelsFor({{"incidence", value},
                             {"hospitalisation", 1},
                             {"incidence_change", 0},
                             {"hospitalisation_change", 0}})[0];
  };
  EXPECT_EQ(incidence(49.9), 0);
  EXPECT_EQ(incidence(50), 1);
  EXPECT_EQ(incidence(100), 2);
  EXPECT_EQ(incidence(250), 2);
  EXPECT_EQ(incidence(250.1), 3);
  EXPECT_EQ(incidence(1000), 4);
  EXPECT_EQ(incidence(1000.1), 5);
  const auto change = [&](double value) {
    return design.levelsFor({{"incidence", 10},
                             {"hospitalisation", 1},
                             {"incidence_change", value},
                             {"hospitalisation_change", 0}})[2];
  };
  // Table 6.10: < -9, [-9, -3[, [-3, 3], ]3, 9], > 9.
  EXPECT_EQ(change(-9.1), 0);
  EXPECT_EQ(change(-9), 1);
  EXPECT_EQ(change(-3), 2);
  EXPECT_EQ(change(3), 2);
  EXPECT_EQ(change(3.1), 3);
  EXPECT_EQ(change(9), 3);
  EXPECT_EQ(change(9.1), 4);
  EXPECT_NE(errorOf(replaced(kMinimal, "edges: [50]",
                             "edges: [50]\n    edges_belong_below: [true, false]"))
                .find("edges_belong_below must be true/false or a list of one per edge"),
            std::string::npos);
}

TEST(GlyphDesign, BadValuesNameTheVariable) {
  const GlyphDesign design = parseDesign(kMinimal, "/base", model());
  const auto message = [&](const std::map<std::string, double>& values) {
    try {
      design.levelsFor(values);
    } catch (const DesignValueError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(message({{"p", std::nan("")}}).find("p is NaN"), std::string::npos);
  EXPECT_NE(message({{"p", 101.0}}).find("p = 101 is outside its domain [0, 100]"),
            std::string::npos);
  // Printed with enough digits not to read as inside the domain.
  EXPECT_NE(message({{"p", 100.0000001}}).find("p = 100.0000001 is outside"), std::string::npos)
      << message({{"p", 100.0000001}});
  EXPECT_NE(message({}).find("missing value for 'p'"), std::string::npos);
  EXPECT_NE(message({{"p", 1.0}, {"q", 1.0}}).find("no variable 'q'"), std::string::npos);
}

TEST(DesignValues, ParsesListsAndNamesBadEntries) {
  const auto values = parseValueList("probability=75,amount=3.5");
  EXPECT_DOUBLE_EQ(values.at("probability"), 75.0);
  EXPECT_DOUBLE_EQ(values.at("amount"), 3.5);
  EXPECT_TRUE(std::isnan(parseValueList("p=nan").at("p")));
  EXPECT_THROW(parseValueList("p"), DesignValueError);
  EXPECT_THROW(parseValueList("p=1,p=2"), DesignValueError);
  try {
    parseValueList("amount=lots");
    FAIL();
  } catch (const DesignValueError& e) {
    EXPECT_NE(std::string(e.what()).find("amount = 'lots' is not a number"), std::string::npos);
  }
  // A number too small for a normal double is still a number; hexadecimal and leading blanks
  // are not decimal numbers.
  EXPECT_EQ(parseValueList("p=1e-320").at("p"), 1e-320);
  EXPECT_THROW(parseValueList("p=0x55"), DesignValueError);
  EXPECT_THROW(parseValueList("p= 5"), DesignValueError);
}
