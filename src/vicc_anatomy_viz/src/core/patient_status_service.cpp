#include "vicc_anatomy_viz/patient_status_service.hpp"

#include <cstdlib>
#include <filesystem>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "vicc_anatomy_viz/errors.hpp"
#include "vicc_anatomy_viz/time_format.hpp"
#include "vicc_paths/package_share.hpp"

namespace vicc_anatomy_viz {

namespace {

/// <share>/vicc_anatomy_viz/<relative> of the devel or install space holding this code (the
/// core library, or vicc_patient, which takes the core's objects in).
std::string packageFile(const std::string& relative) {
  static const int anchor = 0;
  return vicc_paths::packageDataPath("vicc_anatomy_viz", relative, &anchor).string();
}

/// A database that turned out unusable is dropped, so that the next call opens it afresh.
bool needsReopen(const StoreError& error) {
  return error.kind() == StoreError::Kind::kCorrupt || error.kind() == StoreError::Kind::kIo ||
         error.kind() == StoreError::Kind::kForeign;
}

}  // namespace

std::string defaultEncodingConfigPath() {
  return packageFile("config/encoding/neurological_status.yaml");
}

std::string defaultAnatomyConfigPath() { return packageFile("config/anatomy/structures.yaml"); }

void PatientStatusConfig::validate() const {
  if (encoding_config.empty()) throw std::invalid_argument("encoding_config path is empty");
  if (anatomy_config.empty()) throw std::invalid_argument("anatomy_config path is empty");
  if (view_id.empty()) throw std::invalid_argument("view_id is empty");
  store.validate();
  plausibility.validate();
}

PatientStatusService::PatientStatusService(const PatientStatusConfig& config) : config_(config) {
  config_.validate();
  model_ = std::make_unique<EncodingModel>(
      EncodingModel::load(config_.encoding_config, config_.anatomy_config));
  validator_ = std::make_unique<ExaminationValidator>(*model_, config_.view_id);
  encoder_ = std::make_unique<StatusEncoder>(*model_, config_.view_id);
}

PatientStatusService::~PatientStatusService() = default;

const View& PatientStatusService::view() const { return model_->view(config_.view_id); }

RecordStore& PatientStatusService::store() {
  if (!store_) store_ = std::make_unique<RecordStore>(config_.store);
  return *store_;
}

std::vector<PatientSummary> PatientStatusService::listPatients() {
  try {
    return store().listPatients();
  } catch (const StoreError& error) {
    if (needsReopen(error)) store_.reset();
    throw;
  }
}

std::vector<TimestampUs> PatientStatusService::examinationDates(const std::string& patient_id) {
  if (const std::string reason = patientIdProblem(patient_id); !reason.empty()) {
    throw ValidationError({reason});
  }
  try {
    return store().examinationTimes(patient_id);
  } catch (const StoreError& error) {
    if (needsReopen(error)) store_.reset();
    throw;
  }
}

std::optional<Examination> PatientStatusService::examinationAt(const std::string& patient_id,
                                                               const std::string& date) {
  if (const std::string reason = patientIdProblem(patient_id); !reason.empty()) {
    throw ValidationError({reason});
  }
  TimestampUs bound = std::numeric_limits<TimestampUs>::max();
  if (!date.empty()) {
    const auto parsed = parseUpperBound(date);
    if (!parsed) {
      throw ValidationError(
          {"date '" + date + "' is not ISO 8601 (YYYY-MM-DD or YYYY-MM-DDTHH:MM[:SS][Z])"});
    }
    bound = *parsed;
  }
  try {
    return store().examinationAtOrBefore(patient_id, bound);
  } catch (const StoreError& error) {
    if (needsReopen(error)) store_.reset();
    throw;
  }
}

EncodedStatus PatientStatusService::encodedStatus(
    const std::string& patient_id, const std::string& date,
    const std::vector<std::string>& hidden_categories) {
  const auto examination = examinationAt(patient_id, date);
  EncodeOptions options;
  options.requested_date = date;
  options.hidden_categories = hidden_categories;
  return encoder_->encode(patient_id, examination, options);
}

std::size_t PatientStatusService::record(std::vector<Examination> examinations, WriteMode mode) {
  std::vector<std::string> implausible;
  for (const auto& examination : examinations) {
    const std::string problem = config_.plausibility.problem(examination.taken_at_us);
    if (!problem.empty()) {
      implausible.push_back("patient " + examination.patient_id +
                            ": implausible examination time: " + problem);
    }
  }
  if (!implausible.empty()) throw ValidationError(implausible);
  const ValidatedBatch batch = validator_->validate(std::move(examinations));
  try {
    store().write(batch, mode);
  } catch (const StoreError& error) {
    if (needsReopen(error)) store_.reset();
    throw;
  }
  return batch.examinations().size();
}

}  // namespace vicc_anatomy_viz
