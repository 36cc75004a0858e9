#pragma once
// A small parameter table for the reader tests: values of every plain type, an enum stored as
// text, a nested section and validate().

#include <stdexcept>
#include <string>
#include <vector>

namespace vicc_common_test {

enum class Shape { kCircle, kSquare };

inline std::string toParameterText(const Shape& shape) {
  return shape == Shape::kCircle ? "circle" : "square";
}
inline void fromParameterText(const std::string& text, Shape& shape) {
  if (text == "circle") {
    shape = Shape::kCircle;
  } else if (text == "square") {
    shape = Shape::kSquare;
  } else {
    throw std::invalid_argument("unknown shape '" + text + "' (circle or square)");
  }
}

struct Inner {
  double gain = 0.5;
  std::vector<int> levels = {4, 2};
  void validate() const {
    if (!(gain > 0.0)) throw std::invalid_argument("gain must be > 0");
  }
};

struct Outer {
  int count = 3;
  bool enabled = false;
  std::string name = "default";
  std::vector<double> weights = {0.25};
  Shape shape = Shape::kCircle;
  Inner inner;
  void validate() const {
    if (count < 0) throw std::invalid_argument("count must be >= 0");
  }
};

template <typename Config, typename Visitor>
std::enable_if_t<std::is_same_v<std::remove_const_t<Config>, Inner>> visitParameters(
    Config& config, Visitor& visit) {
  visit("gain", config.gain);
  visit("levels", config.levels);
}

template <typename Config, typename Visitor>
std::enable_if_t<std::is_same_v<std::remove_const_t<Config>, Outer>> visitParameters(
    Config& config, Visitor& visit) {
  visit("count", config.count);
  visit("enabled", config.enabled);
  visit("name", config.name);
  visit("weights", config.weights);
  visit("shape", config.shape);
  visit.section("inner", config.inner);
}

}  // namespace vicc_common_test
