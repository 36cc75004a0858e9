#include <gtest/gtest.h>

#include <set>
#include <string>

#include "test_config.hpp"
#include "vicc_common/json_parameters.hpp"
#include "vicc_common/parameter_names.hpp"
#include "vicc_common/yaml_parameters.hpp"

namespace vicc_common_test {
namespace {

using vicc_common::parseYamlParameters;

std::string errorOf(const std::string& yaml) {
  try {
    parseYamlParameters<Outer>(yaml, "test.yaml");
  } catch (const std::invalid_argument& error) {
    return error.what();
  }
  return "no error";
}

TEST(YamlParameters, ReadsEveryTypeAndKeepsDefaultsOfKeysLeftOut) {
  const Outer config = parseYamlParameters<Outer>(
      "count: 7\nenabled: true\nname: probe\nweights: [1.5, 2]\nshape: square\n"
      "inner:\n  gain: 2.25\n",
      "test.yaml");
  EXPECT_EQ(config.count, 7);
  EXPECT_TRUE(config.enabled);
  EXPECT_EQ(config.name, "probe");
  EXPECT_EQ(config.weights, (std::vector<double>{1.5, 2.0}));
  EXPECT_EQ(config.shape, Shape::kSquare);
  EXPECT_DOUBLE_EQ(config.inner.gain, 2.25);
  EXPECT_EQ(config.inner.levels, (std::vector<int>{4, 2}));  // default kept
}

TEST(YamlParameters, EmptyTextAndEmptySectionKeepAllDefaults) {
  EXPECT_EQ(parseYamlParameters<Outer>("", "empty.yaml").count, 3);
  EXPECT_DOUBLE_EQ(parseYamlParameters<Outer>("inner:\n", "t.yaml").inner.gain, 0.5);
}

TEST(YamlParameters, UnknownKeysAreNamedWithTheirPathAndTheKnownKeys) {
  EXPECT_EQ(errorOf("cuont: 1\n"),
            "test.yaml: cuont: unknown key (known here: count, enabled, name, weights, shape, "
            "inner)");
  EXPECT_EQ(errorOf("inner:\n  gian: 1\n"),
            "test.yaml: inner/gian: unknown key (known here: gain, levels)");
}

TEST(YamlParameters, WrongTypesAreNamedWithTheExpectedType) {
  EXPECT_EQ(errorOf("count: many\n"),
            "test.yaml: count: has the wrong type: expected an integer, got 'many'");
  EXPECT_EQ(errorOf("count: 1.5\n"),
            "test.yaml: count: has the wrong type: expected an integer, got '1.5'");
  EXPECT_EQ(errorOf("enabled: maybe\n"),
            "test.yaml: enabled: has the wrong type: expected true or false, got 'maybe'");
  EXPECT_EQ(errorOf("name: [a, b]\n"),
            "test.yaml: name: has the wrong type: expected a string, got a list");
  EXPECT_EQ(errorOf("inner:\n  levels: 3\n"),
            "test.yaml: inner/levels: has the wrong type: expected a list of integers, got '3'");
  EXPECT_EQ(errorOf("inner: 3\n"), "test.yaml: inner: must be a section of keys, got '3'");
}

TEST(YamlParameters, TextValuesAndValidateNameTheKey) {
  EXPECT_EQ(errorOf("shape: hexagon\n"),
            "test.yaml: shape: unknown shape 'hexagon' (circle or square)");
  EXPECT_EQ(errorOf("inner:\n  gain: -1\n"), "test.yaml: inner: gain must be > 0");
  EXPECT_EQ(errorOf("count: -2\n"), "test.yaml: count must be >= 0");
}

TEST(YamlParameters, InvalidYamlAndNonMapsAreRejected) {
  EXPECT_NE(errorOf("count: [1\n").find("test.yaml: not valid YAML"), std::string::npos);
  EXPECT_EQ(errorOf("- 1\n- 2\n"), "test.yaml: expected a map of parameters");
}

TEST(YamlParameters, WriterOutputReadsBackToTheSameValues) {
  Outer config;
  config.count = 11;
  config.enabled = true;
  config.name = "a b";
  config.weights = {0.1, 1e-7};
  config.shape = Shape::kSquare;
  config.inner.gain = 1.0 / 3.0;
  config.inner.levels = {9};
  const std::string yaml = vicc_common::toYamlParameters(config);
  const Outer read = parseYamlParameters<Outer>(yaml, "written");
  EXPECT_EQ(read.count, 11);
  EXPECT_TRUE(read.enabled);
  EXPECT_EQ(read.name, "a b");
  EXPECT_EQ(read.weights, config.weights);  // exact: shortest round-trip text
  EXPECT_EQ(read.shape, Shape::kSquare);
  EXPECT_EQ(read.inner.gain, config.inner.gain);
  EXPECT_EQ(read.inner.levels, (std::vector<int>{9}));
  EXPECT_NE(yaml.find("shape: square"), std::string::npos) << yaml;
}

TEST(YamlParameters, NameCollectorListsKeyPaths) {
  std::set<std::string> names;
  vicc_common::collectParameterNames(Outer{}, names);
  EXPECT_EQ(names, (std::set<std::string>{"count", "enabled", "name", "weights", "shape",
                                          "inner/gain", "inner/levels"}));
}

TEST(YamlParameters, JsonWriterNestsSectionsAndWritesTextTypesAsText) {
  Outer config;
  config.shape = Shape::kSquare;
  nlohmann::json json;
  vicc_common::writeJsonParameters(config, json);
  EXPECT_EQ(json["count"], 3);
  EXPECT_EQ(json["shape"], "square");
  EXPECT_EQ(json["inner"]["levels"], nlohmann::json::array({4, 2}));
  EXPECT_DOUBLE_EQ(json["inner"]["gain"].get<double>(), 0.5);
}

TEST(YamlParameters, MissingFileIsNamed) {
  try {
    vicc_common::loadYamlParameters<Outer>("/nonexistent/params.yaml");
    FAIL() << "no error";
  } catch (const std::invalid_argument& error) {
    EXPECT_STREQ(error.what(), "cannot read the parameter file /nonexistent/params.yaml");
  }
}

}  // namespace
}  // namespace vicc_common_test
