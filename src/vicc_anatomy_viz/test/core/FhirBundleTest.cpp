// HL7 FHIR R4 exchange: a Bundle of Observations with code, effectiveDateTime, bodySite with
// laterality and valueInteger / valueCodeableConcept / valueBoolean.
#include <gtest/gtest.h>

#include <set>

#include "test_support.hpp"
#include "vicc_anatomy_viz/errors.hpp"
#include "vicc_anatomy_viz/examination_validator.hpp"
#include "vicc_anatomy_viz/fhir_bundle.hpp"
#include "vicc_anatomy_viz/time_format.hpp"

namespace vicc_anatomy_viz {
namespace {

using nlohmann::json;
using test::shippedModel;

std::vector<Examination> allSamples() {
  auto examinations = test::sampleExaminations("cases.json");
  const auto figure = test::figurePatient();
  examinations.insert(examinations.end(), figure.begin(), figure.end());
  return examinations;
}

const json* observationWith(const json& bundle, const std::string& code,
                            const std::string& structure) {
  for (const auto& entry : bundle["entry"]) {
    const json& resource = entry["resource"];
    if (resource["code"]["coding"][0]["code"] == code &&
        resource["bodySite"]["coding"][0]["code"] == structure) {
      return &resource;
    }
  }
  return nullptr;
}

TEST(FhirBundleTest, ExportImportRoundTrip) {
  const auto examinations = allSamples();
  const json bundle = examinationsToFhirBundle(examinations, shippedModel());
  EXPECT_EQ(bundle["resourceType"], "Bundle");
  const FhirImport imported = examinationsFromFhirBundle(bundle, shippedModel());
  EXPECT_TRUE(imported.warnings.empty());
  ASSERT_EQ(imported.examinations.size(), examinations.size());
  for (const auto& original : examinations) {
    bool found = false;
    for (const auto& back : imported.examinations) {
      if (back.patient_id != original.patient_id || back.taken_at_us != original.taken_at_us)
        continue;
      found = true;
      EXPECT_EQ(back.source, "fhir");
      ASSERT_EQ(back.findings.size(), original.findings.size()) << original.describe();
      for (const auto& finding : original.findings) {
        EXPECT_NE(std::find(back.findings.begin(), back.findings.end(), finding),
                  back.findings.end())
            << original.describe() << ": " << finding.describe();
      }
    }
    EXPECT_TRUE(found) << original.describe();
  }
  // Exporting is deterministic (stable resource ids).
  EXPECT_EQ(examinationsToFhirBundle(examinations, shippedModel()), bundle);
}

TEST(FhirBundleTest, ObservationsUseValueTypesBodySitesAndLaterality) {
  const json bundle = examinationsToFhirBundle(test::figurePatient(), shippedModel());
  const json* pain = observationWith(bundle, "radicular_pain.intensity", "dermatome_L5");
  ASSERT_NE(pain, nullptr);
  EXPECT_EQ((*pain)["status"], "final");
  EXPECT_EQ((*pain)["code"]["coding"][0]["system"], fhir::kCodeSystem);
  EXPECT_EQ((*pain)["effectiveDateTime"], "2023-03-06T09:15:00Z");
  EXPECT_EQ((*pain)["subject"]["identifier"]["value"], "SDH-046");
  EXPECT_EQ((*pain)["valueInteger"], 8);
  const json& laterality = (*pain)["bodySite"]["extension"][0];
  EXPECT_EQ(laterality["url"], fhir::kLateralityExtension);
  EXPECT_EQ(laterality["valueCodeableConcept"]["coding"][0]["system"], "http://snomed.info/sct");
  EXPECT_EQ(laterality["valueCodeableConcept"]["coding"][0]["code"], "7771000");  // left

  const json* trigger = observationWith(bundle, "radicular_pain.trigger", "dermatome_L5");
  ASSERT_NE(trigger, nullptr);
  EXPECT_EQ((*trigger)["valueCodeableConcept"]["coding"][0]["code"], "constant");

  const json* ehl = observationWith(bundle, "paresis.muscle_strength", "extensor_hallucis_longus");
  ASSERT_NE(ehl, nullptr);
  EXPECT_EQ((*ehl)["bodySite"]["coding"][1]["system"], fhir::kFmaSystem);
  EXPECT_EQ((*ehl)["bodySite"]["coding"][1]["code"], "22533");
  EXPECT_EQ((*ehl)["bodySite"]["extension"][0]["valueCodeableConcept"]["coding"][0]["code"],
            "24028007");  // right

  const json* urethra = observationWith(bundle, "excretion_disorder.intensity", "urethra");
  ASSERT_NE(urethra, nullptr);
  EXPECT_EQ((*urethra)["valueBoolean"], false);
  EXPECT_FALSE((*urethra)["bodySite"].contains("extension"));  // midline
}

json observation(const std::string& code_system, const std::string& code) {
  json resource = json::parse(R"({"resourceType": "Observation", "id": "x1", "status": "final",
    "subject": {"identifier": {"system": "https://vicc.example.org/fhir/NamingSystem/pseudonym",
                               "value": "SDH-200"}},
    "effectiveDateTime": "2024-01-01T10:00:00Z",
    "bodySite": {"coding": [{"system": "https://vicc.example.org/fhir/CodeSystem/anatomy",
                             "code": "dermatome_L4"}],
                 "extension": [{"url": "http://hl7.org/fhir/StructureDefinition/observation-structureLaterality",
                   "valueCodeableConcept": {"coding": [{"system": "http://snomed.info/sct", "code": "24028007"}]}}]},
    "valueInteger": 6})");
  resource["code"] = {{"coding", json::array({{{"system", code_system}, {"code", code}}})}};
  return resource;
}

json bundleOf(std::vector<json> resources) {
  json entries = json::array();
  for (auto& resource : resources) entries.push_back({{"resource", resource}});
  return {{"resourceType", "Bundle"}, {"type", "collection"}, {"entry", entries}};
}

TEST(FhirBundleTest, UnknownCodesAreReportedNotDropped) {
  const json bundle = bundleOf({observation(fhir::kCodeSystem, "radicular_pain.intensity"),
                                observation("http://loinc.org", "72514-3")});
  try {
    examinationsFromFhirBundle(bundle, shippedModel());
    FAIL() << "unknown code silently accepted";
  } catch (const ValidationError& e) {
    ASSERT_EQ(e.problems().size(), 1u);
    EXPECT_NE(
        e.problems()[0].find("entry 1 (Observation x1): unknown code http://loinc.org|72514-3"),
        std::string::npos);
  }
  FhirImportOptions skip;
  skip.skip_unknown = true;
  const FhirImport imported = examinationsFromFhirBundle(bundle, shippedModel(), skip);
  ASSERT_EQ(imported.warnings.size(), 1u);
  EXPECT_NE(imported.warnings[0].find("unknown code http://loinc.org|72514-3 (skipped; the "
                                      "examination is stored as partial)"),
            std::string::npos);
  ASSERT_EQ(imported.examinations.size(), 1u);
  // The pain of the skipped observation is unknown, not normal: the examination says so.
  EXPECT_TRUE(imported.examinations[0].partial);
  EXPECT_EQ(imported.examinations[0].partial_reason, "1 observation(s) not imported");
  const Finding& finding = imported.examinations[0].findings.at(0);
  EXPECT_EQ(finding.structure, "dermatome_L4");
  EXPECT_EQ(finding.side, Side::kRight);
  EXPECT_EQ(finding.values.at("intensity"), Value::number(6));
}

TEST(FhirBundleTest, UnknownBodySitesAndValueCodesAreReported) {
  json foreign_site = observation(fhir::kCodeSystem, "radicular_pain.intensity");
  foreign_site["bodySite"]["coding"][0] = {{"system", "http://snomed.info/sct"}, {"code", "12345"}};
  json foreign_value = observation(fhir::kCodeSystem, "radicular_pain.trigger");
  foreign_value.erase("valueInteger");
  foreign_value["valueCodeableConcept"] = {
      {"coding", json::array({{{"system", "http://example.org/x"}, {"code", "stress"}}})}};
  try {
    examinationsFromFhirBundle(bundleOf({foreign_site, foreign_value}), shippedModel());
    FAIL();
  } catch (const ValidationError& e) {
    const std::string text = e.what();
    EXPECT_NE(text.find("entry 0 (Observation x1): unknown body site http://snomed.info/sct|12345"),
              std::string::npos)
        << text;
    EXPECT_NE(text.find("entry 1 (Observation x1): valueCodeableConcept has no code of our value "
                        "system"),
              std::string::npos)
        << text;
  }
}

TEST(FhirBundleTest, MalformedObservationsAreNamed) {
  json no_subject = observation(fhir::kCodeSystem, "radicular_pain.intensity");
  no_subject.erase("subject");
  json bad_time = observation(fhir::kCodeSystem, "radicular_pain.intensity");
  bad_time["effectiveDateTime"] = "yesterday";
  json duplicate = observation(fhir::kCodeSystem, "radicular_pain.intensity");
  try {
    examinationsFromFhirBundle(bundleOf({no_subject, bad_time, duplicate, duplicate}),
                               shippedModel());
    FAIL();
  } catch (const ValidationError& e) {
    const std::string text = e.what();
    EXPECT_NE(text.find("entry 0 (Observation x1): subject has no identifier of the pseudonym "
                        "system"),
              std::string::npos);
    EXPECT_NE(text.find("entry 1 (Observation x1): effectiveDateTime 'yesterday'"),
              std::string::npos);
    EXPECT_NE(text.find("entry 3 (Observation x1): repeats the observation of entry 2"),
              std::string::npos);
  }
  EXPECT_THROW(examinationsFromFhirBundle(json{{"resourceType", "Patient"}}, shippedModel()),
               ExchangeError);
}

TEST(FhirBundleTest, HospitalFeedSampleImports) {
  const std::string path = test::packagePath("data/samples/fhir/hospital_feed_bundle.json");
  const FhirImport imported =
      examinationsFromFhirBundle(parseJsonText(readTextFile(path), path), shippedModel());
  ASSERT_EQ(imported.warnings.size(), 1u);
  EXPECT_EQ(imported.warnings[0],
            "entry 0: Patient resource ignored (only Observation is imported)");
  ASSERT_EQ(imported.examinations.size(), 1u);
  const Examination& examination = imported.examinations[0];
  EXPECT_EQ(examination.patient_id, "SDH-106");
  EXPECT_EQ(formatTimestamp(examination.taken_at_us), "2024-06-03T05:50:00Z");  // +02:00 -> UTC
  std::set<std::string> described;
  for (const auto& finding : examination.findings) described.insert(finding.describe());
  EXPECT_TRUE(described.count("paresis on extensor_hallucis_longus right"));  // via FMA id
  EXPECT_TRUE(described.count("excretion_disorder on urethra"));
  for (const auto& finding : examination.findings) {
    if (finding.category == "radicular_pain") {
      EXPECT_EQ(finding.values.at("intensity"), Value::number(6));  // valueQuantity
      EXPECT_EQ(finding.values.at("trigger"), Value::label("stress"));
    }
  }
  EXPECT_TRUE(ExaminationValidator(shippedModel(), "neurological_status_sdh")
                  .problems(examination)
                  .empty());
}

}  // namespace
}  // namespace vicc_anatomy_viz
