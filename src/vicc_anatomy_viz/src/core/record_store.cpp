#include "vicc_anatomy_viz/record_store.hpp"

#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <stdexcept>

#include "vicc_anatomy_viz/database_files.hpp"
#include "vicc_anatomy_viz/errors.hpp"
#include "vicc_anatomy_viz/record_json.hpp"
#include "vicc_anatomy_viz/schema_migrations.hpp"
#include "vicc_anatomy_viz/time_format.hpp"

namespace vicc_anatomy_viz {

namespace {

/// Resets a cached statement however the query ends, so it can be reused.
class ResetOnExit {
 public:
  explicit ResetOnExit(SqliteStatement& statement) : statement_(statement) {}
  ~ResetOnExit() { statement_.reset(); }
  ResetOnExit(const ResetOnExit&) = delete;
  ResetOnExit& operator=(const ResetOnExit&) = delete;

 private:
  SqliteStatement& statement_;
};

Value readValue(const SqliteStatement& statement, int int_column, int text_column) {
  if (!statement.columnIsNull(int_column)) {
    return Value::number(static_cast<int>(statement.columnInt(int_column)));
  }
  return Value::label(statement.columnText(text_column));
}

/// The examination columns every query selects, after the row id and the pseudonym.
constexpr const char* kExaminationColumns =
    "e.taken_at, e.view_id, e.source, e.status, e.partial, e.partial_reason, e.recorded_at";

/// Reads kExaminationColumns starting at `column`.
Examination readExaminationRow(const SqliteStatement& statement, int column,
                               const std::string& path) {
  Examination examination;
  examination.taken_at_us = statement.columnInt(column);
  examination.view_id = statement.columnText(column + 1);
  examination.source = statement.columnText(column + 2);
  const auto status = examinationStatusFromString(statement.columnText(column + 3));
  if (!status) {
    throw StoreError(StoreError::Kind::kCorrupt,
                     "patient database '" + path + "' holds an invalid examination status");
  }
  examination.status = *status;
  examination.partial = statement.columnInt(column + 4) != 0;
  examination.partial_reason = statement.columnText(column + 5);
  examination.recorded_at = statement.columnInt(column + 6);
  return examination;
}

}  // namespace

void StoreConfig::validate() const {
  if (path.empty()) throw std::invalid_argument("store.path (database file) is empty");
  if (busy_timeout_ms < 0) throw std::invalid_argument("store.busy_timeout_ms must be >= 0");
}

std::string defaultDatabasePath() {
  const char* ros_home = std::getenv("ROS_HOME");
  const char* home = std::getenv("HOME");
  std::string base;
  if (ros_home && *ros_home) {
    base = ros_home;
  } else {
    base = std::string(home && *home ? home : ".") + "/.ros";
  }
  return base + "/vicc/patients.db";
}

RecordStore::RecordStore(const StoreConfig& config) : config_(config) {
  config_.validate();
  if (std::filesystem::is_directory(config_.path)) {
    throw StoreError(StoreError::Kind::kIo,
                     "patient database path '" + config_.path + "' is a directory");
  }
  if (config_.read_only) {
    openReadOnly();
  } else {
    openForWriting();
  }
  find_patient_ = std::make_unique<SqliteStatement>(*connection_,
                                                    "SELECT id FROM patients WHERE pseudonym = ?");
  at_or_before_ = std::make_unique<SqliteStatement>(
      *connection_, std::string("SELECT e.id, ") + kExaminationColumns +
                        " FROM examinations e WHERE e.patient_id = ? AND e.taken_at <= ? "
                        "ORDER BY e.taken_at DESC LIMIT 1");
  findings_of_ = std::make_unique<SqliteStatement>(
      *connection_,
      "SELECT f.id, f.category, f.structure, f.side, v.prop_type, v.int_value, v.text_value "
      "FROM findings f JOIN finding_values v ON v.finding_id = f.id "
      "WHERE f.examination_id = ? ORDER BY f.id, v.prop_type");
}

void RecordStore::openForWriting() {
  // Created 0600 in 0700 directories: the file holds every pseudonym and value.
  connection_ = std::make_unique<SqliteConnection>(config_.path, config_.busy_timeout_ms,
                                                   SqliteConnection::OpenMode::kCreateReadWrite);
  warnings_ = permissionWarnings(config_.path);
  // Identify the file before changing anything in it: another application's database is
  // left exactly as it was.
  checkDatabaseIdentity(*connection_);
  connection_->exec("PRAGMA journal_mode = WAL");
  connection_->exec("PRAGMA foreign_keys = ON");
  connection_->exec("PRAGMA synchronous = FULL");  // commits survive power loss (durability.md)
  migrateSchema(*connection_);
}

void RecordStore::openReadOnly() {
  // A missing file is reported (StoreError kNotFound), never created.
  connection_ = std::make_unique<SqliteConnection>(config_.path, config_.busy_timeout_ms,
                                                   SqliteConnection::OpenMode::kReadOnly);
  warnings_ = permissionWarnings(config_.path);
  checkDatabaseIdentity(*connection_);
  const std::int64_t version = connection_->queryInt("PRAGMA user_version");
  if (version < latestSchemaVersion()) {
    throw StoreError(StoreError::Kind::kOther, "patient database '" + config_.path +
                                                   "' has schema version " +
                                                   std::to_string(version) +
                                                   "; open it for writing once (vicc_patient "
                                                   "init) to migrate it to version " +
                                                   std::to_string(latestSchemaVersion()));
  }
}

RecordStore::~RecordStore() {
  // Statements must be finalized before the connection closes.
  find_patient_.reset();
  at_or_before_.reset();
  findings_of_.reset();
}

int RecordStore::schemaVersion() {
  return static_cast<int>(connection_->queryInt("PRAGMA user_version"));
}

int RecordStore::synchronousSetting() {
  return static_cast<int>(connection_->queryInt("PRAGMA synchronous"));
}

void RecordStore::backupTo(const std::string& out_path) { backupDatabase(*connection_, out_path); }

void RecordStore::restoreFrom(const std::string& backup_path) {
  if (config_.read_only) {
    throw StoreError(StoreError::Kind::kIo,
                     "patient database '" + config_.path + "' is open read-only");
  }
  restoreDatabase(backup_path, *connection_);
}

std::int64_t RecordStore::patientRowId(const std::string& patient_id, bool create) {
  {
    ResetOnExit reset(*find_patient_);
    find_patient_->bind(1, patient_id);
    if (find_patient_->step()) return find_patient_->columnInt(0);
  }
  if (!create) {
    throw StoreError(StoreError::Kind::kNotFound, "unknown patient '" + patient_id + "'");
  }
  SqliteStatement insert(*connection_,
                         "INSERT INTO patients (pseudonym, created_at) VALUES (?, ?)");
  insert.bind(1, patient_id).bind(2, static_cast<std::int64_t>(std::time(nullptr)));
  insert.step();
  return connection_->lastInsertRowid();
}

std::vector<PatientSummary> RecordStore::listPatients() {
  SqliteStatement query(*connection_,
                        "SELECT p.pseudonym, count(e.id), min(e.taken_at), max(e.taken_at) "
                        "FROM patients p LEFT JOIN examinations e ON e.patient_id = p.id "
                        "GROUP BY p.id ORDER BY p.pseudonym");
  std::vector<PatientSummary> patients;
  while (query.step()) {
    PatientSummary summary;
    summary.patient_id = query.columnText(0);
    summary.examination_count = static_cast<std::size_t>(query.columnInt(1));
    summary.first_examination = query.columnInt(2);
    summary.last_examination = query.columnInt(3);
    patients.push_back(summary);
  }
  return patients;
}

std::vector<TimestampUs> RecordStore::examinationTimes(const std::string& patient_id) {
  SqliteTransaction snapshot(*connection_, SqliteTransaction::Mode::kRead);
  const std::int64_t patient = patientRowId(patient_id, false);
  SqliteStatement query(*connection_,
                        "SELECT taken_at FROM examinations WHERE patient_id = ? ORDER BY taken_at");
  query.bind(1, patient);
  std::vector<TimestampUs> times;
  while (query.step()) times.push_back(query.columnInt(0));
  snapshot.commit();
  return times;
}

void RecordStore::loadFindings(Examination& examination, std::int64_t examination_row) {
  ResetOnExit reset(*findings_of_);
  findings_of_->bind(1, examination_row);
  std::int64_t current = -1;
  while (findings_of_->step()) {
    const std::int64_t finding_row = findings_of_->columnInt(0);
    if (finding_row != current) {
      current = finding_row;
      Finding finding;
      finding.category = findings_of_->columnText(1);
      finding.structure = findings_of_->columnText(2);
      const auto side = sideFromString(findings_of_->columnText(3));
      if (!side) {
        throw StoreError(StoreError::Kind::kCorrupt, "patient database '" + config_.path +
                                                         "' holds an invalid side in finding " +
                                                         std::to_string(finding_row));
      }
      finding.side = *side;
      examination.findings.push_back(finding);
    }
    examination.findings.back().values[findings_of_->columnText(4)] =
        readValue(*findings_of_, 5, 6);
  }
}

std::optional<Examination> RecordStore::examinationAtOrBefore(const std::string& patient_id,
                                                              TimestampUs upper_bound) {
  SqliteTransaction snapshot(*connection_, SqliteTransaction::Mode::kRead);
  const std::int64_t patient = patientRowId(patient_id, false);
  Examination examination;
  std::int64_t examination_row = 0;
  {
    ResetOnExit reset(*at_or_before_);
    at_or_before_->bind(1, patient).bind(2, upper_bound);
    if (!at_or_before_->step()) {
      snapshot.commit();
      return std::nullopt;
    }
    examination_row = at_or_before_->columnInt(0);
    examination = readExaminationRow(*at_or_before_, 1, config_.path);
    examination.patient_id = patient_id;
  }
  loadFindings(examination, examination_row);
  snapshot.commit();
  return examination;
}

std::vector<Examination> RecordStore::examinations(const std::string& patient_id) {
  SqliteTransaction snapshot(*connection_, SqliteTransaction::Mode::kRead);
  if (!patient_id.empty()) patientRowId(patient_id, false);
  SqliteStatement query(*connection_,
                        std::string("SELECT e.id, p.pseudonym, ") + kExaminationColumns +
                            " FROM examinations e JOIN patients p ON p.id = e.patient_id "
                            "WHERE ? = '' OR p.pseudonym = ? ORDER BY p.pseudonym, e.taken_at");
  query.bind(1, patient_id).bind(2, patient_id);
  std::vector<std::pair<std::int64_t, Examination>> rows;
  while (query.step()) {
    Examination examination = readExaminationRow(query, 2, config_.path);
    examination.patient_id = query.columnText(1);
    rows.emplace_back(query.columnInt(0), examination);
  }
  std::vector<Examination> out;
  for (auto& [row, examination] : rows) {
    loadFindings(examination, row);
    out.push_back(std::move(examination));
  }
  snapshot.commit();
  return out;
}

std::vector<SupersededExamination> RecordStore::history(const std::string& patient_id) {
  SqliteTransaction snapshot(*connection_, SqliteTransaction::Mode::kRead);
  if (!patient_id.empty()) patientRowId(patient_id, false);
  SqliteStatement query(*connection_,
                        "SELECT p.pseudonym, s.record, s.recorded_at, s.superseded_at, "
                        "s.replaced_by_source FROM superseded_examinations s "
                        "JOIN patients p ON p.id = s.patient_id WHERE ? = '' OR p.pseudonym = ? "
                        "ORDER BY p.pseudonym, s.taken_at, s.superseded_at, s.id");
  query.bind(1, patient_id).bind(2, patient_id);
  std::vector<SupersededExamination> out;
  while (query.step()) {
    SupersededExamination version;
    try {
      const nlohmann::json record = parseJsonText(query.columnText(1), "history");
      const auto parsed = examinationsFromJson(record, "history");
      if (parsed.size() != 1) throw ExchangeError("not one examination");
      version.examination = parsed.front();
      // The version keeps the provenance it had when it was current (none before schema 2).
      const nlohmann::json provenance = record.value("provenance", nlohmann::json::object());
      version.examination.source = provenance.value("source", std::string("unknown"));
    } catch (const std::exception&) {
      throw StoreError(StoreError::Kind::kCorrupt,
                       "patient database '" + config_.path +
                           "' holds an unreadable superseded examination of patient " +
                           query.columnText(0));
    }
    version.examination.recorded_at = query.columnInt(2);
    version.superseded_at = query.columnInt(3);
    version.replaced_by_source = query.columnText(4);
    out.push_back(std::move(version));
  }
  snapshot.commit();
  return out;
}

void RecordStore::supersede(std::int64_t row, const Examination& replacement, WriteMode mode,
                            std::int64_t now, std::vector<std::string>& conflicts) {
  SqliteStatement query(*connection_, std::string("SELECT e.id, ") + kExaminationColumns +
                                          ", e.patient_id FROM examinations e WHERE e.id = ?");
  query.bind(1, row);
  if (!query.step()) return;
  Examination old = readExaminationRow(query, 1, config_.path);
  const std::int64_t patient_row = query.columnInt(8);
  old.patient_id = replacement.patient_id;
  loadFindings(old, row);
  if (replacement.findings.empty() && !old.findings.empty() &&
      mode != WriteMode::kReplaceEvenWithEmpty) {
    conflicts.push_back(replacement.describe() + ": replacing an examination with " +
                        std::to_string(old.findings.size()) +
                        " finding(s) by one without findings needs the explicit "
                        "replace-with-empty option");
    return;
  }
  SqliteStatement keep(*connection_,
                       "INSERT INTO superseded_examinations (patient_id, taken_at, recorded_at, "
                       "superseded_at, replaced_by_source, record) VALUES (?, ?, ?, ?, ?, ?)");
  keep.bind(1, patient_row)
      .bind(2, old.taken_at_us)
      .bind(3, old.recorded_at)
      .bind(4, now)
      .bind(5, replacement.source.empty() ? std::string("unknown") : replacement.source)
      .bind(6, examinationToJson(old).dump());
  keep.step();
  SqliteStatement remove(*connection_, "DELETE FROM examinations WHERE id = ?");
  remove.bind(1, row);
  remove.step();
}

void RecordStore::insertExamination(std::int64_t patient_row, const Examination& examination,
                                    std::int64_t now) {
  SqliteStatement insert_examination(
      *connection_,
      "INSERT INTO examinations (patient_id, taken_at, view_id, source, recorded_at, status, "
      "partial, partial_reason) VALUES (?, ?, ?, ?, ?, ?, ?, ?)");
  insert_examination.bind(1, patient_row)
      .bind(2, examination.taken_at_us)
      .bind(3, examination.view_id)
      .bind(4, examination.source.empty() ? std::string("unknown") : examination.source)
      .bind(5, now)
      .bind(6, toString(examination.status))
      .bind(7, static_cast<std::int64_t>(examination.partial ? 1 : 0))
      .bind(8, examination.partial_reason);
  insert_examination.step();
  const std::int64_t examination_row = connection_->lastInsertRowid();
  SqliteStatement insert_finding(
      *connection_,
      "INSERT INTO findings (examination_id, category, structure, side) VALUES (?, ?, ?, ?)");
  SqliteStatement insert_value(
      *connection_,
      "INSERT INTO finding_values (finding_id, prop_type, int_value, text_value) "
      "VALUES (?, ?, ?, ?)");
  for (const Finding& finding : examination.findings) {
    insert_finding.bind(1, examination_row)
        .bind(2, finding.category)
        .bind(3, finding.structure)
        .bind(4, toString(finding.side));
    insert_finding.step();
    insert_finding.reset();
    const std::int64_t finding_row = connection_->lastInsertRowid();
    for (const auto& [prop_type, value] : finding.values) {
      insert_value.bind(1, finding_row).bind(2, prop_type);
      if (value.isNumber()) {
        insert_value.bind(3, static_cast<std::int64_t>(value.asNumber())).bindNull(4);
      } else {
        insert_value.bindNull(3).bind(4, value.asLabel());
      }
      insert_value.step();
      insert_value.reset();
    }
  }
}

void RecordStore::write(const ValidatedBatch& batch, WriteMode mode) {
  if (config_.read_only) {
    throw StoreError(StoreError::Kind::kIo,
                     "patient database '" + config_.path + "' is open read-only");
  }
  SqliteTransaction transaction(*connection_);
  SqliteStatement find_examination(
      *connection_, "SELECT id FROM examinations WHERE patient_id = ? AND taken_at = ?");
  const auto now = static_cast<std::int64_t>(std::time(nullptr));
  std::vector<std::string> conflicts;
  for (const Examination& examination : batch.examinations()) {
    const std::int64_t patient = patientRowId(examination.patient_id, true);
    find_examination.bind(1, patient).bind(2, examination.taken_at_us);
    const bool exists = find_examination.step();
    const std::int64_t existing = exists ? find_examination.columnInt(0) : 0;
    find_examination.reset();
    if (exists && mode == WriteMode::kRejectExisting) {
      conflicts.push_back(examination.describe() +
                          " is already recorded (replace it explicitly; the recorded version "
                          "is then kept as history)");
      continue;
    }
    const std::size_t conflicts_before = conflicts.size();
    if (exists) supersede(existing, examination, mode, now, conflicts);
    if (conflicts.size() == conflicts_before) insertExamination(patient, examination, now);
  }
  if (!conflicts.empty()) {
    // The transaction rolls back: nothing of the batch is written.
    throw StoreError(StoreError::Kind::kConflict,
                     std::to_string(conflicts.size()) +
                         " examination(s) conflict with the record, nothing was written:\n" +
                         joinProblems(conflicts));
  }
  transaction.commit();
}

std::vector<std::string> RecordStore::integrityCheck() {
  SqliteStatement query(*connection_, "PRAGMA integrity_check");
  std::vector<std::string> rows;
  while (query.step()) rows.push_back(query.columnText(0));
  SqliteStatement keys(*connection_, "PRAGMA foreign_key_check");
  while (keys.step()) rows.push_back("foreign key violation in table " + keys.columnText(0));
  return rows;
}

}  // namespace vicc_anatomy_viz
