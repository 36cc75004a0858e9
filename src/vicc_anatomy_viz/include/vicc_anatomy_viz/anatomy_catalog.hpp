#pragma once
// The concrete anatomical structures findings refer to: dermatomes C2-S5, named muscles with
// FMA ids, reflex tendons, urethra and anal sphincter, each bilateral (left/right) or midline.

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace vicc_anatomy_viz {

enum class Side { kLeft, kRight, kNone };

std::string toString(Side side);
/// "left", "right", "none" (also "" for none); nullopt otherwise.
std::optional<Side> sideFromString(const std::string& text);
Side contralateral(Side side);

enum class Laterality { kBilateral, kMidline };

struct StructureClass {
  std::string id;  ///< e.g. dermatome
  std::string label;
  Laterality laterality = Laterality::kBilateral;
  bool proxy = false;  ///< too small to colour directly: the avatar draws a proxy
  bool requires_fma_id = false;
};

struct Structure {
  std::string id;  ///< e.g. dermatome_L5
  std::string class_id;
  std::string name;    ///< e.g. "Dermatome L5"
  std::string fma_id;  ///< e.g. "FMA:22533"; "" if not catalogued
};

class AnatomyCatalog {
 public:
  /// Parses the YAML catalogue; throws ConfigError naming the entry on any problem.
  static AnatomyCatalog fromYamlText(const std::string& yaml_text, const std::string& origin);
  static AnatomyCatalog load(const std::string& path);

  const Structure* structure(const std::string& id) const;
  const StructureClass* structureClass(const std::string& id) const;
  const StructureClass& classOf(const Structure& structure) const;
  const std::vector<Structure>& structures() const { return structures_; }
  const std::vector<StructureClass>& classes() const { return classes_; }
  /// Catalogue position of a structure (for a stable display order); -1 if unknown.
  int order(const std::string& id) const;
  /// Looks a structure up by its FMA id (e.g. from a FHIR bodySite coding).
  const Structure* structureByFmaId(const std::string& fma_id) const;

  /// Whether `side` is allowed for the structure ("none" for midline, left/right otherwise).
  bool sideAllowed(const Structure& structure, Side side) const;
  /// "Dermatome L5 (left)", "Urethra".
  std::string displayName(const Structure& structure, Side side) const;

 private:
  void add(const StructureClass& structure_class);
  void add(const Structure& structure);

  std::vector<StructureClass> classes_;
  std::vector<Structure> structures_;
  std::map<std::string, std::size_t> class_index_;
  std::map<std::string, std::size_t> structure_index_;
  std::map<std::string, std::size_t> fma_index_;
};

}  // namespace vicc_anatomy_viz
