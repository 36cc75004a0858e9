// Standard codings beside ours (config/fhir/standard_codes.yaml): the shipped LOINC code for
// the pain intensity, and rejection of codings without a published source.
#include <gtest/gtest.h>

#include <string>

#include "../core/test_support.hpp"
#include "vicc_anatomy_viz/errors.hpp"
#include "vicc_anatomy_viz/fhir_standard_codes.hpp"

namespace vicc_anatomy_viz {
namespace {

using nlohmann::json;

const char* const kSourced = R"(codes:
  radicular_pain.intensity:
    - system: http://loinc.org
      code: 72514-3
      display: Pain severity
      source: {name: a publication, version: "1.0", file: codes.json}
)";

std::string rejection(const std::string& yaml_text) {
  try {
    StandardCodes::fromYamlText(yaml_text, "codes.yaml");
  } catch (const ConfigError& e) {
    return e.what();
  }
  ADD_FAILURE() << "accepted:\n" << yaml_text;
  return "";
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  return text.replace(text.find(from), from.size(), to);
}

TEST(StandardCodesTest, ShippedPainIntensityHasTheLoincNumericRatingScale) {
  const json expected = {
      {"system", "http://loinc.org"},
      {"code", "72514-3"},
      {"display", "Pain severity - 0-10 verbal numeric rating [Score] - Reported"}};
  EXPECT_EQ(standardCodings("radicular_pain.intensity"), std::vector<json>{expected});
  const auto& entries = shippedStandardCodes().entries("radicular_pain.intensity");
  ASSERT_EQ(entries.size(), 1u);
  EXPECT_NE(entries[0].source.find("hl7-eu/eps"), std::string::npos) << entries[0].source;
  EXPECT_NE(entries[0].source.find("1cdebaff-a26d-404e-9cc1-51246e489456.fsh"), std::string::npos);
}

TEST(StandardCodesTest, CodesWithoutAPublishedStandardCodeHaveNone) {
  EXPECT_TRUE(standardCodings("dermatome_L5").empty());
  EXPECT_TRUE(standardCodings("paresis.muscle_strength").empty());
  EXPECT_TRUE(standardCodings("no_such_code").empty());
}

TEST(StandardCodesTest, ShippedKeysAreCodesOfTheShippedModel) {
  EXPECT_EQ(
      shippedStandardCodes().ourCodes(),
      (std::vector<std::string>{"intracranial_pressure.intensity", "radicular_pain.intensity"}));
  EXPECT_TRUE(shippedStandardCodes().unknownCodes(test::shippedModel()).empty());
}

TEST(StandardCodesTest, UnknownCodesNamesMisspeltKeys) {
  const StandardCodes codes = StandardCodes::fromYamlText(
      replaced(kSourced, "radicular_pain.intensity", "radicular_pain.intensty"), "codes.yaml");
  EXPECT_EQ(codes.unknownCodes(test::shippedModel()),
            std::vector<std::string>{"radicular_pain.intensty"});
}

TEST(StandardCodesTest, AcceptsASourcedCodingAndKeepsItsSource) {
  const StandardCodes codes = StandardCodes::fromYamlText(kSourced, "codes.yaml");
  ASSERT_EQ(codes.entries("radicular_pain.intensity").size(), 1u);
  EXPECT_EQ(codes.entries("radicular_pain.intensity")[0].source, "a publication, 1.0, codes.json");
}

TEST(StandardCodesTest, RejectsACodingWithoutSource) {
  const std::string message = rejection(replaced(
      kSourced, "      source: {name: a publication, version: \"1.0\", file: codes.json}\n", ""));
  EXPECT_NE(message.find("codes.yaml"), std::string::npos) << message;
  EXPECT_NE(message.find("codes.radicular_pain.intensity[0]"), std::string::npos) << message;
  EXPECT_NE(message.find("missing 'source'"), std::string::npos) << message;
}

TEST(StandardCodesTest, RejectsASourceWithoutFileOrWithAnEmptyVersion) {
  EXPECT_NE(rejection(replaced(kSourced, ", file: codes.json", "")).find("missing 'file'"),
            std::string::npos);
  EXPECT_NE(rejection(replaced(kSourced, "\"1.0\"", "\"\"")).find("'version' is empty"),
            std::string::npos);
}

TEST(StandardCodesTest, RejectsMalformedCodings) {
  EXPECT_NE(rejection(replaced(kSourced, "http://loinc.org", "loinc")).find("absolute"),
            std::string::npos);
  EXPECT_NE(rejection(replaced(kSourced, "code: 72514-3", "code: \" 72514-3\""))
                .find("surrounding whitespace"),
            std::string::npos);
  EXPECT_NE(rejection(replaced(kSourced, "display:", "dispaly:")).find("dispaly"),
            std::string::npos);
  const std::string coding = std::string(kSourced).substr(std::string(kSourced).find("    - "));
  EXPECT_NE(rejection(std::string(kSourced) + coding).find("listed twice"), std::string::npos);
}

}  // namespace
}  // namespace vicc_anatomy_viz
