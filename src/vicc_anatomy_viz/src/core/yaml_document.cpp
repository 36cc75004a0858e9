#include "yaml_document.hpp"

#include <yaml.h>

#include <map>
#include <new>
#include <string_view>

#include "vicc_anatomy_viz/errors.hpp"

namespace vicc_anatomy_viz::yaml_reading {

namespace {

/// Owns a libyaml parser reading `text` (which must outlive it).
class Parser {
 public:
  explicit Parser(const std::string& text) {
    if (!yaml_parser_initialize(&parser_)) throw std::bad_alloc();
    yaml_parser_set_input_string(&parser_, reinterpret_cast<const unsigned char*>(text.data()),
                                 text.size());
  }
  ~Parser() { yaml_parser_delete(&parser_); }
  Parser(const Parser&) = delete;
  Parser& operator=(const Parser&) = delete;

  yaml_parser_t* get() { return &parser_; }

 private:
  yaml_parser_t parser_;
};

/// Owns one event; libyaml zeroes it before filling it, so deleting it is always safe.
struct Event {
  Event() = default;
  ~Event() { yaml_event_delete(&event); }
  Event(const Event&) = delete;
  Event& operator=(const Event&) = delete;

  yaml_event_t event{};
};

std::string markText(const std::string& origin, const yaml_mark_t& mark) {
  return origin + ":" + std::to_string(mark.line + 1) + ":" + std::to_string(mark.column + 1);
}

ConfigError syntaxError(const std::string& origin, const yaml_parser_t& parser) {
  const std::string problem = parser.problem ? parser.problem : "malformed YAML";
  if (parser.error == YAML_READER_ERROR) {
    return ConfigError(origin + ": " + problem + " at byte " +
                       std::to_string(parser.problem_offset));
  }
  std::string message = markText(origin, parser.problem_mark) + ": " + problem;
  if (parser.context) {
    message += " (" + std::string(parser.context) + " started at line " +
               std::to_string(parser.context_mark.line + 1) + ")";
  }
  return ConfigError(message);
}

std::string_view scalarText(const yaml_event_t& event) {
  return {reinterpret_cast<const char*>(event.data.scalar.value), event.data.scalar.length};
}

/// yaml-cpp's rule (YAML 1.2 core schema): only an untagged plain scalar can be null.
bool isNullScalar(const yaml_event_t& event) {
  if (event.data.scalar.style != YAML_PLAIN_SCALAR_STYLE || event.data.scalar.tag) return false;
  const std::string_view text = scalarText(event);
  return text.empty() || text == "~" || text == "null" || text == "Null" || text == "NULL";
}

const char* anchorOf(const yaml_event_t& event) {
  switch (event.type) {
    case YAML_SCALAR_EVENT:
      return reinterpret_cast<const char*>(event.data.scalar.anchor);
    case YAML_SEQUENCE_START_EVENT:
      return reinterpret_cast<const char*>(event.data.sequence_start.anchor);
    case YAML_MAPPING_START_EVENT:
      return reinterpret_cast<const char*>(event.data.mapping_start.anchor);
    default:
      return nullptr;
  }
}

/// Appends nodes in document order and links each to the collection that is open.
class TreeBuilder {
 public:
  explicit TreeBuilder(YamlDocument& document) : document_(document) {}

  void scalar(const yaml_event_t& event) {
    YamlNode node;
    node.line = static_cast<int>(event.start_mark.line);
    if (!isNullScalar(event)) {
      node.kind = YamlNode::Kind::kScalar;
      node.scalar = std::string(scalarText(event));
    }
    add(std::move(node), event);
  }

  void open(YamlNode::Kind kind, const yaml_event_t& event) {
    YamlNode node;
    node.kind = kind;
    node.line = static_cast<int>(event.start_mark.line);
    open_.push_back(add(std::move(node), event));
  }

  void close() {
    if (!open_.empty()) open_.pop_back();
  }

  void alias(const yaml_event_t& event) {
    const std::string anchor = reinterpret_cast<const char*>(event.data.alias.anchor);
    const auto it = anchors_.find(anchor);
    if (it == anchors_.end()) {
      throw ConfigError(markText(document_.origin, event.start_mark) + ": alias '*" + anchor +
                        "' names no anchor defined before it");
    }
    attach(it->second);
  }

 private:
  std::size_t add(YamlNode node, const yaml_event_t& event) {
    const std::size_t index = document_.nodes.size();
    document_.nodes.push_back(std::move(node));
    if (const char* anchor = anchorOf(event)) anchors_[anchor] = index;
    attach(index);
    return index;
  }

  void attach(std::size_t index) {
    if (!open_.empty()) document_.nodes[open_.back()].children.push_back(index);
  }

  YamlDocument& document_;
  std::vector<std::size_t> open_;  ///< the collections being filled, innermost last
  std::map<std::string, std::size_t> anchors_;
};

}  // namespace

YamlDocument parseYamlDocument(const std::string& text, const std::string& origin) {
  YamlDocument document;
  document.origin = origin;
  Parser parser(text);
  TreeBuilder builder(document);
  for (;;) {
    Event next;
    if (!yaml_parser_parse(parser.get(), &next.event)) throw syntaxError(origin, *parser.get());
    const yaml_event_t& event = next.event;
    switch (event.type) {
      case YAML_SCALAR_EVENT:
        builder.scalar(event);
        break;
      case YAML_SEQUENCE_START_EVENT:
        builder.open(YamlNode::Kind::kSequence, event);
        break;
      case YAML_MAPPING_START_EVENT:
        builder.open(YamlNode::Kind::kMap, event);
        break;
      case YAML_SEQUENCE_END_EVENT:
      case YAML_MAPPING_END_EVENT:
        builder.close();
        break;
      case YAML_ALIAS_EVENT:
        builder.alias(event);
        break;
      case YAML_DOCUMENT_END_EVENT:  // like YAML::Load: the first document only
      case YAML_STREAM_END_EVENT:
        return document;
      default:
        break;
    }
  }
}

}  // namespace vicc_anatomy_viz::yaml_reading
