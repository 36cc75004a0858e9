#include <gtest/gtest.h>

#include "../../src/tools/command_line.hpp"

namespace vicc_glyphs::tools {
namespace {

const std::vector<OptionSpec> kSpecs{
    {"out", "FILE", "output"}, {"size", "N", "width"}, {"report", "", "print a report"}};

TEST(CommandLineTest, ParsesValuesFlagsAndPositionals) {
  const ParsedArguments parsed =
      parseArguments({"in.svg", "--out", "a.png", "--size=64", "--report"}, kSpecs);
  EXPECT_EQ(parsed.positional, std::vector<std::string>{"in.svg"});
  EXPECT_EQ(parsed.value("out"), "a.png");
  EXPECT_EQ(parsed.value("size"), "64");
  EXPECT_TRUE(parsed.has("report"));
  EXPECT_FALSE(parsed.has("missing"));
  EXPECT_EQ(parsed.value("missing", "fallback"), "fallback");
}

TEST(CommandLineTest, RejectsMistakes) {
  EXPECT_THROW(parseArguments({"--colour", "red"}, kSpecs), UsageError);
  EXPECT_THROW(parseArguments({"--out"}, kSpecs), UsageError);
  EXPECT_THROW(parseArguments({"--report=yes"}, kSpecs), UsageError);
  EXPECT_THROW(parseArguments({"-o", "x"}, kSpecs), UsageError);
}

TEST(CommandLineTest, DoubleDashEndsOptions) {
  const ParsedArguments parsed = parseArguments({"--", "--out"}, kSpecs);
  EXPECT_EQ(parsed.positional, std::vector<std::string>{"--out"});
}

TEST(CommandLineTest, IntegersAreCheckedAgainstTheirRange) {
  EXPECT_EQ(parseInteger("size", "512", 1, 1000), 512);
  EXPECT_THROW(parseInteger("size", "0", 1, 1000), UsageError);
  EXPECT_THROW(parseInteger("size", "12px", 1, 1000), UsageError);
  EXPECT_THROW(parseInteger("size", "", 1, 1000), UsageError);
  EXPECT_THROW(parseInteger("size", "99999999999999", 1, 1000), UsageError);
}

}  // namespace
}  // namespace vicc_glyphs::tools
