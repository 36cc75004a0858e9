// Reading configuration YAML through libyaml: the rules the readers rely on (what counts as
// null, aliases, the first document only) and messages that name file, line and entry.
#include <gtest/gtest.h>

#include <string>

#include "../../src/core/yaml_reading.hpp"
#include "test_support.hpp"
#include "vicc_anatomy_viz/errors.hpp"

namespace vicc_anatomy_viz {
namespace {

using yaml_reading::Cursor;
using yaml_reading::parseText;

std::string errorOf(const std::string& yaml, const std::string& origin = "test.yaml") {
  try {
    parseText(yaml, origin);
  } catch (const ConfigError& e) {
    return e.what();
  }
  ADD_FAILURE() << "parsed: " << yaml;
  return "";
}

TEST(YamlReadingTest, OnlyUntaggedPlainNullsCountAsAbsent) {
  const Cursor root = parseText(
      "a: ~\nb: null\nc: NULL\nd:\ne: 'null'\nf: \"\"\ng: !!str null\nh: nulls\n", "t.yaml");
  for (const std::string key : {"a", "b", "c", "d"}) {
    EXPECT_FALSE(root.has(key)) << key;
    EXPECT_EQ(root.string(key, "fallback"), "fallback") << key;
  }
  EXPECT_EQ(root.string("e"), "null");
  EXPECT_EQ(root.string("f"), "");
  EXPECT_EQ(root.string("g"), "null");
  EXPECT_EQ(root.string("h"), "nulls");
  EXPECT_FALSE(root.has("missing"));
}

TEST(YamlReadingTest, ScalarsKeepTheirTextAndAreConvertedWithChecks) {
  const Cursor root = parseText(
      "n: 42\nx: -0.5\nflag: true\nquoted: '007'\nlist: [1, two, '3']\n"
      "block: |\n  line one\n  line two\n",
      "t.yaml");
  EXPECT_EQ(root.integer("n", 0), 42);
  EXPECT_DOUBLE_EQ(root.number("x"), -0.5);
  EXPECT_TRUE(root.boolean("flag", false));
  EXPECT_EQ(root.string("quoted"), "007");
  EXPECT_EQ(root.strings("list"), (std::vector<std::string>{"1", "two", "3"}));
  EXPECT_EQ(root.string("block"), "line one\nline two\n");
  try {
    root.sequence("list")[1].asInt();
    FAIL();
  } catch (const ConfigError& e) {
    EXPECT_STREQ(e.what(), "t.yaml:5: list[1]: 'two' is not an integer");
  }
}

TEST(YamlReadingTest, MapEntriesComeInFileOrderWithTheirPaths) {
  const Cursor root = parseText("derive:\n  2: weak\n  0: none\n  1: [x]\n", "t.yaml");
  const auto entries = root.child("derive").entries();
  ASSERT_EQ(entries.size(), 3u);
  EXPECT_EQ(entries[0].first, "2");
  EXPECT_EQ(entries[0].second.asString(), "weak");
  EXPECT_EQ(entries[1].first, "0");
  EXPECT_EQ(entries[1].second.path(), "derive.0");
  try {
    entries[2].second.asString();
    FAIL();
  } catch (const ConfigError& e) {
    EXPECT_STREQ(e.what(), "t.yaml:4: derive.1: expected a text value");
  }
  EXPECT_FALSE(entries[2].second.isMap());
  EXPECT_TRUE(root.child("derive").isMap());
}

TEST(YamlReadingTest, RepeatedKeysReadTheFirstAndUnknownKeysAreNamed) {
  const Cursor root = parseText("id: first\nid: second\nlable: x\n", "t.yaml");
  EXPECT_EQ(root.string("id"), "first");
  try {
    root.allowOnly({"id", "label"});
    FAIL();
  } catch (const ConfigError& e) {
    EXPECT_STREQ(e.what(), "t.yaml:1: unknown key 'lable' (known: id, label)");
  }
}

TEST(YamlReadingTest, AliasesResolveToTheAnchoredNode) {
  const Cursor root =
      parseText("levels: &three [1, 2, 3]\nother: *three\nname: &n pain\ncopy: *n\n", "t.yaml");
  EXPECT_EQ(root.strings("other"), (std::vector<std::string>{"1", "2", "3"}));
  EXPECT_EQ(root.string("copy"), "pain");
  EXPECT_EQ(errorOf("a: *nowhere\n"),
            "test.yaml:1:4: alias '*nowhere' names no anchor defined "
            "before it");
}

TEST(YamlReadingTest, SyntaxErrorsNameFileLineColumnAndContext) {
  EXPECT_EQ(errorOf("hues:\n  - {name: red, degrees: 0\n", "broken.yaml"),
            "broken.yaml:3:1: did not find expected ',' or '}' (while parsing a flow mapping "
            "started at line 2)");
  EXPECT_EQ(errorOf("a: b: c\n"), "test.yaml:1:5: mapping values are not allowed in this context");
  EXPECT_EQ(errorOf("a: \"\xff\"\n").rfind("test.yaml: invalid leading UTF-8 octet at byte", 0),
            0u);
}

TEST(YamlReadingTest, OnlyTheFirstDocumentIsRead) {
  const Cursor root = parseText("a: 1\n---\nb: [unclosed\n", "t.yaml");
  EXPECT_EQ(root.integer("a", 0), 1);
  EXPECT_FALSE(root.has("b"));
}

TEST(YamlReadingTest, AnEmptyDocumentIsNotAMap) {
  for (const std::string text : {"", "# only a comment\n", "~\n"}) {
    const Cursor root = parseText(text, "empty.yaml");
    EXPECT_FALSE(root.isMap());
    try {
      root.child("hues");
      FAIL() << text;
    } catch (const ConfigError& e) {
      EXPECT_STREQ(e.what(), "empty.yaml: expected a map with key 'hues'");
    }
  }
}

TEST(YamlReadingTest, CursorsKeepTheirDocumentAlive) {
  const Cursor item = parseText("list:\n  - {id: a}\n", "t.yaml").sequence("list")[0];
  EXPECT_EQ(item.string("id"), "a");
  EXPECT_EQ(item.where(), "t.yaml:2: list[0]");
}

TEST(YamlReadingTest, ShippedConfigurationReadsTheSameAfterAYamlCppRoundTrip) {
  // yaml-cpp writes the variants the other tests use; both readings must build equal views.
  const EncodingConfig direct = EncodingConfig::load(test::encodingConfigPath());
  const EncodingConfig round_trip =
      EncodingConfig::fromYamlText(YAML::Dump(test::shippedConfigYaml()), "dumped.yaml");
  ASSERT_EQ(direct.categories.size(), round_trip.categories.size());
  for (std::size_t i = 0; i < direct.categories.size(); ++i) {
    const Category& a = direct.categories[i];
    const Category& b = round_trip.categories[i];
    EXPECT_EQ(a.id, b.id);
    EXPECT_EQ(a.spatial_refs, b.spatial_refs);
    ASSERT_EQ(a.props.size(), b.props.size());
    for (std::size_t j = 0; j < a.props.size(); ++j) {
      EXPECT_EQ(a.props[j].domain.describe(), b.props[j].domain.describe());
      EXPECT_EQ(a.props[j].thresholds, b.props[j].thresholds);
      EXPECT_EQ(a.props[j].visual_variable, b.props[j].visual_variable);
    }
  }
  ASSERT_EQ(direct.hues.size(), round_trip.hues.size());
  for (std::size_t i = 0; i < direct.hues.size(); ++i) {
    EXPECT_EQ(direct.hues[i].name, round_trip.hues[i].name);
    EXPECT_DOUBLE_EQ(direct.hues[i].degrees, round_trip.hues[i].degrees);
  }
  EXPECT_EQ(direct.views.size(), round_trip.views.size());
}

}  // namespace
}  // namespace vicc_anatomy_viz
