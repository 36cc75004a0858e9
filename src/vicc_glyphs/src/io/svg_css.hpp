#pragma once
// The CSS of <style> elements, as far as icons use it: rules with simple selectors (a type,
// `*`, `.class`, `#id`, or a compound of them such as `path.a`), comma-separated lists, and
// declarations. Combinators, attribute selectors, pseudo-classes and at-rules are not
// supported: they are reported instead of being guessed.

#include <tinyxml2.h>

#include <functional>
#include <string>
#include <vector>

namespace vicc_glyphs {
namespace io_detail {

struct CssDeclaration {
  std::string name;
  std::string value;
};

/// Called for each unsupported construct; it throws (strict) or records a warning (lenient).
using UnsupportedHandler = std::function<void(const std::string& feature)>;

class StyleSheet {
 public:
  /// Adds the rules of one <style> element's text.
  void parse(const std::string& css, const UnsupportedHandler& unsupported);
  /// Declarations of the rules matching `element`, in cascade order: lower specificity first,
  /// equal specificity in source order (later ones win when applied in sequence).
  std::vector<CssDeclaration> matching(const tinyxml2::XMLElement& element) const;
  bool empty() const { return rules_.empty(); }

 private:
  struct Selector {
    std::string type;  ///< empty or "*": any element
    std::string id;
    std::vector<std::string> classes;
    int specificity = 0;
  };
  struct Rule {
    Selector selector;
    std::vector<CssDeclaration> declarations;
    std::size_t order = 0;
  };

  std::vector<Rule> rules_;
};

/// Splits "a: b; c: d" into declarations (a trailing "!important" is dropped). Throws
/// std::invalid_argument for a declaration without ':'.
std::vector<CssDeclaration> parseDeclarations(const std::string& text);

}  // namespace io_detail
}  // namespace vicc_glyphs
