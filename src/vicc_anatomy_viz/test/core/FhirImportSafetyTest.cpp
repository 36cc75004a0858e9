// FHIR import paths that used to show a patient's deficits as normal, or accepted
// contradictory input silently: each case here failed before the fix.
#include <gtest/gtest.h>

#include "test_support.hpp"
#include "vicc_anatomy_viz/errors.hpp"
#include "vicc_anatomy_viz/fhir_bundle.hpp"
#include "vicc_anatomy_viz/time_format.hpp"

namespace vicc_anatomy_viz {
namespace {

using nlohmann::json;
using test::finding;
using test::shippedModel;

/// A foreign feed's Observation: pain intensity 6 on the right L4 dermatome of SDH-200.
json painObservation(const std::string& when = "2024-01-01T10:00:00Z") {
  json resource = json::parse(R"({"resourceType": "Observation", "id": "x1", "status": "final",
    "code": {"coding": [{"system": "https://vicc.example.org/fhir/CodeSystem/neurological-status",
                         "code": "radicular_pain.intensity"}]},
    "subject": {"identifier": {"system": "https://vicc.example.org/fhir/NamingSystem/pseudonym",
                               "value": "SDH-200"}},
    "bodySite": {"coding": [{"system": "https://vicc.example.org/fhir/CodeSystem/anatomy",
                             "code": "dermatome_L4"}],
                 "extension": [{"url": "http://hl7.org/fhir/StructureDefinition/observation-structureLaterality",
                   "valueCodeableConcept": {"coding": [{"system": "http://snomed.info/sct", "code": "24028007"}]}}]},
    "valueInteger": 6})");
  resource["effectiveDateTime"] = when;
  return resource;
}

json triggerObservation(const std::string& when) {
  json resource = painObservation(when);
  resource["code"]["coding"][0]["code"] = "radicular_pain.trigger";
  resource.erase("valueInteger");
  resource["valueCodeableConcept"] = {
      {"coding", json::array({{{"system", fhir::kValueSystem}, {"code", "stress"}}})}};
  return resource;
}

json bundleOf(const std::vector<json>& resources) {
  json entries = json::array();
  for (const auto& resource : resources) entries.push_back({{"resource", resource}});
  return {{"resourceType", "Bundle"}, {"type", "collection"}, {"entry", entries}};
}

/// The rejection message of a bundle; a test failure when it is accepted.
std::string rejection(const json& bundle, const FhirImportOptions& options = {}) {
  try {
    examinationsFromFhirBundle(bundle, shippedModel(), options);
  } catch (const ValidationError& e) {
    return e.what();
  }
  ADD_FAILURE() << "bundle accepted";
  return "";
}

Examination examinationOf(TimestampUs time, std::vector<Finding> findings) {
  Examination examination;
  examination.patient_id = "SDH-046";
  examination.taken_at_us = time;
  examination.source = "test";
  examination.findings = std::move(findings);
  return examination;
}

TEST(FhirImportSafetyTest, AllNormalExaminationSurvivesTheRoundTrip) {
  // Pre-operative deficit, then a follow-up with everything normal.
  const auto before = examinationOf(
      *parseTimestamp("2023-03-06T09:15:00Z"),
      {finding("radicular_pain", "dermatome_L5", Side::kLeft, {{"intensity", Value::number(8)}})});
  const auto follow_up = examinationOf(*parseTimestamp("2023-04-06T09:15:00Z"), {});
  const json bundle = examinationsToFhirBundle({before, follow_up}, shippedModel());
  const FhirImport imported = examinationsFromFhirBundle(bundle, shippedModel());
  ASSERT_EQ(imported.examinations.size(), 2u) << "the all-normal examination vanished";
  EXPECT_EQ(imported.examinations[1].taken_at_us, follow_up.taken_at_us);
  EXPECT_TRUE(imported.examinations[1].findings.empty());
  EXPECT_FALSE(imported.examinations[1].partial);
  EXPECT_EQ(imported.examinations[0].findings.size(), 1u);
  // The grouping Observation says so explicitly, for any receiver.
  const json& panel = bundle["entry"].back()["resource"];
  EXPECT_EQ(panel["code"]["coding"][0]["code"], fhir::kExaminationCode);
  EXPECT_EQ(panel["valueCodeableConcept"]["coding"][0]["code"], fhir::kNoAbnormalFindings);
  EXPECT_FALSE(panel.contains("hasMember"));
}

TEST(FhirImportSafetyTest, ObservationsSecondsApartAreOneExamination) {
  // A foreign feed stamps the values of one examination seconds apart.
  const FhirImport imported =
      examinationsFromFhirBundle(bundleOf({painObservation("2024-01-01T10:00:00Z"),
                                           triggerObservation("2024-01-01T10:00:07Z")}),
                                 shippedModel());
  ASSERT_EQ(imported.examinations.size(), 1u) << "split into a later 'all normal' examination";
  ASSERT_EQ(imported.examinations[0].findings.size(), 1u);
  EXPECT_EQ(imported.examinations[0].findings[0].values.size(), 2u);
  EXPECT_EQ(formatTimestamp(imported.examinations[0].taken_at_us), "2024-01-01T10:00:00Z");
  ASSERT_EQ(imported.warnings.size(), 1u);
  EXPECT_NE(imported.warnings[0].find("grouped by time window"), std::string::npos);
  // Outside the window they are two examinations; the window is configurable.
  FhirImportOptions narrow;
  narrow.grouping_window_seconds = 5;
  EXPECT_EQ(examinationsFromFhirBundle(bundleOf({painObservation("2024-01-01T10:00:00Z"),
                                                 triggerObservation("2024-01-01T10:00:07Z")}),
                                       shippedModel(), narrow)
                .examinations.size(),
            2u);
}

TEST(FhirImportSafetyTest, AnEncounterGroupsWhateverTheTimes) {
  json pain = painObservation("2024-01-01T10:00:00Z");
  json trigger = triggerObservation("2024-01-01T11:30:00Z");
  pain["encounter"] = {{"reference", "Encounter/e1"}};
  trigger["encounter"] = {{"reference", "Encounter/e1"}};
  const FhirImport imported = examinationsFromFhirBundle(bundleOf({pain, trigger}), shippedModel());
  ASSERT_EQ(imported.examinations.size(), 1u);
  EXPECT_NE(imported.warnings.at(0).find("grouped by encounter Encounter/e1"), std::string::npos);
}

TEST(FhirImportSafetyTest, ExportedExaminationIdentityGroupsDifferentTimes) {
  auto examination = examinationOf(
      *parseTimestamp("2023-03-06T09:15:00Z"),
      {finding("radicular_pain", "dermatome_L5", Side::kLeft, {{"intensity", Value::number(8)}})});
  json bundle = examinationsToFhirBundle({examination}, shippedModel());
  // A member edited to another time stays in its examination (hasMember), with a warning.
  bundle["entry"][1]["resource"]["effectiveDateTime"] = "2023-03-06T18:00:00Z";
  const FhirImport imported = examinationsFromFhirBundle(bundle, shippedModel());
  ASSERT_EQ(imported.examinations.size(), 1u);
  EXPECT_EQ(imported.examinations[0].taken_at_us, examination.taken_at_us);
  EXPECT_EQ(imported.examinations[0].findings.size(), 1u);
  EXPECT_EQ(imported.warnings.size(), 1u);
  // A dangling member reference makes the examination incomplete: rejected.
  bundle["entry"].erase(1);
  EXPECT_NE(rejection(bundle).find("is not an Observation of this bundle"), std::string::npos);
}

TEST(FhirImportSafetyTest, SkippedContentMakesThePartialFlagTravel) {
  json unknown = painObservation();
  unknown["code"]["coding"][0]["code"] = "radicular_pain.quality";
  FhirImportOptions skip;
  skip.skip_unknown = true;
  const FhirImport imported = examinationsFromFhirBundle(
      bundleOf({unknown, triggerObservation("2024-01-01T10:00:00Z")}), shippedModel(), skip);
  ASSERT_EQ(imported.examinations.size(), 1u);
  EXPECT_TRUE(imported.examinations[0].partial);
  // Our export carries the flag as a modifierExtension; our import understands it.
  const json bundle = examinationsToFhirBundle(imported.examinations, shippedModel());
  EXPECT_EQ(bundle["entry"][0]["resource"]["modifierExtension"][0]["url"], fhir::kPartialExtension);
  const FhirImport again = examinationsFromFhirBundle(bundle, shippedModel());
  ASSERT_EQ(again.examinations.size(), 1u);
  EXPECT_TRUE(again.examinations[0].partial);
  EXPECT_EQ(again.examinations[0].partial_reason, imported.examinations[0].partial_reason);
}

TEST(FhirImportSafetyTest, AbsentValueIsPartialNotNormal) {
  json absent = painObservation();
  absent.erase("valueInteger");
  absent["dataAbsentReason"] = {{"text", "patient sedated"}};
  const FhirImport imported = examinationsFromFhirBundle(bundleOf({absent}), shippedModel());
  ASSERT_EQ(imported.examinations.size(), 1u);
  EXPECT_TRUE(imported.examinations[0].partial);
  EXPECT_TRUE(imported.examinations[0].findings.empty());
}

TEST(FhirImportSafetyTest, PreliminaryIsKept) {
  json preliminary = painObservation();
  preliminary["status"] = "preliminary";
  const FhirImport imported = examinationsFromFhirBundle(bundleOf({preliminary}), shippedModel());
  ASSERT_EQ(imported.examinations.size(), 1u);
  EXPECT_EQ(imported.examinations[0].status, ExaminationStatus::kPreliminary);
  const json bundle = examinationsToFhirBundle(imported.examinations, shippedModel());
  for (const auto& entry : bundle["entry"]) EXPECT_EQ(entry["resource"]["status"], "preliminary");
}

TEST(FhirImportSafetyTest, ContradictionsAreRejectedNamingTheEntry) {
  json modifier = painObservation();
  modifier["modifierExtension"] = {{{"url", "http://example.org/negated"}, {"valueBoolean", true}}};
  json nested_modifier = painObservation();
  nested_modifier["bodySite"]["modifierExtension"] = {{{"url", "http://example.org/x"}}};
  json two_sides = painObservation();
  two_sides["bodySite"]["extension"].push_back(two_sides["bodySite"]["extension"][0]);
  two_sides["bodySite"]["extension"][1]["valueCodeableConcept"]["coding"][0]["code"] = "7771000";
  json two_sites = painObservation();
  two_sites["bodySite"]["coding"].push_back(
      {{"system", fhir::kAnatomySystem}, {"code", "dermatome_L5"}});
  json fma_conflict = painObservation();
  fma_conflict["bodySite"]["coding"].push_back({{"system", fhir::kFmaSystem}, {"code", "37670"}});
  json comparator = painObservation();
  comparator.erase("valueInteger");
  comparator["valueQuantity"] = {{"value", 6}, {"comparator", ">"}};
  json unit = painObservation();
  unit.erase("valueInteger");
  unit["valueQuantity"] = {{"value", 6}, {"unit", "mg"}};
  json two_values = painObservation();
  two_values["valueBoolean"] = true;
  json mrn = painObservation();
  mrn["subject"]["identifier"]["system"] = "http://hospital.example.org/mrn";
  json reference = painObservation();
  reference["subject"] = {{"reference", "Patient/123"}};
  const std::vector<std::pair<json, std::string>> cases = {
      {modifier, "modifierExtension 'http://example.org/negated' is not understood"},
      {nested_modifier, "modifierExtension 'http://example.org/x' is not understood"},
      {two_sides, "contradictory lateralities"},
      {two_sites, "bodySite codes name different structures"},
      {fma_conflict, "bodySite codes name different structures"},
      {comparator, "valueQuantity has a comparator"},
      {unit, "is not a score"},
      {two_values, "2 values"},
      {mrn, "is not a pseudonym"},
      {reference, "subject has no identifier of the pseudonym system"},
  };
  for (const auto& [resource, expected] : cases) {
    const std::string message = rejection(bundleOf({resource}));
    EXPECT_NE(message.find("entry 0 (Observation x1): "), std::string::npos) << message;
    EXPECT_NE(message.find(expected), std::string::npos) << expected << "\n" << message;
    EXPECT_EQ(message.find("123"), std::string::npos) << message;
  }
  // --skip-unknown does not make a contradiction acceptable.
  FhirImportOptions skip;
  skip.skip_unknown = true;
  EXPECT_NE(rejection(bundleOf({two_sides}), skip).find("contradictory"), std::string::npos);
}

TEST(FhirImportSafetyTest, ImplausibleTimesAreRejected) {
  for (const char* when : {"2999-01-01T10:00:00Z", "9999-12-31T10:00:00Z", "1850-01-01",
                           "2024-01-01T10:00:00+14:59", "2016-12-31T23:59:60Z"}) {
    EXPECT_NE(rejection(bundleOf({painObservation(when)})).find("effectiveDateTime"),
              std::string::npos)
        << when;
  }
  const FhirImport imported = examinationsFromFhirBundle(
      bundleOf({painObservation("2024-01-01T10:00:00")}), shippedModel());
  ASSERT_EQ(imported.warnings.size(), 1u);
  EXPECT_NE(imported.warnings[0].find("has no UTC offset; taken as UTC"), std::string::npos);
}

TEST(FhirImportSafetyTest, EmptyExportIsAValidBundleWithoutEntries) {
  const json bundle = examinationsToFhirBundle({}, shippedModel());
  EXPECT_FALSE(bundle.contains("entry"));  // FHIR forbids empty arrays
  EXPECT_TRUE(examinationsFromFhirBundle(bundle, shippedModel()).examinations.empty());
}

}  // namespace
}  // namespace vicc_anatomy_viz
