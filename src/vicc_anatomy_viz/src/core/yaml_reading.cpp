#include "yaml_reading.hpp"

#include <algorithm>
#include <cerrno>
#include <climits>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "vicc_anatomy_viz/errors.hpp"

namespace vicc_anatomy_viz::yaml_reading {

Cursor parseText(const std::string& text, const std::string& origin) {
  auto document = std::make_shared<const YamlDocument>(parseYamlDocument(text, origin));
  const YamlNode* root = document->nodes.empty() ? nullptr : &document->nodes.front();
  return Cursor(std::move(document), "", root);
}

std::string readFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ConfigError("cannot read configuration file '" + path + "'");
  std::ostringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

std::string Cursor::where() const {
  std::string out = document_->origin;
  if (node_ && node_->kind != YamlNode::Kind::kNull) out += ":" + std::to_string(node_->line + 1);
  if (!path_.empty()) out += ": " + path_;
  return out;
}

void Cursor::fail(const std::string& message) const { throw ConfigError(where() + ": " + message); }

const YamlNode* Cursor::find(const std::string& key) const {
  if (!isMap()) return nullptr;
  const auto& children = node_->children;
  for (std::size_t i = 0; i + 1 < children.size(); i += 2) {
    const YamlNode& candidate = document_->nodes[children[i]];
    if (candidate.kind == YamlNode::Kind::kScalar && candidate.scalar == key) {
      return &document_->nodes[children[i + 1]];
    }
  }
  return nullptr;
}

Cursor Cursor::at(std::string path, std::size_t index) const {
  return Cursor(document_, std::move(path), &document_->nodes[index]);
}

bool Cursor::has(const std::string& key) const {
  const YamlNode* value = find(key);
  return value && value->kind != YamlNode::Kind::kNull;
}

Cursor Cursor::child(const std::string& key) const {
  if (!isMap()) fail("expected a map with key '" + key + "'");
  const YamlNode* value = find(key);
  if (!value || value->kind == YamlNode::Kind::kNull) fail("missing '" + key + "'");
  return Cursor(document_, path_.empty() ? key : path_ + "." + key, value);
}

Cursor Cursor::optionalChild(const std::string& key) const {
  if (!has(key)) return Cursor(document_, path_ + "." + key, nullptr);
  return child(key);
}

std::vector<Cursor> Cursor::items() const {
  if (!node_ || node_->kind != YamlNode::Kind::kSequence) fail("expected a list");
  std::vector<Cursor> out;
  out.reserve(node_->children.size());
  for (std::size_t i = 0; i < node_->children.size(); ++i) {
    out.push_back(at(path_ + "[" + std::to_string(i) + "]", node_->children[i]));
  }
  return out;
}

std::vector<std::pair<std::string, Cursor>> Cursor::entries() const {
  if (!isMap()) fail("expected a map");
  std::vector<std::pair<std::string, Cursor>> out;
  const auto& children = node_->children;
  for (std::size_t i = 0; i + 1 < children.size(); i += 2) {
    const std::string& key = document_->nodes[children[i]].scalar;
    out.emplace_back(key, at(path_ + "." + key, children[i + 1]));
  }
  return out;
}

std::vector<Cursor> Cursor::sequence(const std::string& key) const { return child(key).items(); }

std::vector<Cursor> Cursor::optionalSequence(const std::string& key) const {
  if (!has(key)) return {};
  return sequence(key);
}

std::string Cursor::asString() const {
  if (!isScalar()) fail("expected a text value");
  return node_->scalar;
}

double Cursor::asDouble() const {
  const std::string text = asString();
  errno = 0;
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (text.empty() || errno != 0 || end != text.c_str() + text.size()) {
    fail("'" + text + "' is not a number");
  }
  return value;
}

int Cursor::asInt() const {
  const std::string text = asString();
  errno = 0;
  char* end = nullptr;
  const long value = std::strtol(text.c_str(), &end, 10);
  if (text.empty() || errno != 0 || end != text.c_str() + text.size() || value < INT_MIN ||
      value > INT_MAX) {
    fail("'" + text + "' is not an integer");
  }
  return static_cast<int>(value);
}

bool Cursor::asBool() const {
  const std::string text = asString();
  if (text == "true") return true;
  if (text == "false") return false;
  fail("'" + text + "' is not true or false");
}

std::string Cursor::string(const std::string& key) const { return child(key).asString(); }

std::string Cursor::string(const std::string& key, const std::string& fallback) const {
  return has(key) ? string(key) : fallback;
}

double Cursor::number(const std::string& key) const { return child(key).asDouble(); }

double Cursor::number(const std::string& key, double fallback) const {
  return has(key) ? number(key) : fallback;
}

int Cursor::integer(const std::string& key, int fallback) const {
  return has(key) ? child(key).asInt() : fallback;
}

bool Cursor::boolean(const std::string& key, bool fallback) const {
  return has(key) ? child(key).asBool() : fallback;
}

std::vector<std::string> Cursor::strings(const std::string& key) const {
  std::vector<std::string> out;
  for (const auto& item : sequence(key)) out.push_back(item.asString());
  return out;
}

void Cursor::allowOnly(const std::vector<std::string>& allowed) const {
  if (!isMap()) fail("expected a map");
  const auto& children = node_->children;
  for (std::size_t i = 0; i + 1 < children.size(); i += 2) {
    const std::string& key = document_->nodes[children[i]].scalar;
    if (std::find(allowed.begin(), allowed.end(), key) != allowed.end()) continue;
    std::string known;
    for (const auto& name : allowed) known += (known.empty() ? "" : ", ") + name;
    fail("unknown key '" + key + "' (known: " + known + ")");
  }
}

}  // namespace vicc_anatomy_viz::yaml_reading
