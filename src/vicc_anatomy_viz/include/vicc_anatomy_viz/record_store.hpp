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
  std::string path;            ///< database file; parent directories are created (0700)
  int busy_timeout_ms = 5000;  ///< how long to wait for another writer's lock
  /// Read commands open the file read-only: a missing file is an error (nothing is created),
  /// and a database on a read-only medium or directory stays readable.
  bool read_only = false;
  void validate() const;  ///< throws std::invalid_argument
};

/// ~/.ros/vicc/patients.db (ROS_HOME is honoured).
std::string defaultDatabasePath();

enum class WriteMode {
  kRejectExisting,  ///< an examination at an existing (patient, time) rejects the batch
  /// It replaces the stored one, which is kept as a superseded version (history). Replacing
  /// an examination that has findings by one without any is refused: that would silently
  /// turn a recorded deficit into "normal".
  kReplace,
  kReplaceEvenWithEmpty,  ///< as kReplace, and an examination without findings may replace
};

class RecordStore {
 public:
  explicit RecordStore(const StoreConfig& config);
  ~RecordStore();

  int schemaVersion();
  /// PRAGMA synchronous of the connection (2 = FULL: a reported write survives power loss).
  int synchronousSetting();
  /// What deserves attention about the files (e.g. readable by other users), found at open.
  const std::vector<std::string>& warnings() const { return warnings_; }
  /// Online backup into a new private file (see database_files.hpp).
  void backupTo(const std::string& out_path);
  /// Replaces the whole record by a backup (see database_files.hpp).
  void restoreFrom(const std::string& backup_path);
  const std::string& path() const { return config_.path; }

  std::vector<PatientSummary> listPatients();
  /// Examination times of a patient, oldest first; StoreError kNotFound for an unknown id.
  std::vector<TimestampUs> examinationTimes(const std::string& patient_id);
  /// The latest examination at or before `upper_bound`; nullopt if none.
  /// StoreError kNotFound for an unknown patient.
  std::optional<Examination> examinationAtOrBefore(const std::string& patient_id,
                                                   TimestampUs upper_bound);
  /// All examinations of one patient (or of all patients when `patient_id` is empty).
  std::vector<Examination> examinations(const std::string& patient_id = "");

  /// Superseded versions of a patient's examinations (or of everyone's when `patient_id` is
  /// empty), by examination time, then oldest replacement first.
  std::vector<SupersededExamination> history(const std::string& patient_id = "");

  /// Writes the batch in one transaction: all of it or nothing.
  void write(const ValidatedBatch& batch, WriteMode mode = WriteMode::kRejectExisting);

  /// Result of PRAGMA integrity_check ("ok" when sound).
  std::vector<std::string> integrityCheck();

 private:
  void openForWriting();
  void openReadOnly();
  std::int64_t patientRowId(const std::string& patient_id, bool create);
  void loadFindings(Examination& examination, std::int64_t examination_row);
  /// Moves the stored examination `row` into the history; refuses an empty replacement.
  void supersede(std::int64_t row, const Examination& replacement, WriteMode mode, std::int64_t now,
                 std::vector<std::string>& conflicts);
  void insertExamination(std::int64_t patient_row, const Examination& examination,
                         std::int64_t now);

  StoreConfig config_;
  std::vector<std::string> warnings_;
  std::unique_ptr<SqliteConnection> connection_;
  std::unique_ptr<SqliteStatement> find_patient_;
  std::unique_ptr<SqliteStatement> at_or_before_;
  std::unique_ptr<SqliteStatement> findings_of_;
};

}  // namespace vicc_anatomy_viz
