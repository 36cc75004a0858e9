#include "vicc_anatomy_viz/anatomy_catalog.hpp"

#include "vicc_anatomy_viz/errors.hpp"
#include "yaml_reading.hpp"

namespace vicc_anatomy_viz {

using yaml_reading::Cursor;

std::string toString(Side side) {
  switch (side) {
    case Side::kLeft:
      return "left";
    case Side::kRight:
      return "right";
    case Side::kNone:
      return "none";
  }
  return "none";
}

std::optional<Side> sideFromString(const std::string& text) {
  if (text == "left") return Side::kLeft;
  if (text == "right") return Side::kRight;
  if (text == "none" || text.empty()) return Side::kNone;
  return std::nullopt;
}

Side contralateral(Side side) {
  if (side == Side::kLeft) return Side::kRight;
  if (side == Side::kRight) return Side::kLeft;
  return Side::kNone;
}

AnatomyCatalog AnatomyCatalog::fromYamlText(const std::string& yaml_text,
                                            const std::string& origin) {
  const Cursor root = yaml_reading::parseText(yaml_text, origin);
  AnatomyCatalog catalog;
  for (const auto& item : root.sequence("structure_classes")) {
    item.allowOnly({"id", "label", "laterality", "proxy", "requires_fma_id"});
    StructureClass structure_class;
    structure_class.id = item.string("id");
    structure_class.label = item.string("label", structure_class.id);
    const std::string laterality = item.string("laterality");
    if (laterality == "bilateral") {
      structure_class.laterality = Laterality::kBilateral;
    } else if (laterality == "midline") {
      structure_class.laterality = Laterality::kMidline;
    } else {
      item.fail("laterality must be bilateral or midline, not '" + laterality + "'");
    }
    structure_class.proxy = item.boolean("proxy", false);
    structure_class.requires_fma_id = item.boolean("requires_fma_id", false);
    if (catalog.structureClass(structure_class.id)) {
      item.fail("structure class '" + structure_class.id + "' is defined twice");
    }
    catalog.add(structure_class);
  }
  for (const auto& item : root.sequence("structures")) {
    item.allowOnly({"id", "class", "name", "fma_id"});
    Structure structure;
    structure.id = item.string("id");
    structure.class_id = item.string("class");
    structure.name = item.string("name");
    structure.fma_id = item.string("fma_id", "");
    const StructureClass* structure_class = catalog.structureClass(structure.class_id);
    if (!structure_class) {
      item.fail("structure '" + structure.id + "' has unknown class '" + structure.class_id + "'");
    }
    if (structure_class->requires_fma_id && structure.fma_id.empty()) {
      item.fail("structure '" + structure.id + "' (" + structure.class_id + ") needs an fma_id");
    }
    if (!structure.fma_id.empty() && structure.fma_id.rfind("FMA:", 0) != 0) {
      item.fail("fma_id '" + structure.fma_id + "' must look like FMA:<number>");
    }
    if (catalog.structure(structure.id)) {
      item.fail("structure '" + structure.id + "' is defined twice");
    }
    if (!structure.fma_id.empty() && catalog.structureByFmaId(structure.fma_id)) {
      item.fail("fma_id " + structure.fma_id + " is used by two structures");
    }
    catalog.add(structure);
  }
  return catalog;
}

AnatomyCatalog AnatomyCatalog::load(const std::string& path) {
  return fromYamlText(yaml_reading::readFile(path), path);
}

void AnatomyCatalog::add(const StructureClass& structure_class) {
  class_index_[structure_class.id] = classes_.size();
  classes_.push_back(structure_class);
}

void AnatomyCatalog::add(const Structure& structure) {
  structure_index_[structure.id] = structures_.size();
  if (!structure.fma_id.empty()) fma_index_[structure.fma_id] = structures_.size();
  structures_.push_back(structure);
}

const Structure* AnatomyCatalog::structure(const std::string& id) const {
  const auto it = structure_index_.find(id);
  return it == structure_index_.end() ? nullptr : &structures_[it->second];
}

const StructureClass* AnatomyCatalog::structureClass(const std::string& id) const {
  const auto it = class_index_.find(id);
  return it == class_index_.end() ? nullptr : &classes_[it->second];
}

const StructureClass& AnatomyCatalog::classOf(const Structure& structure) const {
  return classes_.at(class_index_.at(structure.class_id));
}

int AnatomyCatalog::order(const std::string& id) const {
  const auto it = structure_index_.find(id);
  return it == structure_index_.end() ? -1 : static_cast<int>(it->second);
}

const Structure* AnatomyCatalog::structureByFmaId(const std::string& fma_id) const {
  const auto it = fma_index_.find(fma_id);
  return it == fma_index_.end() ? nullptr : &structures_[it->second];
}

bool AnatomyCatalog::sideAllowed(const Structure& structure, Side side) const {
  const bool midline = classOf(structure).laterality == Laterality::kMidline;
  return midline ? side == Side::kNone : side != Side::kNone;
}

std::string AnatomyCatalog::displayName(const Structure& structure, Side side) const {
  if (side == Side::kNone) return structure.name;
  return structure.name + " (" + toString(side) + ")";
}

}  // namespace vicc_anatomy_viz
