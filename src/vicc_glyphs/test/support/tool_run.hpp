#pragma once
// Runs the built vicc_glyph binary (VICC_GLYPH_BINARY) like a user: exit code and both
// output streams, captured through files in a per-test temporary directory.

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace vicc_glyphs::test {

struct ToolRun {
  int exit_code = -1;
  std::string out;
  std::string err;
};

inline std::string readText(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

/// A fresh directory under the system temp dir, named after the test and the process.
inline std::filesystem::path freshTestDirectory(const std::string& prefix,
                                                const std::string& test) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / (prefix + std::to_string(::getpid()) + "_" + test);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

inline ToolRun runTool(const std::string& arguments, const std::filesystem::path& dir) {
  const std::filesystem::path out = dir / "stdout.txt", err = dir / "stderr.txt";
  const std::string command =
      std::string(VICC_GLYPH_BINARY) + " " + arguments + " >" + out.string() + " 2>" + err.string();
  const int status = std::system(command.c_str());
  ToolRun result;
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  result.out = readText(out);
  result.err = readText(err);
  return result;
}

}  // namespace vicc_glyphs::test
