#pragma once
// The medical data model of thesis 4.3.2.1: Property = (propType, dataType, domain),
// Category = (spatialRef, props), View = the categories relevant to a usage context.

#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace vicc_anatomy_viz {

enum class DataType { kNominal, kOrdinal, kNumerical };

std::string toString(DataType type);
/// Throws ConfigError for anything but nominal/ordinal/numerical.
DataType dataTypeFromString(const std::string& text);

/// One recorded value: an integer for numerical properties, a label for nominal and ordinal
/// ones (binary properties are nominal with the labels "false" and "true").
class Value {
 public:
  Value() = default;
  static Value number(int number);
  static Value label(std::string label);

  bool isNumber() const { return is_number_; }
  int asNumber() const { return number_; }
  const std::string& asLabel() const { return label_; }
  std::string toString() const;

  bool operator==(const Value& other) const;
  bool operator!=(const Value& other) const { return !(*this == other); }
  bool operator<(const Value& other) const;

 private:
  bool is_number_ = false;
  int number_ = 0;
  std::string label_;
};

/// The set of values a property can take.
struct Domain {
  DataType type = DataType::kNumerical;
  int min = 0;  ///< numerical: inclusive bounds
  int max = 0;
  std::vector<std::string> labels;  ///< nominal/ordinal: the labels, ordinal in increasing order

  bool contains(const Value& value) const;
  /// All values in order (numerical ascending, labels as listed).
  std::vector<Value> values() const;
  std::size_t size() const;
  /// Position of `value` in values(); -1 if not contained.
  int indexOf(const Value& value) const;
  /// "0..10" or "{constant, stress}".
  std::string describe() const;
  /// Nominal with exactly the labels false/true: exchanged as booleans.
  bool isBinary() const;
  /// Parses text ("8", "stress", "true") into a value of this domain's type; nullopt if the
  /// text cannot be a value of the type (range is checked by contains()).
  std::optional<Value> parse(const std::string& text) const;
  /// Throws ConfigError naming `where` when the domain itself is malformed.
  void validate(const std::string& where) const;
};

/// The raw value a physician records and the property value derived from it, e.g. the MRC
/// muscle strength 0..5 from which the paresis intensity mild/moderate/severe follows.
struct SourceProperty {
  std::string prop_type;
  std::string label;
  Domain domain;
  std::map<std::string, Value> derive;  ///< source value (as text) -> property value
};

struct Property {
  std::string prop_type;
  std::string label;
  Domain domain;
  std::vector<Value> normal;    ///< normal values, not displayed (DG5)
  std::string visual_variable;  ///< M^t: the visual variable encoding this property type
  int levels = 0;               ///< requested number of levels (0: as many as distinguishable)
  std::vector<int> thresholds;  ///< numerical level boundaries (level k+2 starts at thresholds[k])
  std::optional<SourceProperty> source;

  bool isNormal(const Value& value) const;
  /// The normal value used when a finding omits this property (the first normal value).
  std::optional<Value> defaultValue() const;
};

struct Category {
  std::string id;
  std::string label;
  std::vector<std::string> spatial_refs;  ///< structure classes, e.g. {dermatome}
  std::vector<Property> props;
  bool compare_contralateral = false;  ///< show normal values when the other side differs

  const Property* property(const std::string& prop_type) const;
  /// The property recorded through `prop_type` as its raw source (e.g. muscle_strength).
  const Property* propertyWithSource(const std::string& source_prop_type) const;
  bool refersTo(const std::string& structure_class) const;
};

/// A usage-dependent view with its category mapping M^c (category -> hue name).
struct View {
  struct Entry {
    std::string category;
    std::string hue;
  };
  std::string id;
  std::string label;
  std::vector<Entry> categories;

  bool contains(const std::string& category) const;
  /// Hue name of the category in this view; "" when not part of it.
  std::string hueOf(const std::string& category) const;
};

}  // namespace vicc_anatomy_viz
