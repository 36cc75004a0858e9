// Fuzz target 3: the examination validator, and what it lets through.
#include <algorithm>
#include <optional>
#include <string>
#include <vector>

#include "fuzz_targets.hpp"
#include "fuzzed_examinations.hpp"
#include "vicc_anatomy_viz/errors.hpp"
#include "vicc_anatomy_viz/examination_validator.hpp"
#include "vicc_anatomy_viz/record_json.hpp"
#include "vicc_anatomy_viz/status_encoder.hpp"

namespace vicc_anatomy_viz::fuzz {

namespace {

std::vector<Examination> byPatientAndTime(std::vector<Examination> examinations) {
  std::sort(examinations.begin(), examinations.end(),
            [](const Examination& a, const Examination& b) {
              return std::make_pair(a.patient_id, takenAtOf(a)) <
                     std::make_pair(b.patient_id, takenAtOf(b));
            });
  return examinations;
}

/// Our JSON export of validated examinations, as text, must import back to the same records
/// (the export groups by patient, so the order may change).
void checkJsonRoundTrip(const std::vector<Examination>& validated) {
  std::vector<Examination> imported;
  try {
    // Plausibility (no times far in the future or before 1900) is the import's and the
    // service's policy, not the validator's: the round trip checks the format over every
    // time the format can write (years 0000-9999).
    JsonImportOptions options;
    options.plausibility.min_year = 0;
    options.plausibility.max_future_seconds = 1000000000000;
    imported = examinationsFromJson(parseJsonText(recordsToJson(validated).dump(), "export"),
                                    "json", nullptr, options);
  } catch (const std::exception& e) {
    throw FuzzInvariantError(std::string("export of a validated batch does not import: ") +
                             e.what());
  }
  const std::vector<Examination> expected = byPatientAndTime(validated);
  imported = byPatientAndTime(std::move(imported));
  if (imported.size() != expected.size()) throw FuzzInvariantError("examination count differs");
  for (std::size_t i = 0; i < expected.size(); ++i) {
    if (imported[i].patient_id != expected[i].patient_id ||
        takenAtOf(imported[i]) != takenAtOf(expected[i]) ||
        imported[i].findings != expected[i].findings) {
      throw FuzzInvariantError("examination " + std::to_string(i) + " differs after export");
    }
  }
}

}  // namespace

int fuzzValidator(const std::uint8_t* data, std::size_t size) {
  FuzzedDataProvider provider(data, size);
  FuzzedExaminations fuzzed(fuzzModel(), provider);
  const std::string view_id = fuzzed.viewId();
  const ExaminationValidator validator(fuzzModel(), view_id);
  std::optional<ValidatedBatch> batch;
  try {
    batch.emplace(validator.validate(fuzzed.examinations()));
  } catch (const ValidationError&) {
    return 0;
  }
  const StatusEncoder encoder(fuzzModel(), view_id);
  for (const Examination& examination : batch->examinations()) {
    encoder.encode(examination.patient_id, examination);
  }
  checkJsonRoundTrip(batch->examinations());
  return 0;
}

}  // namespace vicc_anatomy_viz::fuzz
