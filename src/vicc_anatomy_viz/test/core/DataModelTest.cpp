// Property domains and values (thesis 4.3.2.1).
#include <gtest/gtest.h>

#include "vicc_anatomy_viz/data_model.hpp"
#include "vicc_anatomy_viz/errors.hpp"

namespace vicc_anatomy_viz {
namespace {

Domain numerical(int min, int max) {
  Domain domain;
  domain.type = DataType::kNumerical;
  domain.min = min;
  domain.max = max;
  return domain;
}

Domain labels(DataType type, std::vector<std::string> labels) {
  Domain domain;
  domain.type = type;
  domain.labels = std::move(labels);
  return domain;
}

TEST(DataModelTest, NumericalDomainContainsItsRangeOnly) {
  const Domain pain = numerical(0, 10);
  EXPECT_EQ(pain.size(), 11u);
  EXPECT_TRUE(pain.contains(Value::number(0)));
  EXPECT_TRUE(pain.contains(Value::number(10)));
  EXPECT_FALSE(pain.contains(Value::number(11)));
  EXPECT_FALSE(pain.contains(Value::number(-1)));
  EXPECT_FALSE(pain.contains(Value::label("10")));
  EXPECT_EQ(pain.describe(), "0..10");
  EXPECT_EQ(pain.indexOf(Value::number(7)), 7);
}

TEST(DataModelTest, OrdinalDomainKeepsItsOrder) {
  const Domain paresis = labels(DataType::kOrdinal, {"none", "mild", "moderate", "severe"});
  EXPECT_EQ(paresis.indexOf(Value::label("moderate")), 2);
  EXPECT_EQ(paresis.values().back(), Value::label("severe"));
  EXPECT_FALSE(paresis.contains(Value::number(2)));
  EXPECT_EQ(paresis.describe(), "{none, mild, moderate, severe}");
  EXPECT_FALSE(paresis.isBinary());
  EXPECT_TRUE(labels(DataType::kNominal, {"false", "true"}).isBinary());
}

TEST(DataModelTest, TextIsParsedWithTheDomainType) {
  EXPECT_EQ(numerical(0, 10).parse("8"), Value::number(8));
  EXPECT_FALSE(numerical(0, 10).parse("8.5").has_value());
  EXPECT_FALSE(numerical(0, 10).parse("eight").has_value());
  EXPECT_FALSE(numerical(0, 10).parse("").has_value());
  EXPECT_EQ(labels(DataType::kNominal, {"constant", "stress"}).parse("stress"),
            Value::label("stress"));
}

TEST(DataModelTest, MalformedDomainsAreRejectedByName) {
  EXPECT_THROW(numerical(5, 1).validate("x"), ConfigError);
  EXPECT_THROW(labels(DataType::kNominal, {}).validate("x"), ConfigError);
  try {
    labels(DataType::kNominal, {"a", "b", "a"}).validate("category 'c', property 'p'");
    FAIL() << "duplicate label accepted";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("category 'c', property 'p': label 'a' appears twice"),
              std::string::npos);
  }
  EXPECT_THROW(dataTypeFromString("interval"), ConfigError);
}

TEST(DataModelTest, NormalValuesAndDefaults) {
  Property trigger;
  trigger.prop_type = "trigger";
  trigger.domain = labels(DataType::kNominal, {"constant", "stress"});
  trigger.normal = {Value::label("constant")};
  EXPECT_TRUE(trigger.isNormal(Value::label("constant")));
  EXPECT_FALSE(trigger.isNormal(Value::label("stress")));
  EXPECT_EQ(trigger.defaultValue(), Value::label("constant"));
}

}  // namespace
}  // namespace vicc_anatomy_viz
