#pragma once
// The use cases shared by the `vicc_patient` CLI and the `patient_status_server` node: list
// patients and examination dates, encode the status at a date, record examinations. Both
// front ends call this one class, so their results are identical.

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "vicc_anatomy_viz/encoding_model.hpp"
#include "vicc_anatomy_viz/examination_validator.hpp"
#include "vicc_anatomy_viz/record_store.hpp"
#include "vicc_anatomy_viz/status_encoder.hpp"

namespace vicc_anatomy_viz {

struct PatientStatusConfig {
  std::string encoding_config;  ///< YAML with hues, visual variables, categories, views
  std::string anatomy_config;   ///< YAML anatomy catalogue
  std::string view_id = "neurological_status_sdh";
  StoreConfig store;
  /// Examination times every write must have (no far future, no year before 1900).
  TimePlausibility plausibility;
  void validate() const;  ///< throws std::invalid_argument naming the field
};

/// <package>/config/..., found in share/vicc_anatomy_viz of the devel or install space.
std::string defaultEncodingConfigPath();
std::string defaultAnatomyConfigPath();

class PatientStatusService {
 public:
  /// Loads and validates the configuration (ConfigError). The database is opened on first
  /// use, and again after a failed open, so a fixed file is picked up without a restart.
  explicit PatientStatusService(const PatientStatusConfig& config);
  ~PatientStatusService();

  const EncodingModel& model() const { return *model_; }
  const View& view() const;
  const PatientStatusConfig& config() const { return config_; }

  /// The store, opened on demand (StoreError when the file is locked, corrupt or foreign).
  RecordStore& store();
  bool storeIsOpen() const { return store_ != nullptr; }

  std::vector<PatientSummary> listPatients();
  std::vector<TimestampUs> examinationDates(const std::string& patient_id);
  /// The examination at or before `date` ("" = latest); ValidationError for a bad date.
  std::optional<Examination> examinationAt(const std::string& patient_id, const std::string& date);
  EncodedStatus encodedStatus(const std::string& patient_id, const std::string& date,
                              const std::vector<std::string>& hidden_categories = {});
  /// Validates against the view (and the times against the plausibility) and writes
  /// atomically; returns the number written.
  std::size_t record(std::vector<Examination> examinations, WriteMode mode);

 private:
  PatientStatusConfig config_;
  std::unique_ptr<EncodingModel> model_;
  std::unique_ptr<ExaminationValidator> validator_;
  std::unique_ptr<StatusEncoder> encoder_;
  std::unique_ptr<RecordStore> store_;
};

}  // namespace vicc_anatomy_viz
