#include "svg_css.hpp"

#include <algorithm>
#include <sstream>
#include <stdexcept>

namespace vicc_glyphs {
namespace io_detail {
namespace {

std::string trim(const std::string& text) {
  const auto begin = text.find_first_not_of(" \t\r\n");
  if (begin == std::string::npos) return {};
  return text.substr(begin, text.find_last_not_of(" \t\r\n") - begin + 1);
}

std::string withoutComments(const std::string& css) {
  std::string out;
  std::size_t at = 0;
  while (at < css.size()) {
    const auto open = css.find("/*", at);
    if (open == std::string::npos) {
      out += css.substr(at);
      break;
    }
    out += css.substr(at, open - at);
    const auto close = css.find("*/", open + 2);
    at = close == std::string::npos ? css.size() : close + 2;
  }
  return out;
}

bool isNameChar(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' || c == '*' ||
         static_cast<unsigned char>(c) >= 0x80;
}

std::vector<std::string> splitClasses(const char* attribute) {
  std::vector<std::string> classes;
  if (!attribute) return classes;
  std::istringstream words(attribute);
  for (std::string word; words >> word;) classes.push_back(word);
  return classes;
}

}  // namespace

std::vector<CssDeclaration> parseDeclarations(const std::string& text) {
  std::vector<CssDeclaration> declarations;
  std::size_t start = 0;
  while (start <= text.size()) {
    const auto end = std::min(text.find(';', start), text.size());
    const std::string declaration = text.substr(start, end - start);
    const auto colon = declaration.find(':');
    if (colon != std::string::npos) {
      std::string value = trim(declaration.substr(colon + 1));
      const auto important = value.find("!important");
      if (important != std::string::npos) value = trim(value.substr(0, important));
      declarations.push_back({trim(declaration.substr(0, colon)), value});
    } else if (!trim(declaration).empty()) {
      throw std::invalid_argument("style declaration without ':' '" + declaration + "'");
    }
    start = end + 1;
  }
  return declarations;
}

void StyleSheet::parse(const std::string& raw_css, const UnsupportedHandler& unsupported) {
  const std::string css = withoutComments(raw_css);
  std::size_t at = 0;
  while (true) {
    const auto open = css.find('{', at);
    if (open == std::string::npos) {
      if (!trim(css.substr(at)).empty()) throw std::invalid_argument("CSS rule without '{'");
      return;
    }
    const auto close = css.find('}', open);
    if (close == std::string::npos) throw std::invalid_argument("CSS rule without '}'");
    const std::string selectors = trim(css.substr(at, open - at));
    at = close + 1;
    if (!selectors.empty() && selectors[0] == '@') {
      unsupported("CSS at-rule '" + selectors.substr(0, 40) + "'");
      continue;
    }
    const auto declarations = parseDeclarations(css.substr(open + 1, close - open - 1));
    std::stringstream list(selectors);
    for (std::string text; std::getline(list, text, ',');) {
      text = trim(text);
      Selector selector;
      bool ok = !text.empty();
      std::size_t i = 0;
      while (ok && i < text.size()) {
        const char kind = (text[i] == '.' || text[i] == '#') ? text[i++] : 't';
        std::size_t j = i;
        while (j < text.size() && isNameChar(text[j])) ++j;
        const std::string name = text.substr(i, j - i);
        ok = !name.empty() && (kind != 't' || (i == 0 && selector.type.empty()));
        if (kind == '.') selector.classes.push_back(name), selector.specificity += 10;
        if (kind == '#') selector.id = name, selector.specificity += 100;
        if (kind == 't') selector.type = name, selector.specificity += name == "*" ? 0 : 1;
        i = j;
      }
      if (!ok) {
        unsupported("CSS selector '" + text.substr(0, 40) + "'");
        continue;
      }
      rules_.push_back({selector, declarations, rules_.size()});
    }
  }
}

std::vector<CssDeclaration> StyleSheet::matching(const tinyxml2::XMLElement& element) const {
  std::vector<const Rule*> matches;
  const std::vector<std::string> classes = splitClasses(element.Attribute("class"));
  const char* id = element.Attribute("id");
  for (const Rule& rule : rules_) {
    const Selector& s = rule.selector;
    if (!s.type.empty() && s.type != "*" && s.type != element.Name()) continue;
    if (!s.id.empty() && (!id || s.id != id)) continue;
    const bool all_classes = std::all_of(s.classes.begin(), s.classes.end(), [&](const auto& c) {
      return std::find(classes.begin(), classes.end(), c) != classes.end();
    });
    if (all_classes) matches.push_back(&rule);
  }
  std::stable_sort(matches.begin(), matches.end(), [](const Rule* a, const Rule* b) {
    return a->selector.specificity < b->selector.specificity;
  });
  std::vector<CssDeclaration> declarations;
  for (const Rule* rule : matches) {
    declarations.insert(declarations.end(), rule->declarations.begin(), rule->declarations.end());
  }
  return declarations;
}

}  // namespace io_detail
}  // namespace vicc_glyphs
