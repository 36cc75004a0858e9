// Loading views from YAML: the Table 4.1 view and the uniqueness rules of thesis 4.3.2.1.
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

TEST(EncodingConfigTest, ShippedViewHoldsTheFinalCategoriesOfTable41) {
  const EncodingModel& model = shippedModel();
  const View& view = model.view("neurological_status_sdh");
  // Table 4.1's five categories, and the intracranial pressure added for the ICP glyph.
  ASSERT_EQ(view.categories.size(), 6u);
  const std::vector<std::pair<std::string, std::vector<std::string>>> expected = {
      {"radicular_pain", {"dermatome"}},
      {"paresis", {"muscle"}},
      {"t_reflex", {"tendon"}},
      {"excretion_disorder", {"urethra", "anal_sphincter"}},
      {"sensory_disorder", {"dermatome"}},
      {"intracranial_pressure", {"brain"}}};
  for (std::size_t i = 0; i < expected.size(); ++i) {
    EXPECT_EQ(view.categories[i].category, expected[i].first);
    EXPECT_EQ(model.category(expected[i].first).spatial_refs, expected[i].second);
  }
  const Category& pain = model.category("radicular_pain");
  EXPECT_EQ(pain.property("intensity")->domain.describe(), "0..10");
  EXPECT_EQ(pain.property("trigger")->domain.describe(), "{constant, stress}");
  const Category& paresis = model.category("paresis");
  EXPECT_EQ(paresis.property("intensity")->domain.type, DataType::kOrdinal);
  ASSERT_TRUE(paresis.property("intensity")->source.has_value());
  EXPECT_EQ(paresis.property("intensity")->source->prop_type, "muscle_strength");
  EXPECT_EQ(paresis.property("intensity")->source->derive.at("3"), Value::label("moderate"));
  EXPECT_EQ(paresis.property("intensity")->source->derive.at("5"), Value::label("none"));
  EXPECT_EQ(model.category("t_reflex").property("intensity")->domain.describe(), "1..5");
  EXPECT_TRUE(model.category("excretion_disorder").property("intensity")->domain.isBinary());
  EXPECT_EQ(model.category("sensory_disorder").property("intensity")->domain.describe(), "0..4");
  EXPECT_EQ(model.category("sensory_disorder").property("paresthesia")->domain.describe(), "0..3");
  EXPECT_TRUE(model.report().global_warnings.empty());
}

TEST(EncodingConfigTest, UnknownViewIsNamedWithTheKnownOnes) {
  try {
    shippedModel().view("cardiology");
    FAIL();
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("unknown view 'cardiology' (known views: "
                                         "neurological_status_sdh, motor_status)"),
              std::string::npos);
  }
}

TEST(EncodingConfigTest, PropertyTypeMustBeUniqueWithinACategory) {
  YAML::Node root = shippedConfigYaml();
  YAML::Node props = entryWithId(root["categories"], "radicular_pain")["props"];
  props[1]["prop_type"] = "intensity";
  EXPECT_NE(rejection(root).find("category 'radicular_pain': property type 'intensity' appears "
                                 "twice (a property type is unique within a category)"),
            std::string::npos);
}

TEST(EncodingConfigTest, CategoryMustBeUniqueWithinAView) {
  YAML::Node root = shippedConfigYaml();
  YAML::Node view = entryWithId(root["views"], "motor_status");
  view["categories"][1]["category"] = "paresis";
  view["categories"][1]["hue"] = "blue";
  EXPECT_NE(rejection(root).find("view 'motor_status': category 'paresis' appears twice (a "
                                 "category is unique within a view)"),
            std::string::npos);
}

TEST(EncodingConfigTest, CategoryIdsAreUnique) {
  YAML::Node root = shippedConfigYaml();
  entryWithId(root["categories"], "t_reflex")["id"] = "paresis";
  EXPECT_NE(rejection(root).find("category 'paresis' is defined twice"), std::string::npos);
}

TEST(EncodingConfigTest, BrokenReferencesAreNamed) {
  {
    YAML::Node root = shippedConfigYaml();
    entryWithId(root["views"], "motor_status")["categories"][0]["hue"] = "turquoise";
    EXPECT_NE(rejection(root).find("category 'paresis' uses unknown hue 'turquoise'"),
              std::string::npos);
  }
  {
    YAML::Node root = shippedConfigYaml();
    entryWithId(root["categories"], "paresis")["spatial_ref"][0] = "bone";
    EXPECT_NE(rejection(root).find("category 'paresis': spatial reference 'bone' is not a "
                                   "structure class"),
              std::string::npos);
  }
  {
    YAML::Node root = shippedConfigYaml();
    entryWithId(root["categories"], "t_reflex")["props"][0]["visual_variable"] = "hue";
    EXPECT_NE(rejection(root).find("unknown visual variable 'hue' (hue is the category variable"),
              std::string::npos);
  }
  {
    YAML::Node root = shippedConfigYaml();
    entryWithId(root["categories"], "t_reflex")["props"][0]["normal"][0] = "7";
    EXPECT_NE(rejection(root).find("category 't_reflex', property 'intensity': normal value '7' "
                                   "is not in the domain 1..5"),
              std::string::npos);
  }
  {
    YAML::Node root = shippedConfigYaml();
    entryWithId(root["categories"], "paresis")["props"][0]["source"]["derive"].remove("2");
    EXPECT_NE(rejection(root).find("source value 2 of 'muscle_strength' has no derived value"),
              std::string::npos);
  }
}

TEST(EncodingConfigTest, TyposAndSyntaxErrorsNameFileAndLine) {
  YAML::Node root = shippedConfigYaml();
  entryWithId(root["categories"], "paresis")["spatial_reference"] = "muscle";
  EXPECT_NE(rejection(root).find("unknown key 'spatial_reference'"), std::string::npos);
  try {
    EncodingConfig::fromYamlText("hues:\n  - {name: red, degrees: 0\n", "broken.yaml");
    FAIL();
  } catch (const ConfigError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("broken.yaml:", 0), 0u) << e.what();
  }
  try {
    EncodingConfig::fromYamlText(
        "hues: [{name: red, degrees: zero}]\nvisual_variables: []\n"
        "categories: []\nviews: []\n",
        "typed.yaml");
    FAIL();
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("typed.yaml:1: hues[0].degrees: 'zero' is not a number"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace vicc_anatomy_viz
