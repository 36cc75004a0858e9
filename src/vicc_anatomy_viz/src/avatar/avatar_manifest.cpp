#include "vicc_anatomy_viz/avatar/avatar_manifest.hpp"

#include <cmath>
#include <filesystem>

#include "../core/yaml_reading.hpp"
#include "vicc_anatomy_viz/errors.hpp"

namespace vicc_anatomy_viz::avatar {

namespace {

using yaml_reading::Cursor;

/// A finite number (NaN or infinity would silently become a broken mesh).
float number(const Cursor& cursor, const std::string& key, float fallback) {
  const double value = cursor.number(key, fallback);
  if (!std::isfinite(value)) cursor.child(key).fail(key + " must be a finite number");
  return static_cast<float>(value);
}

MeshSource readMeshSource(const Cursor& item, const std::filesystem::path& directory) {
  item.allowOnly({"file", "mesh", "up_axis", "forward_axis", "unit_in_metres", "translation"});
  MeshSource source;
  const std::filesystem::path file = item.string("file");
  source.path = (file.is_absolute() ? file : directory / file).lexically_normal().string();
  source.mesh_name = item.string("mesh", "");
  source.up_axis = item.string("up_axis", source.up_axis);
  source.forward_axis = item.string("forward_axis", source.forward_axis);
  source.unit_in_metres = number(item, "unit_in_metres", 1.0f);
  if (item.has("translation")) {
    const std::vector<Cursor> values = item.child("translation").items();
    if (values.size() != 3) item.child("translation").fail("translation needs three numbers");
    for (int k = 0; k < 3; ++k) {
      const double value = values[k].asDouble();
      if (!std::isfinite(value)) values[k].fail("translation must be finite numbers");
      source.translation[k] = static_cast<float>(value);
    }
  }
  return source;
}

/// The keys every generated part has, and those of its section shape.
const std::vector<std::string> kShapeKeys = {"bone",    "section", "from", "to",
                                             "azimuth", "profile", "tilt"};
const std::vector<std::string> kEllipseKeys = {"depth", "thickness", "width"};
const std::vector<std::string> kSectorKeys = {"span", "inner", "outer"};
const std::vector<std::string> kCavityKeys = {"inset", "half", "fissure"};

SectionShape readSection(const Cursor& item, std::vector<std::string>& allowed) {
  const std::string name = item.string("section", "ellipse");
  const auto allow = [&](const std::vector<std::string>& keys) {
    allowed.insert(allowed.end(), keys.begin(), keys.end());
  };
  if (name == "ellipse") {
    allow(kEllipseKeys);
    return SectionShape::kEllipse;
  }
  if (name == "sector") {
    allow(kSectorKeys);
    return SectionShape::kSector;
  }
  if (name == "cavity") {
    allow(kCavityKeys);
    return SectionShape::kCavity;
  }
  item.child("section").fail("section must be ellipse, sector or cavity, not '" + name + "'");
}

void readEllipse(const Cursor& item, GeneratedShape& shape) {
  shape.depth = number(item, "depth", shape.depth);
  shape.thickness = number(item, "thickness", shape.thickness);
  shape.width = number(item, "width", shape.width);
  if (!(shape.depth >= 0 && shape.depth < 1)) item.fail("depth must be in [0, 1)");
  if (!(shape.thickness > 0 && shape.thickness < 1)) item.fail("thickness must be in (0, 1)");
  if (!(shape.width > 0)) item.fail("width must be positive");
}

void readSector(const Cursor& item, GeneratedShape& shape) {
  shape.span = number(item, "span", shape.span);
  shape.inner = number(item, "inner", shape.inner);
  shape.outer = number(item, "outer", shape.outer);
  if (!(shape.span > 0 && shape.span < 360)) item.fail("span must be in (0, 360) degrees");
  if (!(shape.inner > 0 && shape.inner < shape.outer && shape.outer < 1))
    item.fail("sector needs 0 < inner < outer < 1");
}

void readCavity(const Cursor& item, GeneratedShape& shape) {
  shape.inset = number(item, "inset", shape.inset);
  shape.fissure = number(item, "fissure", shape.fissure);
  const std::string half = item.string("half", "none");
  const std::optional<Side> side = sideFromString(half);
  if (!side) item.child("half").fail("half must be left, right or none, not '" + half + "'");
  shape.half = *side;
  if (!(shape.inset >= 0)) item.fail("inset must be >= 0");
  if (!(shape.fissure >= 0)) item.fail("fissure must be >= 0");
}

/// `profile: e` (both ends) or `profile: [proximal, distal]`.
void readProfile(const Cursor& item, GeneratedShape& shape) {
  if (!item.has("profile")) return;
  const Cursor profile = item.child("profile");
  std::vector<float> exponents;
  if (profile.isSequence()) {
    for (const Cursor& value : profile.items())
      exponents.push_back(static_cast<float>(value.asDouble()));
  } else {
    exponents.push_back(static_cast<float>(profile.asDouble()));
  }
  if (exponents.size() == 1) exponents.push_back(exponents.front());
  if (exponents.size() != 2) profile.fail("profile is one exponent or [proximal, distal]");
  for (float exponent : exponents)
    if (!(exponent > 0 && exponent <= 2)) profile.fail("profile exponents must be in (0, 2]");
  shape.profile_proximal = exponents[0];
  shape.profile_distal = exponents[1];
}

GeneratedShape readShape(const Cursor& item) {
  std::vector<std::string> allowed = kShapeKeys;
  GeneratedShape shape;
  shape.section = readSection(item, allowed);
  item.allowOnly(allowed);
  shape.bone = item.string("bone");
  shape.from = number(item, "from", shape.from);
  shape.to = number(item, "to", shape.to);
  shape.azimuth = number(item, "azimuth", shape.azimuth);
  readProfile(item, shape);
  shape.tilt = number(item, "tilt", shape.tilt);
  if (!(std::fabs(shape.tilt) < 60)) item.fail("tilt must be within -60 and 60 degrees");
  if (!(shape.to > shape.from)) item.fail("'to' must be greater than 'from'");
  if (shape.section == SectionShape::kEllipse) readEllipse(item, shape);
  if (shape.section == SectionShape::kSector) readSector(item, shape);
  if (shape.section == SectionShape::kCavity) readCavity(item, shape);
  return shape;
}

/// One spindle (a mapping) or several parts of one structure (a sequence of mappings).
std::vector<GeneratedShape> readShapes(const Cursor& item) {
  if (item.isMap()) return {readShape(item)};
  std::vector<GeneratedShape> shapes;
  for (const Cursor& part : item.items()) shapes.push_back(readShape(part));
  if (shapes.empty()) item.fail("generated needs at least one part");
  return shapes;
}

ProxyPlacement readProxy(const Cursor& item) {
  item.allowOnly({"bone", "at", "azimuth", "elevation", "radius"});
  ProxyPlacement proxy;
  proxy.bone = item.string("bone");
  proxy.at = number(item, "at", proxy.at);
  proxy.azimuth = number(item, "azimuth", proxy.azimuth);
  proxy.elevation = number(item, "elevation", proxy.elevation);
  proxy.radius = number(item, "radius", proxy.radius);
  if (!(proxy.radius > 0)) item.fail("radius must be positive");
  return proxy;
}

StructureEntry readStructure(const Cursor& item, const AnatomyCatalog& catalog,
                             const std::filesystem::path& directory) {
  item.allowOnly({"id", "sides", "region", "system", "fma_id", "generated", "mesh", "proxy"});
  StructureEntry entry;
  entry.where = item.where();
  entry.id = item.string("id");
  const Structure* structure = catalog.structure(entry.id);
  if (!structure) item.fail("unknown structure '" + entry.id + "' (not in the anatomy catalogue)");
  for (const Cursor& side_item : item.child("sides").items()) {
    const std::optional<Side> side = sideFromString(side_item.asString());
    if (!side || !catalog.sideAllowed(*structure, *side)) {
      side_item.fail("bad side '" + side_item.asString() + "' for " + entry.id);
    }
    entry.sides.push_back(*side);
  }
  if (entry.sides.empty()) item.fail("sides is empty");
  entry.region = item.string("region");
  entry.system = item.string("system");
  entry.fma_id = structure->fma_id;
  const std::string manifest_fma = item.string("fma_id", "");
  if (!manifest_fma.empty() && manifest_fma != structure->fma_id) {
    item.fail("fma_id '" + manifest_fma + "' differs from the catalogue's '" + structure->fma_id +
              "' for " + entry.id);
  }
  if (item.has("generated") == item.has("mesh") && !item.has("proxy")) {
    item.fail(entry.id + " needs exactly one of 'generated' and 'mesh', or a proxy alone");
  }
  if (item.has("generated") && item.has("mesh"))
    item.fail(entry.id + " has both generated and mesh");
  if (item.has("generated")) entry.generated = readShapes(item.child("generated"));
  if (item.has("mesh")) entry.mesh = readMeshSource(item.child("mesh"), directory);
  if (item.has("proxy")) entry.proxy = readProxy(item.child("proxy"));
  return entry;
}

}  // namespace

AvatarManifest loadAvatarManifest(const std::string& path, const AnatomyCatalog& catalog) {
  const Cursor root = yaml_reading::parseText(yaml_reading::readFile(path), path);
  root.allowOnly({"skin", "skin_labelling", "structures"});
  const std::filesystem::path directory = std::filesystem::path(path).parent_path();
  AvatarManifest manifest;
  manifest.path = path;
  manifest.skin = readMeshSource(root.child("skin"), directory);
  manifest.skin_labelling = root.string("skin_labelling", manifest.skin_labelling);
  if (manifest.skin_labelling != "dermatomes") {
    root.child("skin_labelling").fail("skin_labelling must be 'dermatomes'");
  }
  for (const Cursor& item : root.sequence("structures")) {
    manifest.structures.push_back(readStructure(item, catalog, directory));
    const StructureEntry& added = manifest.structures.back();
    for (std::size_t i = 0; i + 1 < manifest.structures.size(); ++i) {
      if (manifest.structures[i].id == added.id)
        item.fail("structure '" + added.id + "' listed twice");
    }
  }
  return manifest;
}

}  // namespace vicc_anatomy_viz::avatar
