#include "vicc_anatomy_viz/fhir_standard_codes.hpp"

#include <cctype>
#include <filesystem>
#include <set>
#include <utility>

#include "fhir_codes.hpp"
#include "vicc_anatomy_viz/patient_status_service.hpp"
#include "yaml_reading.hpp"

namespace vicc_anatomy_viz {

using yaml_reading::Cursor;

namespace {

/// Text that FHIR accepts as a code: not empty, no whitespace at either end.
bool isFhirCode(const std::string& text) {
  return !text.empty() && !std::isspace(static_cast<unsigned char>(text.front())) &&
         !std::isspace(static_cast<unsigned char>(text.back()));
}

std::string readSource(const Cursor& source) {
  source.allowOnly({"name", "version", "file", "reference"});
  std::string described;
  for (const char* key : {"name", "version", "file"}) {
    const std::string value = source.string(key);
    if (value.empty()) source.fail(std::string("'") + key + "' is empty");
    described += (described.empty() ? "" : ", ") + value;
  }
  return described;
}

StandardCoding readCoding(const Cursor& entry) {
  entry.allowOnly({"system", "code", "display", "source"});
  const std::string system = entry.string("system");
  const std::string code = entry.string("code");
  const std::string display = entry.string("display");
  if (system.rfind("http://", 0) != 0 && system.rfind("https://", 0) != 0) {
    entry.fail("system must be an absolute http(s) URI");
  }
  if (!isFhirCode(code)) entry.fail("code is empty or has surrounding whitespace");
  if (display.empty()) entry.fail("display is empty");
  return {fhir_codes::coding(system, code, display), readSource(entry.child("source"))};
}

}  // namespace

StandardCodes StandardCodes::fromYamlText(const std::string& yaml_text, const std::string& origin) {
  const Cursor root = yaml_reading::parseText(yaml_text, origin);
  root.allowOnly({"codes"});
  const Cursor codes = root.child("codes");
  if (!codes.isMap()) codes.fail("expected a map from our codes to codings");
  StandardCodes out;
  for (const auto& [our_code, codings] : codes.entries()) {
    std::set<std::pair<std::string, std::string>> seen;
    for (const Cursor& entry : codings.items()) {
      StandardCoding coding = readCoding(entry);
      if (!seen.emplace(coding.coding["system"].get<std::string>(),
                        coding.coding["code"].get<std::string>())
               .second) {
        entry.fail("the same system and code are listed twice");
      }
      out.codes_[our_code].push_back(std::move(coding));
    }
  }
  return out;
}

StandardCodes StandardCodes::load(const std::string& path) {
  return fromYamlText(yaml_reading::readFile(path), path);
}

std::vector<nlohmann::json> StandardCodes::standardCodings(const std::string& our_code) const {
  std::vector<nlohmann::json> out;
  for (const auto& entry : entries(our_code)) out.push_back(entry.coding);
  return out;
}

const std::vector<StandardCoding>& StandardCodes::entries(const std::string& our_code) const {
  static const std::vector<StandardCoding> kNone;
  const auto found = codes_.find(our_code);
  return found == codes_.end() ? kNone : found->second;
}

std::vector<std::string> StandardCodes::ourCodes() const {
  std::vector<std::string> out;
  for (const auto& [our_code, codings] : codes_) {
    if (!codings.empty()) out.push_back(our_code);
  }
  return out;
}

std::vector<std::string> StandardCodes::unknownCodes(const EncodingModel& model) const {
  std::vector<std::string> out;
  for (const auto& [our_code, codings] : codes_) {
    if (!fhir_codes::propertyOfCode(model, our_code) && !model.anatomy().structure(our_code)) {
      out.push_back(our_code);
    }
  }
  return out;
}

std::string defaultStandardCodesPath() {
  namespace fs = std::filesystem;
  // config/encoding/<file> -> config/fhir/standard_codes.yaml
  const fs::path config_dir = fs::path(defaultEncodingConfigPath()).parent_path().parent_path();
  return (config_dir / "fhir" / "standard_codes.yaml").string();
}

const StandardCodes& shippedStandardCodes() {
  static const StandardCodes codes = StandardCodes::load(defaultStandardCodesPath());
  return codes;
}

std::vector<nlohmann::json> standardCodings(const std::string& our_code) {
  return shippedStandardCodes().standardCodings(our_code);
}

}  // namespace vicc_anatomy_viz
