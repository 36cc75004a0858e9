#pragma once
// A parsed YAML document as a small read-only tree, built from libyaml's events.
// libyaml (the C reference parser) reads the configuration about ten times faster than
// yaml-cpp did, which is most of the start-up time of every vicc_patient call.
// Scalars keep their text: the readers convert and check types themselves.

#include <cstddef>
#include <string>
#include <vector>

namespace vicc_anatomy_viz::yaml_reading {

struct YamlNode {
  /// kNull: a plain, untagged ~, null, Null, NULL or empty scalar (as yaml-cpp and YAML 1.2).
  enum class Kind { kNull, kScalar, kSequence, kMap };
  Kind kind = Kind::kNull;
  int line = 0;        ///< 0-based line where the node starts
  std::string scalar;  ///< the text of a scalar (quotes and escapes resolved)
  /// Indices into YamlDocument::nodes: the items of a sequence, or key, value, key, value...
  /// of a map. An alias is the index of the anchored node.
  std::vector<std::size_t> children;
};

struct YamlDocument {
  std::string origin;           ///< the file name for messages
  std::vector<YamlNode> nodes;  ///< nodes[0] is the root; empty for an empty document
};

/// Parses the first document of `text`; throws ConfigError "origin:line:column: message"
/// on a syntax error or an alias to an undefined anchor.
YamlDocument parseYamlDocument(const std::string& text, const std::string& origin);

}  // namespace vicc_anatomy_viz::yaml_reading
