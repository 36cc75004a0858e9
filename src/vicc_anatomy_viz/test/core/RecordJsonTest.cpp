// Our JSON exchange format.
#include <gtest/gtest.h>

#include "test_support.hpp"
#include "vicc_anatomy_viz/errors.hpp"
#include "vicc_anatomy_viz/record_json.hpp"

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
  EXPECT_THROW(readTextFile("/nonexistent/records.json"), ExchangeError);
}

}  // namespace
}  // namespace vicc_anatomy_viz
