// Our CodeSystem resources, generated from the encoding model: the urls the export uses, every
// code the export can send, the value codes and the anatomy structure codes.
#include <gtest/gtest.h>

#include <set>
#include <string>
#include <vector>

#include "../core/test_support.hpp"
#include "vicc_anatomy_viz/fhir_bundle.hpp"
#include "vicc_anatomy_viz/fhir_code_system.hpp"

namespace vicc_anatomy_viz {
namespace {

using nlohmann::json;
using test::shippedModel;

const json& shippedCodeSystems() {
  static const json bundle = codeSystemResources(shippedModel());
  return bundle;
}

const json& codeSystemWithUrl(const json& bundle, const std::string& url) {
  for (const auto& entry : bundle["entry"]) {
    if (entry["resource"]["url"] == url) return entry["resource"];
  }
  throw std::runtime_error("no CodeSystem " + url);
}

std::vector<std::string> codesOf(const json& code_system) {
  std::vector<std::string> codes;
  for (const auto& concept_json : code_system.value("concept", json::array())) {
    codes.push_back(concept_json["code"]);
  }
  return codes;
}

const json& conceptWithCode(const json& code_system, const std::string& code) {
  for (const auto& concept_json : code_system["concept"]) {
    if (concept_json["code"] == code) return concept_json;
  }
  throw std::runtime_error("no concept " + code);
}

bool contains(const std::vector<std::string>& codes, const std::string& code) {
  return std::find(codes.begin(), codes.end(), code) != codes.end();
}

TEST(FhirCodeSystemTest, BundleHoldsOneActiveCompleteCodeSystemPerExportSystem) {
  const json& bundle = shippedCodeSystems();
  EXPECT_EQ(bundle["resourceType"], "Bundle");
  EXPECT_EQ(bundle["type"], "collection");
  ASSERT_EQ(bundle["entry"].size(), 3u);
  const std::vector<std::pair<std::string, std::string>> expected = {
      {fhir::kCodeSystem, "neurological-status"},
      {fhir::kValueSystem, "neurological-status-values"},
      {fhir::kAnatomySystem, "anatomy"}};
  for (std::size_t i = 0; i < expected.size(); ++i) {
    const json& entry = bundle["entry"][i];
    const json& resource = entry["resource"];
    EXPECT_EQ(resource["resourceType"], "CodeSystem");
    EXPECT_EQ(resource["url"], expected[i].first);
    EXPECT_EQ(entry["fullUrl"], expected[i].first);
    EXPECT_EQ(resource["id"], expected[i].second);
    EXPECT_EQ(resource["status"], "active");
    EXPECT_EQ(resource["content"], "complete");
    EXPECT_EQ(resource["caseSensitive"], true);
    EXPECT_EQ(resource["count"], resource["concept"].size());
  }
}

TEST(FhirCodeSystemTest, PropertyCodesAreTheCategoryPropertiesAndTheirRecordedSources) {
  const json& system = codeSystemWithUrl(shippedCodeSystems(), fhir::kCodeSystem);
  const std::vector<std::string> expected = {
      "examination",  // the grouping Observation of one examination
      "radicular_pain.intensity",
      "radicular_pain.trigger",
      "paresis.intensity",
      "paresis.muscle_strength",
      "t_reflex.intensity",
      "excretion_disorder.intensity",
      "sensory_disorder.intensity",
      "sensory_disorder.paresthesia",
      "intracranial_pressure.intensity"};
  EXPECT_EQ(codesOf(system), expected);
  const json& pain = conceptWithCode(system, "radicular_pain.intensity");
  EXPECT_EQ(pain["display"], "Radicular pain intensity");
  EXPECT_EQ(pain["definition"], "numerical 0..10; normal: 0");
  const json& strength = conceptWithCode(system, "paresis.muscle_strength");
  EXPECT_EQ(strength["display"], "Paresis muscle strength (MRC)");
  EXPECT_EQ(strength["definition"],
            "numerical 0..5, as recorded; paresis.intensity is derived from it");
  EXPECT_EQ(conceptWithCode(system, "excretion_disorder.intensity")["definition"],
            "binary {false, true}; normal: false");
}

TEST(FhirCodeSystemTest, ValueCodesAreTheNominalAndOrdinalLabelsWithoutBooleans) {
  const json& system = codeSystemWithUrl(shippedCodeSystems(), fhir::kValueSystem);
  const std::vector<std::string> expected = {"no-abnormal-findings",
                                             "abnormal-findings",  // the value of an examination
                                             "constant",
                                             "stress",
                                             "none",
                                             "mild",
                                             "moderate",
                                             "severe"};
  EXPECT_EQ(codesOf(system), expected);
  EXPECT_EQ(conceptWithCode(system, "stress")["definition"], "Value of radicular_pain.trigger");
  EXPECT_EQ(conceptWithCode(system, "mild")["display"], "mild");
}

TEST(FhirCodeSystemTest, AnatomyCodesAreTheCatalogueWithClassAndFmaId) {
  const json& system = codeSystemWithUrl(shippedCodeSystems(), fhir::kAnatomySystem);
  ASSERT_EQ(system["concept"].size(), shippedModel().anatomy().structures().size());
  const json& muscle = conceptWithCode(system, "biceps_brachii");
  EXPECT_EQ(muscle["display"], "M. biceps brachii");
  EXPECT_EQ(muscle["definition"], "Structure class: muscle");
  EXPECT_EQ(muscle["property"], json::parse(R"([{"code": "structure_class", "valueCode": "muscle"},
                            {"code": "fma_id", "valueString": "FMA:37670"}])"));
  const json& dermatome = conceptWithCode(system, "dermatome_L5");
  EXPECT_EQ(dermatome["property"],
            json::parse(R"([{"code": "structure_class", "valueCode": "dermatome"}])"));
  EXPECT_EQ(system["property"].size(), 2u);
}

TEST(FhirCodeSystemTest, EveryCodeOfOursInTheExportIsDefined) {
  auto examinations = test::sampleExaminations("cases.json");
  const auto figure = test::figurePatient();
  examinations.insert(examinations.end(), figure.begin(), figure.end());
  const json exported = examinationsToFhirBundle(examinations, shippedModel());
  std::map<std::string, std::vector<std::string>> defined;
  for (const char* url : {fhir::kCodeSystem, fhir::kValueSystem, fhir::kAnatomySystem}) {
    defined[url] = codesOf(codeSystemWithUrl(shippedCodeSystems(), url));
  }
  std::size_t checked = 0;
  auto checkCodings = [&](const json& concept_json) {
    for (const auto& coding : concept_json.value("coding", json::array())) {
      const auto system = defined.find(coding.value("system", ""));
      if (system == defined.end()) continue;  // a standard code system
      EXPECT_TRUE(contains(system->second, coding["code"])) << coding.dump();
      ++checked;
    }
  };
  for (const auto& entry : exported["entry"]) {
    const json& resource = entry["resource"];
    checkCodings(resource.value("code", json::object()));
    checkCodings(resource.value("bodySite", json::object()));
    checkCodings(resource.value("valueCodeableConcept", json::object()));
  }
  EXPECT_GT(checked, 2 * exported["entry"].size());
}

TEST(FhirCodeSystemTest, WithoutLabelsOnlyTheExaminationValuesAreDefined) {
  YAML::Node root = test::shippedConfigYaml();
  YAML::Node reflex = test::entryWithId(root["categories"], "t_reflex");
  root["categories"] = YAML::Load("[]");
  root["categories"].push_back(reflex);
  root["views"] = YAML::Load(
      "[{id: reflexes, label: Reflexes, categories: [{category: t_reflex, hue: green}]}]");
  const json bundle = codeSystemResources(test::modelFrom(root));
  const json& values = codeSystemWithUrl(bundle, fhir::kValueSystem);
  EXPECT_EQ(values["count"], 2);
  EXPECT_EQ(codesOf(values),
            (std::vector<std::string>{fhir::kNoAbnormalFindings, fhir::kAbnormalFindings}));
  EXPECT_EQ(codesOf(codeSystemWithUrl(bundle, fhir::kCodeSystem)),
            (std::vector<std::string>{fhir::kExaminationCode, "t_reflex.intensity"}));
}

}  // namespace
}  // namespace vicc_anatomy_viz
