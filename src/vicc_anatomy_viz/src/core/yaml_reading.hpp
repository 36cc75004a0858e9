#pragma once
// Small helpers to read YAML configuration with messages that name the file, the line and
// the entry, so that a typo in a view definition is found at once.

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "yaml_document.hpp"

namespace vicc_anatomy_viz::yaml_reading {

class Cursor;

/// Parses text into a cursor on its root; throws ConfigError "origin:line:column: message"
/// on a syntax error.
Cursor parseText(const std::string& text, const std::string& origin);
std::string readFile(const std::string& path);  ///< ConfigError if unreadable

/// A reading position: the file, the entry path (e.g. "categories[2].props[0]") and the node
/// (none when a key is absent). Cursors share the parsed document and keep it alive.
class Cursor {
 public:
  Cursor(std::shared_ptr<const YamlDocument> document, std::string path, const YamlNode* node)
      : document_(std::move(document)), path_(std::move(path)), node_(node) {}

  const std::string& path() const { return path_; }
  bool isMap() const { return node_ && node_->kind == YamlNode::Kind::kMap; }
  bool isSequence() const { return node_ && node_->kind == YamlNode::Kind::kSequence; }
  /// "file:line: path" for messages.
  std::string where() const;
  [[noreturn]] void fail(const std::string& message) const;

  bool has(const std::string& key) const;
  Cursor child(const std::string& key) const;  ///< required key of a map
  Cursor optionalChild(const std::string& key) const;
  std::vector<Cursor> sequence(const std::string& key) const;          ///< required sequence
  std::vector<Cursor> optionalSequence(const std::string& key) const;  ///< empty if missing
  std::vector<Cursor> items() const;                                   ///< this node as a sequence
  /// The entries of this map in file order: key text and a cursor on the value (named
  /// path.key); fails if this is not a map.
  std::vector<std::pair<std::string, Cursor>> entries() const;

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
  bool isScalar() const { return node_ && node_->kind == YamlNode::Kind::kScalar; }
  /// The value of `key` in this map, or nullptr (the first one if a key repeats).
  const YamlNode* find(const std::string& key) const;
  Cursor at(std::string path, std::size_t index) const;

  std::shared_ptr<const YamlDocument> document_;
  std::string path_;
  const YamlNode* node_;
};

}  // namespace vicc_anatomy_viz::yaml_reading
