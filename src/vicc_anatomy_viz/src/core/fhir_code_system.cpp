// Our three FHIR R4 CodeSystems, generated from the loaded configuration so that they always
// list exactly the codes the export can send.
#include "vicc_anatomy_viz/fhir_code_system.hpp"

#include <map>
#include <set>
#include <string>
#include <vector>

#include "vicc_anatomy_viz/errors.hpp"
#include "vicc_anatomy_viz/fhir_bundle.hpp"

namespace vicc_anatomy_viz {

using nlohmann::json;

namespace {

/// Concepts in order; a code given twice is a configuration error, since FHIR requires
/// codes to be unique within a code system.
class ConceptList {
 public:
  explicit ConceptList(std::string system) : system_(std::move(system)) {}

  void add(const std::string& code, const std::string& display, const std::string& definition,
           json properties = json()) {
    if (!codes_.insert(code).second) {
      throw ConfigError("code '" + code + "' would be defined twice in " + system_);
    }
    json concept_json = {{"code", code}, {"display", display}};
    if (!definition.empty()) concept_json["definition"] = definition;
    if (!properties.empty()) concept_json["property"] = std::move(properties);
    concepts_.push_back(std::move(concept_json));
  }
  const json& concepts() const { return concepts_; }

 private:
  std::string system_;
  std::set<std::string> codes_;
  json concepts_ = json::array();
};

struct CodeSystemHeader {
  const char* url;
  const char* name;
  const char* title;
  const char* description;
};

json codeSystem(const CodeSystemHeader& header, const ConceptList& concepts,
                const json& property_definitions = json()) {
  const std::string url = header.url;
  json resource = {{"resourceType", "CodeSystem"},
                   {"id", url.substr(url.rfind('/') + 1)},
                   {"url", url},
                   {"name", header.name},
                   {"title", header.title},
                   {"status", "active"},
                   {"experimental", false},
                   {"description", header.description},
                   {"caseSensitive", true},
                   {"content", "complete"},
                   {"count", concepts.concepts().size()}};
  if (!property_definitions.empty()) resource["property"] = property_definitions;
  // FHIR JSON never has empty arrays: a code system without concepts omits the element.
  if (!concepts.concepts().empty()) resource["concept"] = concepts.concepts();
  return resource;
}

std::string describeDomain(const Domain& domain) {
  const std::string type = domain.isBinary() ? "binary" : toString(domain.type);
  return type + " " + domain.describe();
}

std::string describeProperty(const Property& prop) {
  std::string normal;
  for (const Value& value : prop.normal) normal += (normal.empty() ? "" : ", ") + value.toString();
  return describeDomain(prop.domain) + (normal.empty() ? "" : "; normal: " + normal);
}

json propertyCodeSystem(const EncodingConfig& config) {
  ConceptList concepts(fhir::kCodeSystem);
  concepts.add(fhir::kExaminationCode, "Neurological examination",
               "One examination: groups its findings (hasMember) and states whether any was "
               "abnormal; a structure without a finding is normal unless the examination "
               "carries the partial modifier extension.");
  for (const Category& category : config.categories) {
    for (const Property& prop : category.props) {
      const std::string code = category.id + "." + prop.prop_type;
      concepts.add(code, category.label + " " + prop.label, describeProperty(prop));
      if (prop.source) {
        concepts.add(
            category.id + "." + prop.source->prop_type, category.label + " " + prop.source->label,
            describeDomain(prop.source->domain) + ", as recorded; " + code + " is derived from it");
      }
    }
  }
  return codeSystem({fhir::kCodeSystem, "ViccNeurologicalStatus", "VICC neurological status",
                     "The properties of a neurological status finding, coded "
                     "<category>.<property> as in the VICC encoding configuration."},
                    concepts);
}

/// Labels of nominal and ordinal domains (binary ones travel as valueBoolean), each with the
/// property codes that use it.
json valueCodeSystem(const EncodingConfig& config) {
  std::vector<std::string> labels;
  std::map<std::string, std::string> used_by;
  auto collect = [&](const std::string& code, const Domain& domain) {
    if (domain.type == DataType::kNumerical || domain.isBinary()) return;
    for (const std::string& label : domain.labels) {
      std::string& users = used_by[label];
      if (users.empty()) labels.push_back(label);
      users += (users.empty() ? "" : ", ") + code;
    }
  };
  for (const Category& category : config.categories) {
    for (const Property& prop : category.props) {
      collect(category.id + "." + prop.prop_type, prop.domain);
      if (prop.source) collect(category.id + "." + prop.source->prop_type, prop.source->domain);
    }
  }
  ConceptList concepts(fhir::kValueSystem);
  concepts.add(fhir::kNoAbnormalFindings, "No abnormal findings",
               "Value of an examination: examined, every structure normal");
  concepts.add(fhir::kAbnormalFindings, "Abnormal findings",
               "Value of an examination: its members record the abnormal findings");
  for (const std::string& label : labels) concepts.add(label, label, "Value of " + used_by[label]);
  return codeSystem(
      {fhir::kValueSystem, "ViccNeurologicalStatusValues", "VICC neurological status values",
       "The values of the nominal and ordinal neurological status properties."},
      concepts);
}

json anatomyCodeSystem(const AnatomyCatalog& anatomy) {
  ConceptList concepts(fhir::kAnatomySystem);
  for (const Structure& structure : anatomy.structures()) {
    json properties =
        json::array({{{"code", "structure_class"}, {"valueCode", structure.class_id}}});
    if (!structure.fma_id.empty()) {
      properties.push_back({{"code", "fma_id"}, {"valueString", structure.fma_id}});
    }
    concepts.add(structure.id, structure.name,
                 "Structure class: " + anatomy.classOf(structure).label, std::move(properties));
  }
  const json property_definitions = json::array(
      {{{"code", "structure_class"},
        {"description", "The structure class of the anatomy catalogue (e.g. dermatome)"},
        {"type", "code"}},
       {{"code", "fma_id"},
        {"description", "Foundational Model of Anatomy id, where catalogued"},
        {"type", "string"}}});
  return codeSystem({fhir::kAnatomySystem, "ViccAnatomy", "VICC anatomical structures",
                     "The anatomical structures findings refer to (VICC anatomy catalogue)."},
                    concepts, property_definitions);
}

}  // namespace

json codeSystemResources(const EncodingModel& model) {
  json entries = json::array();
  for (json resource : {propertyCodeSystem(model.config()), valueCodeSystem(model.config()),
                        anatomyCodeSystem(model.anatomy())}) {
    entries.push_back({{"fullUrl", resource["url"]}, {"resource", std::move(resource)}});
  }
  return {{"resourceType", "Bundle"}, {"type", "collection"}, {"entry", entries}};
}

}  // namespace vicc_anatomy_viz
