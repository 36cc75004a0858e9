#include "yaml_reading.hpp"

#include <algorithm>
#include <cerrno>
#include <climits>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "vicc_anatomy_viz/errors.hpp"

namespace vicc_anatomy_viz::yaml_reading {

YAML::Node parseText(const std::string& text, const std::string& origin) {
  try {
    return YAML::Load(text);
  } catch (const YAML::ParserException& e) {
    std::ostringstream out;
    out << origin << ":" << e.mark.line + 1 << ":" << e.mark.column + 1 << ": " << e.msg;
    throw ConfigError(out.str());
  }
}

std::string readFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ConfigError("cannot read configuration file '" + path + "'");
  std::ostringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

std::string Cursor::where() const {
  std::ostringstream out;
  out << origin_;
  if (node_.IsDefined() && !node_.IsNull() && node_.Mark().line >= 0) {
    out << ":" << node_.Mark().line + 1;
  }
  if (!path_.empty()) out << ": " << path_;
  return out.str();
}

void Cursor::fail(const std::string& message) const { throw ConfigError(where() + ": " + message); }

bool Cursor::has(const std::string& key) const {
  return node_.IsMap() && node_[key].IsDefined() && !node_[key].IsNull();
}

Cursor Cursor::child(const std::string& key) const {
  if (!node_.IsMap()) fail("expected a map with key '" + key + "'");
  if (!has(key)) fail("missing '" + key + "'");
  return Cursor(origin_, path_.empty() ? key : path_ + "." + key, node_[key]);
}

Cursor Cursor::optionalChild(const std::string& key) const {
  if (!has(key)) return Cursor(origin_, path_ + "." + key, YAML::Node());
  return child(key);
}

std::vector<Cursor> Cursor::items() const {
  if (!node_.IsSequence()) fail("expected a list");
  std::vector<Cursor> out;
  for (std::size_t i = 0; i < node_.size(); ++i) {
    out.emplace_back(origin_, path_ + "[" + std::to_string(i) + "]", node_[i]);
  }
  return out;
}

Cursor Cursor::sub(const std::string& path_suffix, const YAML::Node& node) const {
  return Cursor(origin_, path_ + path_suffix, node);
}

std::vector<Cursor> Cursor::sequence(const std::string& key) const { return child(key).items(); }

std::vector<Cursor> Cursor::optionalSequence(const std::string& key) const {
  if (!has(key)) return {};
  return sequence(key);
}

std::string Cursor::asString() const {
  if (!node_.IsScalar()) fail("expected a text value");
  return node_.Scalar();
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
  if (!node_.IsMap()) fail("expected a map");
  for (const auto& entry : node_) {
    const std::string key = entry.first.Scalar();
    if (std::find(allowed.begin(), allowed.end(), key) == allowed.end()) {
      std::ostringstream known;
      for (std::size_t i = 0; i < allowed.size(); ++i) known << (i ? ", " : "") << allowed[i];
      fail("unknown key '" + key + "' (known: " + known.str() + ")");
    }
  }
}

}  // namespace vicc_anatomy_viz::yaml_reading
