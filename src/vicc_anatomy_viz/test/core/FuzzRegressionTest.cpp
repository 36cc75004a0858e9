// Replays the fuzz seeds and the minimised crash inputs under fuzz/regressions/<target>/
// through the same harness functions libFuzzer runs (fuzz/run_fuzz.sh).
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "fuzz_targets.hpp"
#include "test_support.hpp"
#include "vicc_anatomy_viz/examination_validator.hpp"
#include "vicc_anatomy_viz/fhir_bundle.hpp"

namespace vicc_anatomy_viz::test {
namespace {

struct FuzzTarget {
  std::string name;
  int (*harness)(const std::uint8_t*, std::size_t);
};

std::ostream& operator<<(std::ostream& out, const FuzzTarget& target) { return out << target.name; }

/// The seed files fuzz/seeds.txt lists for the target, then its regression inputs.
std::vector<std::string> replayInputs(const std::string& target) {
  std::vector<std::string> paths;
  std::ifstream seeds(packagePath("fuzz/seeds.txt"));
  std::string line;
  while (std::getline(seeds, line)) {
    std::istringstream fields(line);
    std::string seed_target, path;
    if (fields >> seed_target >> path && seed_target == target) paths.push_back(packagePath(path));
  }
  const std::filesystem::path regressions = packagePath("fuzz/regressions/" + target);
  if (std::filesystem::is_directory(regressions)) {
    for (const auto& entry : std::filesystem::directory_iterator(regressions)) {
      if (entry.is_regular_file()) paths.push_back(entry.path().string());
    }
  }
  return paths;
}

int replay(const FuzzTarget& target, const std::string& bytes) {
  return target.harness(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
}

class FuzzReplayTest : public ::testing::TestWithParam<FuzzTarget> {};

TEST_P(FuzzReplayTest, EverySeedAndRegressionInputHasAnAllowedOutcome) {
  const std::vector<std::string> inputs = replayInputs(GetParam().name);
  EXPECT_GE(inputs.size(), 2u) << "no seeds listed for " << GetParam().name;
  for (const std::string& path : inputs) {
    ASSERT_TRUE(std::filesystem::is_regular_file(path)) << path;
    EXPECT_NO_THROW(EXPECT_EQ(replay(GetParam(), fileBytes(path)), 0)) << path;
  }
}

TEST_P(FuzzReplayTest, EmptyAndTruncatedInputsHaveAnAllowedOutcome) {
  for (const std::string& path : replayInputs(GetParam().name)) {
    const std::string bytes = fileBytes(path);
    for (std::size_t length : {std::size_t{0}, std::size_t{1}, bytes.size() / 2}) {
      EXPECT_NO_THROW(replay(GetParam(), bytes.substr(0, length))) << path << " at " << length;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Harnesses, FuzzReplayTest,
                         ::testing::Values(FuzzTarget{"json_import", fuzz::fuzzJsonImport},
                                           FuzzTarget{"fhir_import", fuzz::fuzzFhirImport},
                                           FuzzTarget{"validator", fuzz::fuzzValidator}),
                         [](const ::testing::TestParamInfo<FuzzTarget>& info) {
                           return info.param.name;
                         });

Examination normalExaminationAt(std::int64_t seconds) {
  Examination examination;
  examination.patient_id = "SDH-046";
  fuzz::setTakenAtSeconds(examination, seconds);
  return examination;
}

// Found by the validator target: a time our JSON export cannot write was accepted.
TEST(FuzzFindingsTest, ValidatorRejectsTimesOutsideTheIsoYears) {
  const ExaminationValidator validator(shippedModel(), "neurological_status_sdh");
  const std::int64_t first = -62167219200;  // 0000-01-01T00:00:00Z
  const std::int64_t last = 253402300799;   // 9999-12-31T23:59:59Z
  for (const std::int64_t fine : {first, std::int64_t{0}, last}) {
    EXPECT_TRUE(validator.problems(normalExaminationAt(fine)).empty()) << fine;
  }
  for (const std::int64_t outside : {first - 1, last + 1, std::int64_t{-7631201066543}}) {
    const auto problems = validator.problems(normalExaminationAt(outside));
    ASSERT_EQ(problems.size(), 1u) << joinProblems(problems);
    EXPECT_NE(problems[0].find("time cannot be written as ISO 8601 (years 0000-9999)"),
              std::string::npos);
  }
}

// Found by the JSON import target: a "format" that is not text escaped as json::type_error.
TEST(FuzzFindingsTest, JsonFormatThatIsNotTextIsAnExchangeError) {
  for (const char* text : {R"({"format": 4})", R"({"format": ["vicc-examination"]})"}) {
    EXPECT_THROW(examinationsFromJson(nlohmann::json::parse(text)), ExchangeError) << text;
  }
}

// Found by both import targets: a number beyond double escaped as json::out_of_range.
TEST(FuzzFindingsTest, NumberTooLargeIsAnExchangeErrorThatDoesNotQuoteIt) {
  try {
    parseJsonText(R"({"values": {"intensity": 2e401}})", "exam.json");
    FAIL() << "accepted";
  } catch (const ExchangeError& e) {
    const std::string message = e.what();
    EXPECT_EQ(message, "exam.json: invalid JSON (a number is too large)");
  }
}

// Found by the FHIR import target: json::value() threw type_error for a field that is not
// text; now such a field counts as absent or unknown.
TEST(FuzzFindingsTest, FhirFieldsThatAreNotTextAreReportedNotThrown) {
  EXPECT_FALSE(isFhirBundle(nlohmann::json::parse(R"({"resourceType": []})")));
  const std::string seed = fileBytes(packagePath("fuzz/seeds/observation_bundle.json"));
  const auto bundle = [&seed](const char* pointer, nlohmann::json replacement) {
    nlohmann::json document = nlohmann::json::parse(seed);
    document[nlohmann::json::json_pointer(std::string("/entry/0/resource") + pointer)] =
        std::move(replacement);
    return document;
  };
  ASSERT_EQ(
      examinationsFromFhirBundle(nlohmann::json::parse(seed), shippedModel()).examinations.size(),
      1u);
  for (const char* pointer : {"/status", "/code/coding/0/system", "/code/coding/0/code"}) {
    EXPECT_THROW(examinationsFromFhirBundle(bundle(pointer, 1), shippedModel()), ValidationError)
        << pointer;
  }
  // A laterality extension whose url is not text is no laterality: right becomes none, which
  // the bilateral dermatome does not allow, but the import itself reads it.
  const FhirImport no_laterality =
      examinationsFromFhirBundle(bundle("/bodySite/extension/0/url", 7), shippedModel());
  ASSERT_EQ(no_laterality.examinations.size(), 1u);
  EXPECT_EQ(no_laterality.examinations[0].findings.at(0).side, Side::kNone);
  // An id that is not text is named "?"; another resourceType skips the entry.
  EXPECT_EQ(examinationsFromFhirBundle(bundle("/id", nlohmann::json::object()), shippedModel())
                .examinations.size(),
            1u);
  const FhirImport skipped =
      examinationsFromFhirBundle(bundle("/resourceType", nullptr), shippedModel());
  EXPECT_TRUE(skipped.examinations.empty());
  EXPECT_EQ(skipped.warnings.size(), 1u);
}

// Found with the import harnesses' value checks: an integer above LLONG_MAX was read as a
// negative one (18446744073709551615 as -1) instead of being reported out of range.
TEST(FuzzFindingsTest, UnsignedIntegersAboveIntAreOutOfRangeNotWrapped) {
  for (const char* target : {"json_import", "fhir_import"}) {
    const std::string path =
        packagePath(std::string("fuzz/regressions/") + target + "/unsigned_wraps_to_negative.json");
    const nlohmann::json document = parseJsonText(fileBytes(path), path);
    try {
      if (isFhirBundle(document)) {
        examinationsFromFhirBundle(document, shippedModel());
      } else {
        examinationsFromJson(document);
      }
      ADD_FAILURE() << target << ": accepted";
    } catch (const ValidationError& e) {
      ASSERT_EQ(e.problems().size(), 1u) << e.what();
      EXPECT_NE(e.problems()[0].find("out of range"), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace vicc_anatomy_viz::test
