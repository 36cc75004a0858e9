// The vicc_patient command line on a real database file: every subcommand, and bad input
// giving clear errors with exit code 1 (usage errors 2) and nothing half-written.
#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>

#include <nlohmann/json.hpp>

#include "../core/test_support.hpp"
#include "vicc_anatomy_viz/patient_cli.hpp"

namespace vicc_anatomy_viz {
namespace {

using test::packagePath;
using test::TempDir;

struct Result {
  int code;
  std::string out;
  std::string err;
};

class PatientCliTest : public ::testing::Test {
 protected:
  Result run(std::vector<std::string> args, const std::string& db = "") {
    args.insert(args.end(), {"--db", db.empty() ? db_ : db, "--config", test::encodingConfigPath(),
                             "--anatomy", test::anatomyConfigPath()});
    std::ostringstream out, err;
    const int code = runPatientCli(args, out, err);
    return {code, out.str(), err.str()};
  }
  std::string sample(const std::string& name) { return packagePath("data/samples/" + name); }

  TempDir dir_;
  std::string db_ = dir_.file("vicc/patients.db");
};

TEST_F(PatientCliTest, InitImportListDatesShow) {
  Result r = run({"init"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("schema version 3"), std::string::npos);
  r = run({"import", sample("fig4_6_patient.json")});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("imported 2 examination(s) of 1 patient(s)"), std::string::npos);
  ASSERT_EQ(run({"import", sample("cases.json")}).code, 0);
  r = run({"import", sample("fhir/hospital_feed_bundle.json")});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("hospital_feed_bundle.json: entry 0: Patient resource ignored"),
            std::string::npos)
      << r.err;

  r = run({"list"});
  ASSERT_EQ(r.code, 0);
  for (const char* id : {"SDH-046", "SDH-101", "SDH-105", "SDH-106"}) {
    EXPECT_NE(r.out.find(id), std::string::npos) << id;
  }
  r = run({"dates", "--patient", "SDH-046"});
  EXPECT_EQ(r.out, "2023-03-06T09:15:00Z\n2023-03-10T08:40:00Z\n");
  r = run({"show", "--patient", "SDH-046", "--date", "2023-03-08"});
  ASSERT_EQ(r.code, 0);
  EXPECT_NE(r.out.find("examination 2023-03-06T09:15:00Z"), std::string::npos);
  EXPECT_NE(r.out.find("M. extensor hallucis longus (right)"), std::string::npos);
  EXPECT_NE(r.out.find("muscle_strength=3"), std::string::npos);
}

TEST_F(PatientCliTest, EncodeAsJsonAndText) {
  ASSERT_EQ(run({"import", sample("fig4_6_patient.json")}).code, 0);
  Result r = run({"encode", "--patient", "SDH-046", "--date", "2023-03-06", "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  const auto json = nlohmann::json::parse(r.out);
  EXPECT_EQ(json["examination_time"], "2023-03-06T09:15:00Z");
  EXPECT_EQ(json["structures"].size(), 7u);  // with the (illustrative) ICP of 26 mmHg
  EXPECT_EQ(json["alternations"].size(), 1u);
  r = run({"encode", "--patient", "SDH-046", "--date", "2023-03-06", "--json", "--hide",
           "radicular_pain"});
  EXPECT_EQ(nlohmann::json::parse(r.out)["alternations"].size(), 0u);
  r = run({"encode", "--patient", "SDH-046"});
  ASSERT_EQ(r.code, 0);
  EXPECT_NE(r.out.find("examination 2023-03-10T08:40:00Z"), std::string::npos);
  EXPECT_NE(r.out.find("texture noise 2/3"), std::string::npos);
  r = run({"encode", "--patient", "SDH-046", "--date", "2020-01-01"});
  EXPECT_NE(r.out.find("no examination at or before 2020-01-01"), std::string::npos);
}

// Two --patient options would have shown the last patient's status under a command typed for
// the first: a usage error, nothing shown.
TEST_F(PatientCliTest, AnOptionGivenTwiceIsRefused) {
  ASSERT_EQ(run({"import", sample("fig4_6_patient.json")}).code, 0);
  const Result r = run({"encode", "--patient", "OTHER-1", "--patient", "SDH-046", "--json"});
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("option '--patient' is given more than once"), std::string::npos) << r.err;
  EXPECT_EQ(r.out, "");
}

TEST_F(PatientCliTest, RecordAndExportRoundTrip) {
  ASSERT_EQ(run({"import", sample("cases.json")}).code, 0);
  Result r = run({"record", sample("follow_up_examination.json")});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("recorded patient SDH-102, examination 2023-11-02T09:00:00Z"),
            std::string::npos);
  r = run({"record", sample("follow_up_examination.json")});
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("already recorded"), std::string::npos);
  EXPECT_EQ(run({"record", sample("follow_up_examination.json"), "--replace"}).code, 0);
  EXPECT_EQ(run({"record", sample("cases.json")}).code, 1);  // more than one examination

  for (const std::string format : {"json", "fhir"}) {
    const std::string file = dir_.file("export." + format);
    r = run({"export", "--format", format, "--out", file});
    ASSERT_EQ(r.code, 0) << r.err;
    const std::string copy = dir_.file("copy_" + format + ".db");
    ASSERT_EQ(run({"import", file}, copy).code, 0);
    EXPECT_EQ(run({"list"}, copy).out, run({"list"}).out) << format;
    EXPECT_EQ(run({"encode", "--patient", "SDH-103", "--json"}, copy).out,
              run({"encode", "--patient", "SDH-103", "--json"}).out)
        << format;
  }
  r = run({"export", "--patient", "SDH-105"});
  EXPECT_EQ(nlohmann::json::parse(r.out)["patients"].size(), 1u);
}

TEST_F(PatientCliTest, BadInputFailsClearlyAndWritesNothing) {
  const std::string bad = dir_.file("bad.json");
  test::writeFile(bad, R"({"format": "vicc-patient-records", "version": 1, "patients": [
    {"id": "SDH-300", "examinations": [{"taken_at": "2024-01-01", "findings": [
      {"category": "t_reflex", "structure": "patellar_ligament", "side": "left",
       "values": {"intensity": 3}}]}]},
    {"id": "SDH-301", "examinations": [{"taken_at": "2024-01-01", "findings": [
      {"category": "t_reflex", "structure": "patellar_ligament", "side": "left",
       "values": {"intensity": 6}}]}]}]})");
  Result r = run({"import", bad});
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("the value is outside the domain 1..5"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("6"), std::string::npos) << "the rejected value is echoed: " << r.err;
  EXPECT_EQ(run({"list"}).out.find("SDH-300"), std::string::npos);

  // Nothing was written, so there is no database, and a read does not create one.
  r = run({"encode", "--patient", "SDH-999"});
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("does not exist"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(db_)) << "a read command created the database";
  ASSERT_EQ(run({"init"}).code, 0);
  r = run({"encode", "--patient", "SDH-999"});
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("unknown patient 'SDH-999'"), std::string::npos);
  r = run({"encode", "--patient", "SDH-046", "--date", "last week"});
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("date 'last week' is not ISO 8601"), std::string::npos);

  const std::string garbage = dir_.file("garbage.db");
  test::writeFile(garbage, std::string(2048, '\x7f'));
  r = run({"list"}, garbage);
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("not an SQLite database"), std::string::npos);

  EXPECT_EQ(run({"frobnicate"}).code, 2);
  EXPECT_EQ(run({"encode"}).code, 2);  // --patient missing
  EXPECT_EQ(run({"list", "--colour", "red"}).code, 2);
  std::ostringstream out, err;
  EXPECT_EQ(runPatientCli({"--help"}, out, err), 0);
  EXPECT_NE(out.str().find("usage: vicc_patient"), std::string::npos);
}

TEST_F(PatientCliTest, CheckAndConfigReport) {
  ASSERT_EQ(run({"init"}).code, 0);
  Result r = run({"check"});
  EXPECT_EQ(r.code, 0);
  EXPECT_NE(r.out.find("integrity ok"), std::string::npos);
  r = run({"config"});
  EXPECT_EQ(r.code, 0);
  EXPECT_NE(r.out.find("saturation_brightness (3) quantized"), std::string::npos);
  EXPECT_NE(r.out.find("shown alternately"), std::string::npos);
}

TEST_F(PatientCliTest, AllNormalFollowUpSurvivesAFhirRoundTrip) {
  ASSERT_EQ(run({"import", sample("fig4_6_patient.json")}).code, 0);
  const std::string follow_up = dir_.file("normal.json");
  test::writeFile(follow_up, R"({"format": "vicc-examination", "version": 1,
    "patient": "SDH-046", "taken_at": "2023-06-01T09:00:00Z", "findings": []})");
  ASSERT_EQ(run({"record", follow_up}).code, 0);
  const std::string bundle = dir_.file("bundle.json");
  ASSERT_EQ(run({"export", "--format", "fhir", "--out", bundle}).code, 0);
  const std::string copy = dir_.file("copy.db");
  ASSERT_EQ(run({"import", bundle}, copy).code, 0);
  const Result status = run({"encode", "--patient", "SDH-046", "--date", "2023-06-02"}, copy);
  ASSERT_EQ(status.code, 0) << status.err;
  EXPECT_NE(status.out.find("examination 2023-06-01T09:00:00Z"), std::string::npos) << status.out;
  EXPECT_NE(status.out.find("no abnormal findings"), std::string::npos) << status.out;
}

TEST_F(PatientCliTest, PartialImportIsShownAsPartial) {
  nlohmann::json bundle =
      nlohmann::json::parse(test::fileBytes(sample("fhir/hospital_feed_bundle.json")));
  bundle["entry"][1]["resource"]["code"]["coding"][0]["code"] = "radicular_pain.quality";
  const std::string file = dir_.file("partial.json");
  test::writeFile(file, bundle.dump());
  EXPECT_EQ(run({"import", file}).code, 1);  // unknown code: rejected unless skipped
  const Result imported = run({"import", file, "--skip-unknown"});
  ASSERT_EQ(imported.code, 0) << imported.err;
  const Result status = run({"encode", "--patient", "SDH-106"});
  EXPECT_NE(status.out.find("PARTIAL (1 observation(s) not imported)"), std::string::npos)
      << status.out;
  EXPECT_NE(status.out.find("[partial examination]"), std::string::npos) << status.out;
  const auto json_status =
      nlohmann::json::parse(run({"encode", "--patient", "SDH-106", "--json"}).out);
  EXPECT_TRUE(json_status["examination_partial"].get<bool>());
}

TEST_F(PatientCliTest, ReplaceKeepsHistoryAndEmptyReplaceNeedsItsFlag) {
  ASSERT_EQ(run({"import", sample("fig4_6_patient.json")}).code, 0);
  const std::string empty = dir_.file("empty.json");
  test::writeFile(empty, R"({"format": "vicc-examination", "version": 1,
    "patient": "SDH-046", "taken_at": "2023-03-06T09:15:00Z", "findings": []})");
  Result r = run({"record", empty, "--replace"});
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("needs the explicit replace-with-empty option"), std::string::npos) << r.err;
  r = run({"record", empty, "--replace", "--replace-with-empty"});
  ASSERT_EQ(r.code, 0) << r.err;
  r = run({"history", "--patient", "SDH-046"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("2 examination(s), 1 superseded version(s)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("superseded  recorded"), std::string::npos) << r.out;
  const auto exported = nlohmann::json::parse(run({"export"}).out);
  EXPECT_EQ(exported["patients"][0]["superseded"].size(), 1u);
  const auto fhir = nlohmann::json::parse(run({"export", "--format", "fhir"}).out);
  EXPECT_EQ(fhir["entry"][0]["resource"]["status"], "amended");
}

TEST_F(PatientCliTest, ExportNeverOverwritesTheDatabaseAndWritesPrivateFiles) {
  ASSERT_EQ(run({"import", sample("cases.json")}).code, 0);
  const std::string before = test::fileBytes(db_);
  for (const std::string& target : {db_, db_ + "-wal", dir_.file("vicc/../vicc/patients.db")}) {
    const Result r = run({"export", "--out", target});
    EXPECT_EQ(r.code, 1) << target;
    EXPECT_NE(r.err.find("refusing to overwrite it"), std::string::npos) << r.err;
  }
  EXPECT_EQ(test::fileBytes(db_), before);
  EXPECT_EQ(run({"list"}).code, 0);
  const std::string out = dir_.file("export.json");
  ASSERT_EQ(run({"export", "--out", out}).code, 0);
  EXPECT_EQ(std::filesystem::status(out).permissions() & std::filesystem::perms::all,
            std::filesystem::perms::owner_read | std::filesystem::perms::owner_write);
}

TEST_F(PatientCliTest, BackupAndRestore) {
  ASSERT_EQ(run({"import", sample("cases.json")}).code, 0);
  const std::string backup = dir_.file("backup.db");
  Result r = run({"backup", "--out", backup});
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string listed = run({"list"}).out;
  ASSERT_EQ(run({"import", sample("fig4_6_patient.json")}).code, 0);
  EXPECT_NE(run({"list"}).out, listed);
  r = run({"restore", backup});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("the previous record is kept in"), std::string::npos) << r.out;
  EXPECT_EQ(run({"list"}).out, listed);
  r = run({"restore", sample("cases.json")});  // not a database: refused, nothing changed
  EXPECT_EQ(r.code, 1);
  EXPECT_EQ(run({"list"}).out, listed);
}

}  // namespace
}  // namespace vicc_anatomy_viz
