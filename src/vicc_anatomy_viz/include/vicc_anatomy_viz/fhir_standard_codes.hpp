#pragma once
// Standard codings (LOINC, SNOMED CT, ...) that the FHIR export sends beside our own codes,
// read from config/fhir/standard_codes.yaml. Every coding names the published source it was
// taken from; a coding without one is rejected when the file is loaded.

#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "vicc_anatomy_viz/encoding_model.hpp"

namespace vicc_anatomy_viz {

struct StandardCoding {
  nlohmann::json coding;  ///< a FHIR Coding: system, code, display
  std::string source;     ///< "name, version, file" of the publication it was taken from
};

class StandardCodes {
 public:
  /// Throws ConfigError naming file, line and entry on a malformed or unsourced coding.
  static StandardCodes fromYamlText(const std::string& yaml_text, const std::string& origin);
  static StandardCodes load(const std::string& path);

  /// The codings for our property code "<category>.<property>" or structure id, in file
  /// order; empty when no standard code is published for it.
  std::vector<nlohmann::json> standardCodings(const std::string& our_code) const;
  const std::vector<StandardCoding>& entries(const std::string& our_code) const;
  /// Our codes that have at least one standard coding.
  std::vector<std::string> ourCodes() const;
  /// Keys that are neither a property code of `model` nor one of its structures.
  std::vector<std::string> unknownCodes(const EncodingModel& model) const;

 private:
  std::map<std::string, std::vector<StandardCoding>> codes_;
};

/// <package>/config/fhir/standard_codes.yaml, beside the default encoding configuration.
std::string defaultStandardCodesPath();
/// The shipped mapping, loaded once (ConfigError if it is missing or malformed).
const StandardCodes& shippedStandardCodes();
/// shippedStandardCodes().standardCodings(our_code): what the FHIR export adds to a coding.
std::vector<nlohmann::json> standardCodings(const std::string& our_code);

}  // namespace vicc_anatomy_viz
