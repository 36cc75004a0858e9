#include "vicc_anatomy_viz/data_model.hpp"

#include <algorithm>
#include <cerrno>
#include <climits>
#include <cstdlib>
#include <set>
#include <sstream>

#include "vicc_anatomy_viz/errors.hpp"

namespace vicc_anatomy_viz {

std::string toString(DataType type) {
  switch (type) {
    case DataType::kNominal:
      return "nominal";
    case DataType::kOrdinal:
      return "ordinal";
    case DataType::kNumerical:
      return "numerical";
  }
  return "?";
}

DataType dataTypeFromString(const std::string& text) {
  if (text == "nominal") return DataType::kNominal;
  if (text == "ordinal") return DataType::kOrdinal;
  if (text == "numerical") return DataType::kNumerical;
  throw ConfigError("unknown data type '" + text + "' (expected nominal, ordinal or numerical)");
}

Value Value::number(int number) {
  Value value;
  value.is_number_ = true;
  value.number_ = number;
  return value;
}

Value Value::label(std::string label) {
  Value value;
  value.label_ = std::move(label);
  return value;
}

std::string Value::toString() const { return is_number_ ? std::to_string(number_) : label_; }

bool Value::operator==(const Value& other) const {
  if (is_number_ != other.is_number_) return false;
  return is_number_ ? number_ == other.number_ : label_ == other.label_;
}

bool Value::operator<(const Value& other) const {
  if (is_number_ != other.is_number_) return is_number_;
  return is_number_ ? number_ < other.number_ : label_ < other.label_;
}

bool Domain::contains(const Value& value) const { return indexOf(value) >= 0; }

std::vector<Value> Domain::values() const {
  std::vector<Value> out;
  if (type == DataType::kNumerical) {
    for (int v = min; v <= max; ++v) out.push_back(Value::number(v));
  } else {
    for (const auto& label : labels) out.push_back(Value::label(label));
  }
  return out;
}

std::size_t Domain::size() const {
  if (type == DataType::kNumerical) return max >= min ? static_cast<std::size_t>(max - min + 1) : 0;
  return labels.size();
}

int Domain::indexOf(const Value& value) const {
  if (type == DataType::kNumerical) {
    if (!value.isNumber() || value.asNumber() < min || value.asNumber() > max) return -1;
    return value.asNumber() - min;
  }
  if (value.isNumber()) return -1;
  const auto it = std::find(labels.begin(), labels.end(), value.asLabel());
  return it == labels.end() ? -1 : static_cast<int>(it - labels.begin());
}

std::string Domain::describe() const {
  if (type == DataType::kNumerical) return std::to_string(min) + ".." + std::to_string(max);
  std::ostringstream out;
  out << "{";
  for (std::size_t i = 0; i < labels.size(); ++i) out << (i ? ", " : "") << labels[i];
  out << "}";
  return out.str();
}

bool Domain::isBinary() const {
  return type == DataType::kNominal && labels.size() == 2 && labels[0] == "false" &&
         labels[1] == "true";
}

std::optional<Value> Domain::parse(const std::string& text) const {
  if (type == DataType::kNumerical) {
    if (text.empty()) return std::nullopt;
    errno = 0;
    char* end = nullptr;
    const long number = std::strtol(text.c_str(), &end, 10);
    if (errno != 0 || end != text.c_str() + text.size() || number < INT_MIN || number > INT_MAX) {
      return std::nullopt;
    }
    return Value::number(static_cast<int>(number));
  }
  return Value::label(text);
}

void Domain::validate(const std::string& where) const {
  if (type == DataType::kNumerical) {
    if (min > max) {
      throw ConfigError(where + ": numerical domain [" + std::to_string(min) + ", " +
                        std::to_string(max) + "] is empty");
    }
    if (static_cast<long>(max) - min > 1000) {
      throw ConfigError(where + ": numerical domain " + describe() +
                        " is too large for a discrete clinical scale (max 1001 values)");
    }
    return;
  }
  if (labels.empty()) throw ConfigError(where + ": " + toString(type) + " domain has no labels");
  std::set<std::string> seen;
  for (const auto& label : labels) {
    if (label.empty()) throw ConfigError(where + ": empty label in domain");
    if (!seen.insert(label).second) {
      throw ConfigError(where + ": label '" + label + "' appears twice in the domain");
    }
  }
}

bool Property::isNormal(const Value& value) const {
  return std::find(normal.begin(), normal.end(), value) != normal.end();
}

std::optional<Value> Property::defaultValue() const {
  if (normal.empty()) return std::nullopt;
  return normal.front();
}

const Property* Category::property(const std::string& prop_type) const {
  for (const auto& prop : props) {
    if (prop.prop_type == prop_type) return &prop;
  }
  return nullptr;
}

const Property* Category::propertyWithSource(const std::string& source_prop_type) const {
  for (const auto& prop : props) {
    if (prop.source && prop.source->prop_type == source_prop_type) return &prop;
  }
  return nullptr;
}

bool Category::refersTo(const std::string& structure_class) const {
  return std::find(spatial_refs.begin(), spatial_refs.end(), structure_class) != spatial_refs.end();
}

bool View::contains(const std::string& category) const { return !hueOf(category).empty(); }

std::string View::hueOf(const std::string& category) const {
  for (const auto& entry : categories) {
    if (entry.category == category) return entry.hue;
  }
  return "";
}

}  // namespace vicc_anatomy_viz
