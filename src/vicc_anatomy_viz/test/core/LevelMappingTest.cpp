// Step 4 of the mapping: property values -> visual levels (Table 4.1, right block).
#include <gtest/gtest.h>

#include "test_support.hpp"

namespace vicc_anatomy_viz {
namespace {

using test::shippedModel;

const LevelMapping& levels(const std::string& category, const std::string& prop) {
  return shippedModel().levels(category, prop);
}

TEST(LevelMappingTest, PainIntensityTenValuesThreeLevels) {
  const LevelMapping& pain = levels("radicular_pain", "intensity");
  EXPECT_EQ(pain.levelCount(), 3);
  EXPECT_EQ(pain.displayedValueCount(), 10);
  EXPECT_TRUE(pain.quantized());
  const std::vector<int> expected = {0, 1, 1, 1, 2, 2, 2, 3, 3, 3, 3};
  for (int value = 0; value <= 10; ++value) {
    EXPECT_EQ(pain.levelOf(Value::number(value)), expected[value]) << value;
  }
}

TEST(LevelMappingTest, EveryOtherTable41PropertyIsInjective) {
  const std::vector<std::tuple<std::string, std::string, int>> rows = {
      {"radicular_pain", "trigger", 1},     {"paresis", "intensity", 3},
      {"t_reflex", "intensity", 5},         {"excretion_disorder", "intensity", 1},
      {"sensory_disorder", "intensity", 4}, {"sensory_disorder", "paresthesia", 3}};
  for (const auto& [category, prop, count] : rows) {
    const LevelMapping& mapping = levels(category, prop);
    EXPECT_EQ(mapping.levelCount(), count) << category << "." << prop;
    EXPECT_FALSE(mapping.quantized()) << category << "." << prop;
  }
}

TEST(LevelMappingTest, NormalValuesHaveNoLevel) {
  EXPECT_EQ(levels("radicular_pain", "trigger").levelOf(Value::label("constant")), 0);
  EXPECT_EQ(levels("radicular_pain", "trigger").levelOf(Value::label("stress")), 1);
  EXPECT_EQ(levels("paresis", "intensity").levelOf(Value::label("none")), 0);
  EXPECT_EQ(levels("paresis", "intensity").levelOf(Value::label("mild")), 1);
  EXPECT_EQ(levels("paresis", "intensity").levelOf(Value::label("severe")), 3);
  EXPECT_EQ(levels("excretion_disorder", "intensity").levelOf(Value::label("false")), 0);
  EXPECT_EQ(levels("excretion_disorder", "intensity").levelOf(Value::label("true")), 1);
  EXPECT_EQ(levels("sensory_disorder", "intensity").levelOf(Value::number(4)), 4);
}

TEST(LevelMappingTest, ReflexComparesSidesSoItsNormalValueHasALevel) {
  const LevelMapping& reflex = levels("t_reflex", "intensity");
  for (int value = 1; value <= 5; ++value) EXPECT_EQ(reflex.levelOf(Value::number(value)), value);
}

TEST(LevelMappingTest, WithoutThresholdsValuesAreSplitEvenly) {
  Category category;
  category.id = "pain";
  Property prop;
  prop.prop_type = "intensity";
  prop.domain.type = DataType::kNumerical;
  prop.domain.min = 1;
  prop.domain.max = 10;
  VisualVariable variable;
  variable.id = "sb";
  variable.range = 3;
  const LevelMapping mapping(category, prop, variable);
  EXPECT_EQ(mapping.levelCount(), 3);
  EXPECT_EQ(mapping.valuesAtLevel(1).size(), 4u);  // 1-4
  EXPECT_EQ(mapping.valuesAtLevel(2).size(), 3u);  // 5-7
  EXPECT_EQ(mapping.valuesAtLevel(3).size(), 3u);  // 8-10
}

}  // namespace
}  // namespace vicc_anatomy_viz
