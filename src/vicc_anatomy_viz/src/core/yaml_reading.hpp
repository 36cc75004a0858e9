#pragma once
// Small helpers to read YAML configuration with messages that name the file, the line and
// the entry, so that a typo in a view definition is found at once.

#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

namespace vicc_anatomy_viz::yaml_reading {

/// Parses text; throws ConfigError "origin:line:column: message" on a syntax error.
YAML::Node parseText(const std::string& text, const std::string& origin);
std::string readFile(const std::string& path);  ///< ConfigError if unreadable

/// A reading position: the file, the entry path (e.g. "categories[2].props[0]") and the node.
class Cursor {
 public:
  Cursor(std::string origin, std::string path, YAML::Node node)
      : origin_(std::move(origin)), path_(std::move(path)), node_(std::move(node)) {}

  const YAML::Node& node() const { return node_; }
  const std::string& path() const { return path_; }
  /// "file:line: path" for messages.
  std::string where() const;
  [[noreturn]] void fail(const std::string& message) const;

  bool has(const std::string& key) const;
  Cursor child(const std::string& key) const;  ///< required key of a map
  Cursor optionalChild(const std::string& key) const;
  std::vector<Cursor> sequence(const std::string& key) const;          ///< required sequence
  std::vector<Cursor> optionalSequence(const std::string& key) const;  ///< empty if missing
  std::vector<Cursor> items() const;                                   ///< this node as a sequence
  /// A cursor on `node` below this one (e.g. a map entry), named path + suffix.
  Cursor sub(const std::string& path_suffix, const YAML::Node& node) const;

  std::string asString() const;
  double asDouble() const;
  int asInt() const;
  bool asBool() const;

  std::string string(const std::string& key) const;
  std::string string(const std::string& key, const std::string& fallback) const;
  double number(const std::string& key) const;
  double number(const std::string& key, double fallback) const;
  int integer(const std::string& key, int fallback) const;
  bool boolean(const std::string& key, bool fallback) const;
  std::vector<std::string> strings(const std::string& key) const;

  /// Fails when the map has keys outside `allowed` (catches misspelt options).
  void allowOnly(const std::vector<std::string>& allowed) const;

 private:
  std::string origin_;
  std::string path_;
  YAML::Node node_;
};

}  // namespace vicc_anatomy_viz::yaml_reading
