// Our JSON exchange format.
#include <gtest/gtest.h>

#include "test_support.hpp"
#include "vicc_anatomy_viz/errors.hpp"
#include "vicc_anatomy_viz/record_json.hpp"
#include "vicc_anatomy_viz/time_format.hpp"

namespace vicc_anatomy_viz {
namespace {

using nlohmann::json;

TEST(RecordJsonTest, RecordsRoundTrip) {
  auto examinations = test::sampleExaminations("cases.json");
  const auto figure = test::figurePatient();
  examinations.insert(examinations.end(), figure.begin(), figure.end());
  const auto again = examinationsFromJson(recordsToJson(examinations));
  ASSERT_EQ(again.size(), examinations.size());
  for (std::size_t i = 0; i < again.size(); ++i) {
    EXPECT_EQ(again[i].patient_id, examinations[i].patient_id);
    EXPECT_EQ(again[i].taken_at_us, examinations[i].taken_at_us);
    EXPECT_EQ(again[i].findings, examinations[i].findings);
  }
}

TEST(RecordJsonTest, BinaryValuesTravelAsBooleans) {
  const auto figure = test::figurePatient();
  EXPECT_EQ(figure[0].findings.back().values.at("intensity"), Value::label("false"));
  const json document = examinationToJson(figure[0]);
  EXPECT_EQ(document["format"], "vicc-examination");
  EXPECT_EQ(document["findings"].back()["values"]["intensity"], false);
  EXPECT_EQ(examinationsFromJson(document)[0].findings, figure[0].findings);
}

TEST(RecordJsonTest, EveryMalformedItemIsNamedByItsPath) {
  const json document = json::parse(R"({
    "format": "vicc-patient-records", "version": 1,
    "patients": [{"id": "SDH-1", "examinations": [
      {"taken_at": "2023-02-30", "findings": [
        {"category": "radicular_pain", "structure": "dermatome_L5", "side": "links",
         "values": {"intensity": 7.5, "trigger": null}}]}]},
      {"id": "Max Muster", "examinations": []}]})");
  try {
    examinationsFromJson(document);
    FAIL();
  } catch (const ValidationError& e) {
    const std::string text = e.what();
    EXPECT_EQ(e.problems().size(), 5u) << text;
    for (const char* fragment :
         {"$.patients[0].examinations[0].taken_at: '2023-02-30' is not an ISO 8601",
          "$.patients[0].examinations[0].findings[0].side: 'links' is not left, right or none",
          "$.patients[0].examinations[0].findings[0].values.intensity: is not an integer",
          "$.patients[0].examinations[0].findings[0].values.trigger: must be an integer",
          "$.patients[1].id: patient id may only contain"}) {
      EXPECT_NE(text.find(fragment), std::string::npos) << fragment;
    }
    EXPECT_EQ(text.find("Muster"), std::string::npos);
  }
}

TEST(RecordJsonTest, UnreadableDocumentsGiveExchangeErrors) {
  EXPECT_THROW(examinationsFromJson(json::array()), ExchangeError);
  EXPECT_THROW(examinationsFromJson(json{{"format", "csv"}}), ExchangeError);
  EXPECT_THROW(examinationsFromJson(json{{"format", "vicc-patient-records"}, {"version", 7}}),
               ExchangeError);
  try {
    parseJsonText("{\"format\": ", "broken.json");
    FAIL();
  } catch (const ExchangeError& e) {
    EXPECT_NE(std::string(e.what()).find("broken.json: invalid JSON"), std::string::npos);
  }
  try {
    parseJsonText("{\"values\": {\"intensity\": 9x}}", "typo.json");
    FAIL();
  } catch (const ExchangeError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("typo.json: invalid JSON"), std::string::npos) << message;
    EXPECT_NE(message.find("line 1, column"), std::string::npos) << message;
    EXPECT_EQ(message.find("9x"), std::string::npos) << "quotes the input: " << message;
  }
  EXPECT_THROW(readTextFile("/nonexistent/records.json"), ExchangeError);
}

TEST(RecordJsonTest, RepeatedKeysAreRejectedNotResolvedToTheLast) {
  // {"intensity": 1, "intensity": 9}: which pain was recorded is unknown.
  for (const char* text :
       {R"({"format": "vicc-examination", "version": 1, "patient": "P-1",
            "taken_at": "2024-01-01T10:00:00Z", "findings": [{"category": "radicular_pain",
            "structure": "dermatome_L5", "side": "left",
            "values": {"intensity": 1, "intensity": 9}}]})",
        R"({"format": "vicc-examination", "format": "vicc-examination", "version": 1})"}) {
    try {
      parseJsonText(text, "exam.json");
      FAIL() << text;
    } catch (const ExchangeError& e) {
      const std::string message = e.what();
      EXPECT_NE(message.find("exam.json: key \""), std::string::npos) << message;
      EXPECT_NE(message.find("appears twice"), std::string::npos) << message;
      EXPECT_EQ(message.find('9'), std::string::npos) << message;  // no value in messages
    }
  }
  EXPECT_NE(std::string(parseJsonText(R"({"a": {"x": 1}, "b": {"x": 2}})", "ok.json").dump()),
            "");  // the same key in different objects is fine
}

TEST(RecordJsonTest, StatusPartialAndProvenanceTravel) {
  auto examination = test::figurePatient()[0];
  examination.status = ExaminationStatus::kPreliminary;
  examination.partial = true;
  examination.partial_reason = "2 observation(s) not imported";
  examination.recorded_at = 1700000000;
  examination.source = "fhir";
  const json document = examinationToJson(examination);
  EXPECT_EQ(document["status"], "preliminary");
  EXPECT_EQ(document["provenance"]["source"], "fhir");
  EXPECT_EQ(document["provenance"]["recorded_at"], "2023-11-14T22:13:20Z");
  const auto back = examinationsFromJson(document);
  ASSERT_EQ(back.size(), 1u);
  EXPECT_EQ(back[0].status, ExaminationStatus::kPreliminary);
  EXPECT_TRUE(back[0].partial);
  EXPECT_EQ(back[0].partial_reason, examination.partial_reason);
  json bad = document;
  bad["status"] = "draft";
  bad["partial"] = "yes";
  try {
    examinationsFromJson(bad);
    FAIL();
  } catch (const ValidationError& e) {
    // The bad status, the bad flag, and a reason for an examination now not partial.
    EXPECT_EQ(e.problems().size(), 3u) << e.what();
    EXPECT_NE(std::string(e.what()).find("$.status: 'draft' is not final or preliminary"),
              std::string::npos);
  }
}

TEST(RecordJsonTest, TimesKeepFractionsAndImplausibleOnesAreRejected) {
  auto document = examinationToJson(test::figurePatient()[0]);
  document["taken_at"] = "2023-03-06T09:15:00.9Z";
  EXPECT_EQ(examinationsFromJson(document)[0].taken_at_us,
            *parseTimestamp("2023-03-06T09:15:00Z") + 900000);
  std::vector<std::string> warnings;
  document["taken_at"] = "2023-03-06T09:15:00";
  examinationsFromJson(document, "json", &warnings);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("$.taken_at: '2023-03-06T09:15:00' has no UTC offset"),
            std::string::npos)
      << warnings[0];
  for (const char* when : {"2999-01-01", "9999-12-31T00:00:00Z", "2023-03-06T09:15:00+14:59",
                           "2016-12-31T23:59:60Z"}) {
    document["taken_at"] = when;
    EXPECT_THROW(examinationsFromJson(document), ValidationError) << when;
  }
}

}  // namespace
}  // namespace vicc_anatomy_viz
