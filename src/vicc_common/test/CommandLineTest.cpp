#include <gtest/gtest.h>

#include "vicc_common/command_line.hpp"

namespace vicc_common::cli {
namespace {

const std::vector<OptionSpec> kSpecs = {
    {"size", "PIXELS", "edge length"},
    {"scale", "FACTOR", "zoom"},
    {"json", "", "machine-readable output"},
    {"config", "FILE", "settings, applied in order", true},
};

std::string usageErrorOf(const std::vector<std::string>& args) {
  try {
    parseArguments(args, kSpecs);
  } catch (const UsageError& error) {
    return error.what();
  }
  return "no error";
}

TEST(CommandLine, ParsesBothValueFormsFlagsAndPositionals) {
  const ParsedArguments parsed =
      parseArguments({"in.svg", "--size", "64", "--scale=1.5", "--json", "-", "out.png"}, kSpecs);
  EXPECT_EQ(parsed.positional, (std::vector<std::string>{"in.svg", "-", "out.png"}));
  EXPECT_EQ(parsed.value("size"), "64");
  EXPECT_EQ(parsed.value("scale"), "1.5");
  EXPECT_TRUE(parsed.flag("json"));
  EXPECT_TRUE(parsed.has("size"));
  EXPECT_FALSE(parsed.has("other"));
  EXPECT_EQ(parsed.value("missing", "fallback"), "fallback");
}

TEST(CommandLine, RepeatableOptionsKeepEveryValueInOrder) {
  const ParsedArguments parsed = parseArguments({"--config=a", "--config", "b"}, kSpecs);
  EXPECT_EQ(parsed.value("config"), "b");  // the last one for value()
  EXPECT_EQ(parsed.all("config"), (std::vector<std::string>{"a", "b"}));
  EXPECT_TRUE(parsed.all("scale").empty());
}

// Taking the last of two values would silently do something else than the first asked for.
TEST(CommandLine, AnOptionGivenTwiceThatIsNotRepeatableIsAUsageError) {
  EXPECT_EQ(usageErrorOf({"--size=1", "--size", "2"}), "option '--size' is given more than once");
  EXPECT_EQ(usageErrorOf({"--size", "1", "--size", "1"}),
            "option '--size' is given more than once");
  EXPECT_EQ(usageErrorOf({"--json", "--json"}), "no error");  // a flag twice is the same flag
}

// An output that names an input (or another output), also through another spelling of the
// path, is refused before anything is written; empty paths (options not given) are ignored.
TEST(CommandLine, TheSameFileUnderTwoOptionsIsAUsageError) {
  EXPECT_NO_THROW(requireDistinctFiles({{"INPUT", "a.svg"}, {"--out", "a.png"}, {"--dci", ""}}));
  try {
    requireDistinctFiles({{"INPUT", "dir/../a.png"}, {"--out", "./a.png"}});
    ADD_FAILURE() << "no error";
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("INPUT and --out are the same file (./a.png)"),
              std::string::npos)
        << e.what();
  }
  EXPECT_THROW(requireDistinctFiles({{"INPUT", "x"}, {"--out", "y"}, {"--report", "y"}}),
               UsageError);
}

TEST(CommandLine, UsageErrorIsAnInvalidArgument) {
  EXPECT_THROW(parseArguments({"--nope"}, kSpecs), std::invalid_argument);
}

TEST(CommandLine, DoubleDashEndsTheOptions) {
  const ParsedArguments parsed = parseArguments({"--", "--size", "-x"}, kSpecs);
  EXPECT_EQ(parsed.positional, (std::vector<std::string>{"--size", "-x"}));
  EXPECT_TRUE(parsed.values.empty());
}

TEST(CommandLine, MistakesAreUsageErrorsThatSayWhat) {
  EXPECT_EQ(usageErrorOf({"--sise", "3"}), "unknown option '--sise'");
  EXPECT_EQ(usageErrorOf({"-s"}), "unknown option '-s' (options start with --)");
  EXPECT_EQ(usageErrorOf({"--size"}), "option '--size' needs a value PIXELS");
  EXPECT_EQ(usageErrorOf({"--json=yes"}), "option '--json' takes no value");
}

TEST(CommandLine, TypedGettersCheckRanges) {
  const ParsedArguments parsed = parseArguments({"--size", "64", "--scale", "2.5e-1"}, kSpecs);
  EXPECT_EQ(parsed.integer("size", 1, 1, 4096), 64);
  EXPECT_DOUBLE_EQ(parsed.number("scale", 1.0, 0.0, 10.0), 0.25);
  EXPECT_EQ(parsed.integer("absent", 7, 1, 10), 7);
  EXPECT_THROW(parsed.integer("size", 1, 1, 32), UsageError);
  EXPECT_THROW(parsed.number("scale", 1.0, 0.5, 10.0), UsageError);
  EXPECT_EQ(parsed.required("size", "render"), "64");
  try {
    parsed.required("json", "render");
    FAIL() << "no error";
  } catch (const UsageError& error) {
    EXPECT_STREQ(error.what(), "render needs --json");
  }
}

TEST(CommandLine, NumberParsingRejectsJunkAndNonFinite) {
  EXPECT_EQ(parseInteger("n", "12", 0, 20), 12);
  for (const char* text : {"", "12x", "1.5", " 3", "99"}) {
    EXPECT_THROW(parseInteger("n", text, 0, 20), UsageError) << text;
  }
  try {
    parseInteger("n", "abc", 0, 20);
  } catch (const UsageError& error) {
    EXPECT_STREQ(error.what(), "option '--n' needs an integer from 0 to 20, got 'abc'");
  }
  EXPECT_DOUBLE_EQ(parseNumber("x", "-0.5", -1.0, 1.0), -0.5);
  for (const char* text : {"nan", "inf", "1e999", "0.5m", "2"}) {
    EXPECT_THROW(parseNumber("x", text, -1.0, 1.0), UsageError) << text;
  }
}

TEST(CommandLine, HelpAlignsTheOptions) {
  EXPECT_EQ(formatOptions(kSpecs),
            "  --size PIXELS   edge length\n"
            "  --scale FACTOR  zoom\n"
            "  --json          machine-readable output\n"
            "  --config FILE   settings, applied in order\n");
  EXPECT_EQ(helpText("tool [options] FILE", "Does a thing.", {kSpecs[2]}),
            "usage: tool [options] FILE\nDoes a thing.\noptions:\n"
            "  --json  machine-readable output\n");
}

// runTool with these arguments; the exit code, stdout and stderr.
struct ToolRun {
  int code;
  std::string out, err;
};
ToolRun runToolWith(std::vector<std::string> arguments,
                    const std::function<int(const std::vector<std::string>&)>& run) {
  arguments.insert(arguments.begin(), "tool");
  std::vector<char*> argv;
  for (std::string& argument : arguments) argv.push_back(argument.data());
  testing::internal::CaptureStdout();
  testing::internal::CaptureStderr();
  const int code =
      runTool("tool", static_cast<int>(argv.size()), argv.data(), "usage: tool\n", run);
  const std::string out = testing::internal::GetCapturedStdout();
  return {code, out, testing::internal::GetCapturedStderr()};
}

TEST(RunToolTest, HelpAlonePrintsTheUsageWithoutRunning) {
  bool ran = false;
  const auto run = [&ran](const std::vector<std::string>&) { return ran = true, 0; };
  for (const std::string help : {"--help", "-h"}) {
    const ToolRun result = runToolWith({help}, run);
    EXPECT_EQ(result.code, 0);
    EXPECT_EQ(result.out, "usage: tool\n");
  }
  EXPECT_FALSE(ran);
}

TEST(RunToolTest, ExitCodesSayWhatWentWrong) {
  const ToolRun passed = runToolWith({"a", "b"}, [](const std::vector<std::string>& args) {
    return args == std::vector<std::string>{"a", "b"} ? 3 : 4;
  });
  EXPECT_EQ(passed.code, 3);
  const ToolRun usage = runToolWith({"--bad"}, [](const std::vector<std::string>&) -> int {
    throw UsageError("unknown option '--bad'");
  });
  EXPECT_EQ(usage.code, 2);
  EXPECT_EQ(usage.err, "tool: unknown option '--bad'\nusage: tool\n");
  const ToolRun failed = runToolWith({}, [](const std::vector<std::string>&) -> int {
    throw std::runtime_error("cannot open x.db");
  });
  EXPECT_EQ(failed.code, 1);
  EXPECT_EQ(failed.err, "tool: cannot open x.db\n");
}

}  // namespace
}  // namespace vicc_common::cli
