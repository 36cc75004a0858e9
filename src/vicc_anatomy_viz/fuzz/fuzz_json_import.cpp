// Fuzz target 1: our JSON exchange format.
#include <string>
#include <vector>

#include "fuzz_targets.hpp"
#include "vicc_anatomy_viz/errors.hpp"
#include "vicc_anatomy_viz/record_json.hpp"

namespace vicc_anatomy_viz::fuzz {

namespace {

using nlohmann::json;

/// The finding objects of an accepted document, in the order the importer reads them.
std::vector<const json*> findingObjects(const json& document) {
  std::vector<const json*> out;
  const auto add_examination = [&out](const json& examination) {
    for (const json& finding : examination.at("findings")) out.push_back(&finding);
  };
  if (document.at("format") == kExaminationFormat) {
    add_examination(document);
  } else {
    for (const json& patient : document.at("patients")) {
      for (const json& examination : patient.at("examinations")) add_examination(examination);
    }
  }
  return out;
}

/// Whether `value` is what the document wrote: the same integer (not one wrapped into range),
/// label or boolean.
bool sameValue(const Value& value, const json& written) {
  if (value.isNumber()) {
    return written.is_number_integer() && written.dump() == std::to_string(value.asNumber());
  }
  if (written.is_boolean()) return value.asLabel() == (written.get<bool>() ? "true" : "false");
  return written.is_string() && written.get<std::string>() == value.asLabel();
}

void checkImportedAsWritten(const json& document, const std::vector<Examination>& examinations) {
  const std::vector<const json*> written = findingObjects(document);
  std::size_t next = 0;
  for (const Examination& examination : examinations) {
    for (const Finding& finding : examination.findings) {
      if (next >= written.size()) throw FuzzInvariantError("more findings than written");
      const json& object = *written[next++];
      if (object.at("category") != finding.category ||
          object.at("structure") != finding.structure) {
        throw FuzzInvariantError("finding names differ from the document");
      }
      const json& values = object.at("values");
      if (values.size() != finding.values.size()) throw FuzzInvariantError("value count differs");
      for (const auto& [prop_type, value] : finding.values) {
        if (!sameValue(value, values.at(prop_type))) {
          throw FuzzInvariantError("value of '" + prop_type + "' differs from the document");
        }
      }
    }
  }
  if (next != written.size()) throw FuzzInvariantError("fewer findings than written");
}

}  // namespace

int fuzzJsonImport(const std::uint8_t* data, std::size_t size) {
  try {
    const json document =
        parseJsonText(std::string(reinterpret_cast<const char*>(data), size), "fuzz");
    checkImportedAsWritten(document, examinationsFromJson(document, "fuzz"));
  } catch (const ExchangeError&) {
  } catch (const ValidationError&) {
  }
  return 0;
}

}  // namespace vicc_anatomy_viz::fuzz
