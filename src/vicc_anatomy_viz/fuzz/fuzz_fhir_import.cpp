// Fuzz target 2: FHIR R4 Bundle import, strict and skipping unknown codes.
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "fuzz_targets.hpp"
#include "vicc_anatomy_viz/errors.hpp"
#include "vicc_anatomy_viz/fhir_bundle.hpp"
#include "vicc_anatomy_viz/record_json.hpp"

namespace vicc_anatomy_viz::fuzz {

namespace {

using nlohmann::json;

std::optional<FhirImport> importBundle(const json& bundle, bool skip_unknown) {
  FhirImportOptions options;
  options.skip_unknown = skip_unknown;
  try {
    return examinationsFromFhirBundle(bundle, fuzzModel(), options);
  } catch (const ExchangeError&) {
  } catch (const ValidationError&) {
  }
  return std::nullopt;
}

bool sameExaminations(const std::vector<Examination>& a, const std::vector<Examination>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (a[i].patient_id != b[i].patient_id || takenAtOf(a[i]) != takenAtOf(b[i]) ||
        a[i].findings != b[i].findings) {
      return false;
    }
  }
  return true;
}

/// Every number written as an Observation value (valueInteger, valueQuantity.value).
std::set<double> writtenNumbers(const json& bundle) {
  std::set<double> numbers;
  const json entries = bundle.value("entry", json::array());
  if (!entries.is_array()) return numbers;
  for (const json& entry : entries) {
    if (!entry.is_object() || !entry.contains("resource") || !entry["resource"].is_object())
      continue;
    const json& resource = entry["resource"];
    if (resource.contains("valueInteger") && resource["valueInteger"].is_number()) {
      numbers.insert(resource["valueInteger"].get<double>());
    }
    const json quantity = resource.value("valueQuantity", json());
    if (quantity.is_object() && quantity.contains("value") && quantity["value"].is_number()) {
      numbers.insert(quantity["value"].get<double>());
    }
  }
  return numbers;
}

/// An imported number must be one the bundle wrote, not one wrapped into range.
void checkNumbersAsWritten(const json& bundle, const std::vector<Examination>& examinations) {
  const std::set<double> written = writtenNumbers(bundle);
  for (const Examination& examination : examinations) {
    for (const Finding& finding : examination.findings) {
      for (const auto& [prop_type, value] : finding.values) {
        if (value.isNumber() && !written.count(static_cast<double>(value.asNumber()))) {
          throw FuzzInvariantError("value of '" + prop_type + "' is not one the bundle wrote");
        }
      }
    }
  }
}

}  // namespace

int fuzzFhirImport(const std::uint8_t* data, std::size_t size) {
  json bundle;
  try {
    bundle = parseJsonText(std::string(reinterpret_cast<const char*>(data), size), "fuzz");
  } catch (const ExchangeError&) {
    return 0;
  }
  const std::optional<FhirImport> strict = importBundle(bundle, false);
  const std::optional<FhirImport> lenient = importBundle(bundle, true);
  if (strict) {
    // Nothing unknown was found, so skipping unknown codes must change nothing.
    if (!lenient || !sameExaminations(strict->examinations, lenient->examinations)) {
      throw FuzzInvariantError("strict and lenient imports of an accepted bundle differ");
    }
  }
  if (lenient) checkNumbersAsWritten(bundle, lenient->examinations);
  return 0;
}

}  // namespace vicc_anatomy_viz::fuzz
