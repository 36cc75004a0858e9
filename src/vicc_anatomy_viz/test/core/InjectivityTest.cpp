// The injectivity requirements of thesis 4.3.2.4: local (rejected), global (warned), spatial
// (resolved by alternation) and property domain (quantization reported).
#include <gtest/gtest.h>

#include "test_support.hpp"
#include "vicc_anatomy_viz/errors.hpp"

namespace vicc_anatomy_viz {
namespace {

using test::entryWithId;
using test::modelFrom;
using test::rejection;
using test::shippedConfigYaml;
using test::shippedModel;

TEST(InjectivityTest, LocalCategoryMappingViolationIsRejected) {
  YAML::Node root = shippedConfigYaml();
  entryWithId(root["views"], "neurological_status_sdh")["categories"][1]["hue"] = "red";
  EXPECT_NE(rejection(root).find("view 'neurological_status_sdh': categories 'radicular_pain', "
                                 "'paresis' are all mapped to hue 'red' (M^c must be injective "
                                 "within a view)"),
            std::string::npos);
}

TEST(InjectivityTest, LocalPropertyMappingViolationIsRejected) {
  YAML::Node root = shippedConfigYaml();
  entryWithId(root["categories"], "sensory_disorder")["props"][1]["visual_variable"] =
      "saturation_brightness";
  EXPECT_NE(rejection(root).find("category 'sensory_disorder': properties 'intensity', "
                                 "'paresthesia' are all mapped to visual variable "
                                 "'saturation_brightness' (M^t must be injective within a "
                                 "category)"),
            std::string::npos);
}

TEST(InjectivityTest, TwoTexturesOnOneCategoryAreRejected) {
  YAML::Node root = shippedConfigYaml();
  YAML::Node quality = YAML::Load(
      "{prop_type: quality, data_type: nominal, domain: [dull, burning], normal: [dull], "
      "visual_variable: noise}");
  entryWithId(root["categories"], "radicular_pain")["props"].push_back(quality);
  EXPECT_NE(rejection(root).find("category 'radicular_pain': properties 'trigger', 'quality' use "
                                 "visual variables of the same channel 'texture'"),
            std::string::npos);
}

TEST(InjectivityTest, GlobalViolationsAreWarningsOnly) {
  YAML::Node root = shippedConfigYaml();
  entryWithId(root["views"], "motor_status")["categories"][0]["hue"] = "blue";
  entryWithId(root["categories"], "t_reflex")["props"][0]["visual_variable"] = "transparency";
  const EncodingModel model = modelFrom(root);
  const auto& warnings = model.report().global_warnings;
  auto has = [&](const std::string& fragment) {
    for (const auto& warning : warnings) {
      if (warning.find(fragment) != std::string::npos) return true;
    }
    return false;
  };
  EXPECT_TRUE(has("category 'paresis' has different hues in different views ('blue', 'purple')"));
  EXPECT_TRUE(
      has("property type 'intensity' is encoded by different visual variables "
          "('saturation_brightness', 'transparency')"));
  EXPECT_TRUE(model.report().local_violations.empty());
}

TEST(InjectivityTest, SpatialConflictOfPainAndSensoryDisorderIsDetected) {
  const auto& conflicts = shippedModel().report().spatial_conflicts;
  ASSERT_EQ(conflicts.size(), 1u);
  EXPECT_EQ(conflicts[0].view, "neurological_status_sdh");
  EXPECT_EQ(conflicts[0].category_a, "radicular_pain");
  EXPECT_EQ(conflicts[0].category_b, "sensory_disorder");
  EXPECT_EQ(conflicts[0].shared_classes, std::vector<std::string>{"dermatome"});
  EXPECT_NE(conflicts[0].message.find("shown alternately"), std::string::npos);
  EXPECT_NE(conflicts[0].message.find("category filter"), std::string::npos);
}

TEST(InjectivityTest, PainIntensityQuantizationIsReported) {
  const auto& quantizations = shippedModel().report().quantizations;
  // Of Table 4.1 only the pain intensity is quantized; the added ICP (65 abnormal mmHg values,
  // elevated/pathological) is too -- the glyph above the head shows its value.
  ASSERT_EQ(quantizations.size(), 2u);
  EXPECT_EQ(quantizations[0].category, "radicular_pain");
  EXPECT_EQ(quantizations[0].prop_type, "intensity");
  EXPECT_EQ(quantizations[0].values, 10);
  EXPECT_EQ(quantizations[0].levels, 3);
  EXPECT_NE(quantizations[0].message.find("quantized: 1-3, 4-6, 7-10"), std::string::npos);
  EXPECT_EQ(quantizations[1].category, "intracranial_pressure");
  EXPECT_EQ(quantizations[1].values, 65);
  EXPECT_EQ(quantizations[1].levels, 2);
  EXPECT_NE(quantizations[1].message.find("16-22, 23-80"), std::string::npos)
      << quantizations[1].message;
  const auto notes = shippedModel().notes(shippedModel().view("neurological_status_sdh"));
  EXPECT_EQ(notes.size(), 3u);  // the two quantizations and the spatial conflict
  EXPECT_TRUE(shippedModel().notes(shippedModel().view("motor_status")).empty());
}

TEST(InjectivityTest, UnrealisableLevelsAreRejected) {
  YAML::Node root = shippedConfigYaml();
  for (std::size_t i = 0; i < root["visual_variables"].size(); ++i) {
    if (root["visual_variables"][i]["id"].as<std::string>() == "saturation_brightness") {
      root["visual_variables"][i]["range"] = 3;
    }
  }
  entryWithId(root["categories"], "t_reflex")["props"][0]["levels"] = 5;
  EXPECT_NE(rejection(root).find("category 't_reflex', property 'intensity': 5 levels, but "
                                 "visual variable 'saturation_brightness' distinguishes only 3"),
            std::string::npos);
}

TEST(InjectivityTest, NarrowerRangeQuantizesInsteadOfFailing) {
  YAML::Node root = shippedConfigYaml();
  for (std::size_t i = 0; i < root["visual_variables"].size(); ++i) {
    if (root["visual_variables"][i]["id"].as<std::string>() == "saturation_brightness") {
      root["visual_variables"][i]["range"] = 3;
    }
  }
  const EncodingModel model = modelFrom(root);
  std::vector<std::string> quantized;
  for (const auto& q : model.report().quantizations) quantized.push_back(q.category);
  EXPECT_EQ(quantized, (std::vector<std::string>{"radicular_pain", "t_reflex", "sensory_disorder",
                                                 "intracranial_pressure"}));
}

}  // namespace
}  // namespace vicc_anatomy_viz
