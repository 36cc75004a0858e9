#pragma once
// The patient record store: a real SQLite database (WAL, foreign keys, versioned schema).
// Writes take validated batches only and are atomic; a locked database is waited for up to
// the busy timeout; a corrupt or foreign file gives a StoreError, never a crash.

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "vicc_anatomy_viz/examination_validator.hpp"
#include "vicc_anatomy_viz/patient_record.hpp"
#include "vicc_anatomy_viz/sqlite_connection.hpp"

namespace vicc_anatomy_viz {

struct StoreConfig {
  std::string path;            ///< database file; parent directories are created
  int busy_timeout_ms = 5000;  ///< how long to wait for another writer's lock
  void validate() const;       ///< throws std::invalid_argument
};

/// ~/.ros/vicc/patients.db (ROS_HOME is honoured).
std::string defaultDatabasePath();

enum class WriteMode {
  kRejectExisting,  ///< an examination at an existing (patient, time) rejects the batch
  kReplace,         ///< it replaces the stored one
};

class RecordStore {
 public:
  explicit RecordStore(const StoreConfig& config);
  ~RecordStore();

  int schemaVersion();
  const std::string& path() const { return config_.path; }

  std::vector<PatientSummary> listPatients();
  /// Examination times of a patient, oldest first; StoreError kNotFound for an unknown id.
  std::vector<std::int64_t> examinationTimes(const std::string& patient_id);
  /// The latest examination at or before `upper_bound` (UTC seconds); nullopt if none.
  /// StoreError kNotFound for an unknown patient.
  std::optional<Examination> examinationAtOrBefore(const std::string& patient_id,
                                                   std::int64_t upper_bound);
  /// All examinations of one patient (or of all patients when `patient_id` is empty).
  std::vector<Examination> examinations(const std::string& patient_id = "");

  /// Writes the batch in one transaction: all of it or nothing.
  void write(const ValidatedBatch& batch, WriteMode mode = WriteMode::kRejectExisting);

  /// Result of PRAGMA integrity_check ("ok" when sound).
  std::vector<std::string> integrityCheck();

 private:
  std::int64_t patientRowId(const std::string& patient_id, bool create);
  void loadFindings(Examination& examination, std::int64_t examination_row);

  StoreConfig config_;
  std::unique_ptr<SqliteConnection> connection_;
  std::unique_ptr<SqliteStatement> find_patient_;
  std::unique_ptr<SqliteStatement> at_or_before_;
  std::unique_ptr<SqliteStatement> findings_of_;
};

}  // namespace vicc_anatomy_viz
