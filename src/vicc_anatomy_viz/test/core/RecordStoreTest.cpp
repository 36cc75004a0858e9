// The SQLite record store on real database files: round trip, at-or-before queries, atomic
// batches, migrations, and clear errors for locked, corrupt and foreign files.
#include <gtest/gtest.h>

#include <sqlite3.h>

#include <chrono>
#include <filesystem>
#include <functional>

#include "test_support.hpp"
#include "vicc_anatomy_viz/errors.hpp"
#include "vicc_anatomy_viz/patient_status_service.hpp"
#include "vicc_anatomy_viz/record_store.hpp"
#include "vicc_anatomy_viz/schema_migrations.hpp"
#include "vicc_anatomy_viz/time_format.hpp"

namespace vicc_anatomy_viz {
namespace {

using test::figurePatient;
using test::shippedModel;
using test::storeErrorKind;
using test::TempDir;

StoreConfig storeAt(const std::string& path, int busy_timeout_ms = 5000) {
  StoreConfig config;
  config.path = path;
  config.busy_timeout_ms = busy_timeout_ms;
  return config;
}

ValidatedBatch validated(std::vector<Examination> examinations) {
  return ExaminationValidator(shippedModel(), "neurological_status_sdh")
      .validate(std::move(examinations));
}

/// Raw access for setting up files the store must cope with.
class RawDb {
 public:
  explicit RawDb(const std::string& path) { sqlite3_open(path.c_str(), &db_); }
  ~RawDb() { sqlite3_close(db_); }
  int exec(const std::string& sql) {
    return sqlite3_exec(db_, sql.c_str(), nullptr, nullptr, nullptr);
  }
  std::string text(const std::string& sql) {
    sqlite3_stmt* statement = nullptr;
    sqlite3_prepare_v2(db_, sql.c_str(), -1, &statement, nullptr);
    std::string out;
    if (sqlite3_step(statement) == SQLITE_ROW) {
      out = reinterpret_cast<const char*>(sqlite3_column_text(statement, 0));
    }
    sqlite3_finalize(statement);
    return out;
  }

 private:
  sqlite3* db_ = nullptr;
};

TEST(RecordStoreTest, CreatesAVersionedWalDatabaseInNewDirectories) {
  TempDir dir;
  const std::string path = dir.file("nested/dirs/patients.db");
  {
    RecordStore store(storeAt(path));
    EXPECT_EQ(store.schemaVersion(), latestSchemaVersion());
    EXPECT_EQ(store.integrityCheck(), std::vector<std::string>{"ok"});
  }
  RawDb raw(path);
  EXPECT_EQ(raw.text("PRAGMA journal_mode"), "wal");
  EXPECT_EQ(raw.text("PRAGMA application_id"), std::to_string(kApplicationId));
  EXPECT_EQ(raw.text("PRAGMA user_version"), std::to_string(latestSchemaVersion()));
}

TEST(RecordStoreTest, ExaminationsRoundTripExactly) {
  TempDir dir;
  RecordStore store(storeAt(dir.file("p.db")));
  const auto figure = figurePatient();
  store.write(validated(figure));
  const auto loaded = store.examinations("SDH-046");
  ASSERT_EQ(loaded.size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_EQ(loaded[i].taken_at_us, figure[i].taken_at_us);
    EXPECT_EQ(loaded[i].view_id, "neurological_status_sdh");
    EXPECT_EQ(loaded[i].source, "json");
    auto expected = figure[i].findings;
    auto actual = loaded[i].findings;
    ASSERT_EQ(actual.size(), expected.size());
    for (const auto& finding : expected) {
      EXPECT_NE(std::find(actual.begin(), actual.end(), finding), actual.end())
          << finding.describe();
    }
  }
  const auto patients = store.listPatients();
  ASSERT_EQ(patients.size(), 1u);
  EXPECT_EQ(patients[0].patient_id, "SDH-046");
  EXPECT_EQ(patients[0].examination_count, 2u);
  EXPECT_EQ(formatTimestamp(patients[0].first_examination), "2023-03-06T09:15:00Z");
  EXPECT_EQ(store.examinationTimes("SDH-046"),
            (std::vector<TimestampUs>{figure[0].taken_at_us, figure[1].taken_at_us}));
}

TEST(RecordStoreTest, StatusAtADateIsTheExaminationAtOrBeforeIt) {
  TempDir dir;
  RecordStore store(storeAt(dir.file("p.db")));
  store.write(validated(figurePatient()));
  EXPECT_FALSE(store.examinationAtOrBefore("SDH-046", *parseUpperBound("2023-03-05")).has_value());
  EXPECT_EQ(
      formatTimestamp(
          store.examinationAtOrBefore("SDH-046", *parseUpperBound("2023-03-06"))->taken_at_us),
      "2023-03-06T09:15:00Z");
  EXPECT_EQ(
      formatTimestamp(
          store.examinationAtOrBefore("SDH-046", *parseUpperBound("2023-03-09"))->taken_at_us),
      "2023-03-06T09:15:00Z");
  EXPECT_EQ(formatTimestamp(
                store.examinationAtOrBefore("SDH-046", *parseUpperBound("2023-03-10T08:40:00Z"))
                    ->taken_at_us),
            "2023-03-10T08:40:00Z");
  std::string message;
  EXPECT_EQ(storeErrorKind([&] { store.examinationAtOrBefore("SDH-999", 0); }, &message),
            StoreError::Kind::kNotFound);
  EXPECT_EQ(message, "unknown patient 'SDH-999'");
}

TEST(RecordStoreTest, ABatchWithOneBadValueWritesNothing) {
  TempDir dir;
  PatientStatusConfig config;
  config.encoding_config = test::encodingConfigPath();
  config.anatomy_config = test::anatomyConfigPath();
  config.store = storeAt(dir.file("p.db"));
  PatientStatusService service(config);
  auto batch = test::sampleExaminations("cases.json");
  batch.back().findings.front().values["intensity"] = Value::number(11);  // pain 11 of 10
  try {
    service.record(batch, WriteMode::kRejectExisting);
    FAIL();
  } catch (const ValidationError& e) {
    EXPECT_NE(std::string(e.what()).find("patient SDH-105, examination 2024-05-27T08:30:00Z, "
                                         "finding 1 (radicular_pain on dermatome_C7 left): "
                                         "property 'intensity': the value is outside the "
                                         "domain 0..10"),
              std::string::npos)
        << e.what();
  }
  EXPECT_TRUE(service.listPatients().empty());
}

TEST(RecordStoreTest, ConflictingBatchIsRolledBackWhole) {
  TempDir dir;
  RecordStore store(storeAt(dir.file("p.db")));
  auto figure = figurePatient();
  store.write(validated({figure[0]}));
  auto cases = test::sampleExaminations("cases.json");
  cases.push_back(figure[0]);  // already recorded
  std::string message;
  EXPECT_EQ(storeErrorKind([&] { store.write(validated(cases)); }, &message),
            StoreError::Kind::kConflict);
  EXPECT_NE(message.find("patient SDH-046, examination 2023-03-06T09:15:00Z is already recorded"),
            std::string::npos);
  EXPECT_EQ(store.listPatients().size(), 1u);  // none of the cases was written
  figure[0].findings.pop_back();
  store.write(validated({figure[0]}), WriteMode::kReplace);
  EXPECT_EQ(store.examinations("SDH-046")[0].findings.size(), figure[0].findings.size());
  // The replaced examination's findings went with it (foreign keys, ON DELETE CASCADE).
  EXPECT_EQ(store.integrityCheck(), std::vector<std::string>{"ok"});
  RawDb raw(dir.file("p.db"));
  EXPECT_EQ(raw.text("SELECT count(*) FROM findings"), std::to_string(figure[0].findings.size()));
}

TEST(RecordStoreTest, CorruptFileGivesAClearErrorAndStaysUntouched) {
  TempDir dir;
  const std::string path = dir.file("garbage.db");
  test::writeFile(path, std::string(4096, 'x') + "not a database");
  const std::string before = test::fileBytes(path);
  std::string message;
  EXPECT_EQ(storeErrorKind([&] { RecordStore store(storeAt(path)); }, &message),
            StoreError::Kind::kCorrupt);
  EXPECT_NE(message.find("'" + path + "'"), std::string::npos);
  EXPECT_NE(message.find("not an SQLite database"), std::string::npos);
  EXPECT_EQ(test::fileBytes(path), before);
}

TEST(RecordStoreTest, DamagedPagesAreReportedNotCrashedOn) {
  TempDir dir;
  const std::string path = dir.file("damaged.db");
  {
    RecordStore store(storeAt(path));
    store.write(validated(test::sampleExaminations("cases.json")));
  }
  {
    RawDb raw(path);
    raw.exec("PRAGMA wal_checkpoint(TRUNCATE)");
  }
  std::string bytes = test::fileBytes(path);
  ASSERT_GT(bytes.size(), 4096u * 3);
  for (std::size_t i = 4096 + 8; i < bytes.size(); i += 7) bytes[i] = static_cast<char>(0xA5);
  test::writeFile(path, bytes);
  std::string message;
  const auto kind = storeErrorKind(
      [&] {
        RecordStore store(storeAt(path));
        store.examinations();
      },
      &message);
  EXPECT_EQ(kind, StoreError::Kind::kCorrupt) << message;
  EXPECT_NE(message.find(path), std::string::npos);
}

TEST(RecordStoreTest, ForeignDatabaseIsRefusedAndLeftAsItWas) {
  TempDir dir;
  const std::string path = dir.file("other.db");
  {
    RawDb raw(path);
    raw.exec("CREATE TABLE invoices (id INTEGER PRIMARY KEY, total REAL)");
  }
  const std::string before = test::fileBytes(path);
  std::string message;
  EXPECT_EQ(storeErrorKind([&] { RecordStore store(storeAt(path)); }, &message),
            StoreError::Kind::kForeign);
  EXPECT_NE(message.find("SQLite database of another application"), std::string::npos);
  EXPECT_EQ(test::fileBytes(path), before);
  RawDb raw(path);
  EXPECT_EQ(raw.text("PRAGMA journal_mode"), "delete");
}

TEST(RecordStoreTest, NewerSchemaIsRefused) {
  TempDir dir;
  const std::string path = dir.file("p.db");
  { RecordStore store(storeAt(path)); }
  {
    RawDb raw(path);
    raw.exec("PRAGMA user_version = 99");
  }
  std::string message;
  EXPECT_EQ(storeErrorKind([&] { RecordStore store(storeAt(path)); }, &message),
            StoreError::Kind::kNewerSchema);
  EXPECT_NE(message.find("schema version 99, newer than this program's 3"), std::string::npos);
}

TEST(RecordStoreTest, Version1DatabaseIsMigratedWithItsData) {
  TempDir dir;
  const std::string path = dir.file("v1.db");
  {
    SqliteConnection connection(path, 1000, true);
    migrateSchema(connection, 1);
    connection.exec(
        "INSERT INTO patients (id, pseudonym, created_at) VALUES (1, 'SDH-001', 0);"
        "INSERT INTO examinations (id, patient_id, taken_at, view_id) "
        "  VALUES (1, 1, 1678094100, 'neurological_status_sdh');"
        "INSERT INTO findings (id, examination_id, category, structure, side) "
        "  VALUES (1, 1, 'radicular_pain', 'dermatome_L5', 'left');"
        "INSERT INTO finding_values (finding_id, prop_type, int_value) VALUES (1, 'intensity', "
        "8);");
    EXPECT_EQ(connection.queryInt("PRAGMA user_version"), 1);
  }
  RecordStore store(storeAt(path));
  EXPECT_EQ(store.schemaVersion(), 3);
  // Version 3 keeps times in microseconds: the seconds of version 1 are converted.
  EXPECT_FALSE(store.examinationAtOrBefore("SDH-001", 1678094100 * kMicrosPerSecond - 1));
  const auto examination = store.examinationAtOrBefore("SDH-001", 1678094100 * kMicrosPerSecond);
  ASSERT_TRUE(examination.has_value());
  EXPECT_EQ(formatTimestamp(examination->taken_at_us), "2023-03-06T09:15:00Z");
  EXPECT_EQ(examination->source, "unknown");
  EXPECT_EQ(examination->status, ExaminationStatus::kFinal);
  EXPECT_FALSE(examination->partial);
  ASSERT_EQ(examination->findings.size(), 1u);
  EXPECT_EQ(examination->findings[0].values.at("intensity"), Value::number(8));
}

TEST(RecordStoreTest, LockedDatabaseIsWaitedForThenReported) {
  TempDir dir;
  const std::string path = dir.file("p.db");
  RecordStore store(storeAt(path, 200));
  store.write(validated({figurePatient()[0]}));
  RawDb other(path);
  ASSERT_EQ(other.exec("BEGIN IMMEDIATE"), SQLITE_OK);  // another writer holds the lock
  // Readers are not blocked by a writer in WAL mode, nor is opening the file.
  EXPECT_EQ(store.listPatients().size(), 1u);
  EXPECT_EQ(RecordStore(storeAt(path, 200)).examinationTimes("SDH-046").size(), 1u);
  std::string message;
  const auto start = std::chrono::steady_clock::now();
  EXPECT_EQ(storeErrorKind([&] { store.write(validated({figurePatient()[1]})); }, &message),
            StoreError::Kind::kLocked);
  const auto waited = std::chrono::steady_clock::now() - start;
  EXPECT_GE(waited, std::chrono::milliseconds(150));
  EXPECT_NE(message.find("locked by another process"), std::string::npos);
  EXPECT_NE(message.find("200 ms"), std::string::npos);
  EXPECT_EQ(store.examinationTimes("SDH-046").size(), 1u);
  other.exec("COMMIT");
  store.write(validated({figurePatient()[1]}));
  EXPECT_EQ(store.examinationTimes("SDH-046").size(), 2u);
}

TEST(RecordStoreTest, ConfigurationIsValidated) {
  EXPECT_THROW(RecordStore(storeAt("")), std::invalid_argument);
  EXPECT_THROW(RecordStore(storeAt("x.db", -1)), std::invalid_argument);
  TempDir dir;
  std::filesystem::create_directories(dir.file("a_directory"));
  std::string message;
  EXPECT_EQ(storeErrorKind([&] { RecordStore store(storeAt(dir.file("a_directory"))); }, &message),
            StoreError::Kind::kIo);
  EXPECT_NE(message.find("is a directory"), std::string::npos);
}

TEST(RecordStoreTest, ReplacementKeepsTheReplacedVersionAsHistory) {
  TempDir dir;
  RecordStore store(storeAt(dir.file("p.db")));
  const auto figure = figurePatient();
  store.write(validated({figure[0]}));
  Examination corrected = figure[0];
  corrected.source = "cli";
  corrected.findings.pop_back();
  store.write(validated({corrected}), WriteMode::kReplace);
  EXPECT_EQ(store.examinations("SDH-046").at(0).findings.size(), corrected.findings.size());
  const auto history = store.history("SDH-046");
  ASSERT_EQ(history.size(), 1u);
  EXPECT_EQ(history[0].examination.taken_at_us, figure[0].taken_at_us);
  EXPECT_EQ(history[0].examination.findings.size(), figure[0].findings.size());
  EXPECT_EQ(history[0].examination.source, "json");
  EXPECT_GT(history[0].examination.recorded_at, 0);
  EXPECT_GE(history[0].superseded_at, history[0].examination.recorded_at);
  EXPECT_EQ(history[0].replaced_by_source, "cli");
}

TEST(RecordStoreTest, AnEmptyReplacementNeedsTheExplicitMode) {
  // A pre-operative examination must not be wiped by an accidental empty replacement.
  TempDir dir;
  RecordStore store(storeAt(dir.file("p.db")));
  const auto figure = figurePatient();
  store.write(validated({figure[0]}));
  Examination empty = figure[0];
  empty.findings.clear();
  std::string message;
  EXPECT_EQ(storeErrorKind([&] { store.write(validated({empty}), WriteMode::kReplace); }, &message),
            StoreError::Kind::kConflict);
  EXPECT_NE(message.find("by one without findings needs the explicit replace-with-empty"),
            std::string::npos)
      << message;
  EXPECT_EQ(store.examinations("SDH-046").at(0).findings.size(), figure[0].findings.size());
  EXPECT_TRUE(store.history("SDH-046").empty());
  store.write(validated({empty}), WriteMode::kReplaceEvenWithEmpty);
  EXPECT_TRUE(store.examinations("SDH-046").at(0).findings.empty());
  EXPECT_EQ(store.history("SDH-046").at(0).examination.findings.size(), figure[0].findings.size());
}

TEST(RecordStoreTest, StatusAndPartialFlagAreStored) {
  TempDir dir;
  RecordStore store(storeAt(dir.file("p.db")));
  Examination examination = figurePatient()[0];
  examination.status = ExaminationStatus::kPreliminary;
  examination.partial = true;
  examination.partial_reason = "1 observation(s) not imported";
  examination.taken_at_us += 250000;  // sub-second times are kept
  store.write(validated({examination}));
  const auto loaded = store.examinationAtOrBefore("SDH-046", examination.taken_at_us);
  ASSERT_TRUE(loaded);
  EXPECT_EQ(loaded->taken_at_us, examination.taken_at_us);
  EXPECT_EQ(loaded->status, ExaminationStatus::kPreliminary);
  EXPECT_TRUE(loaded->partial);
  EXPECT_EQ(loaded->partial_reason, examination.partial_reason);
  EXPECT_FALSE(store.examinationAtOrBefore("SDH-046", examination.taken_at_us - 1));
}

TEST(RecordStoreTest, WritesAreDurableAndFilesPrivate) {
  TempDir dir;
  const std::string path = dir.file("new/dir/p.db");
  RecordStore store(storeAt(path));
  EXPECT_EQ(store.synchronousSetting(), 2);  // FULL: an acknowledged write survives power loss
  store.write(validated({figurePatient()[0]}));
  namespace fs = std::filesystem;
  EXPECT_EQ(fs::status(path).permissions() & fs::perms::all,
            fs::perms::owner_read | fs::perms::owner_write);
  EXPECT_EQ(fs::status(dir.file("new/dir")).permissions() & fs::perms::all, fs::perms::owner_all);
  EXPECT_TRUE(store.warnings().empty());
  fs::permissions(path, fs::perms::group_read | fs::perms::others_read, fs::perm_options::add);
  RecordStore again(storeAt(path));
  ASSERT_FALSE(again.warnings().empty());
  EXPECT_NE(again.warnings()[0].find("chmod 600"), std::string::npos) << again.warnings()[0];
}

TEST(RecordStoreTest, ReadOnlyStoreNeverCreatesAndNeverWrites) {
  TempDir dir;
  StoreConfig config = storeAt(dir.file("missing/p.db"));
  config.read_only = true;
  std::string message;
  EXPECT_EQ(storeErrorKind([&] { RecordStore store(config); }, &message),
            StoreError::Kind::kNotFound);
  EXPECT_NE(message.find("does not exist"), std::string::npos) << message;
  EXPECT_FALSE(std::filesystem::exists(dir.file("missing")));
  config.path = dir.file("p.db");
  { RecordStore(storeAt(config.path)).write(validated({figurePatient()[0]})); }
  RecordStore reader(config);
  EXPECT_EQ(reader.listPatients().size(), 1u);
  EXPECT_THROW(reader.write(validated({figurePatient()[1]})), StoreError);
}

TEST(RecordStoreTest, TheServiceRejectsImplausibleTimesOnEveryWritePath) {
  TempDir dir;
  PatientStatusConfig config;
  config.encoding_config = test::encodingConfigPath();
  config.anatomy_config = test::anatomyConfigPath();
  config.store = storeAt(dir.file("p.db"));
  config.plausibility.now = *parseTimestamp("2026-12-01T12:00:00Z");
  config.plausibility.max_future_seconds = 3600;
  PatientStatusService service(config);
  Examination future = figurePatient()[0];
  future.taken_at_us = *parseTimestamp("2026-12-01T14:00:00Z");
  try {
    service.record({future}, WriteMode::kRejectExisting);
    FAIL() << "a time two hours ahead was recorded";
  } catch (const ValidationError& e) {
    EXPECT_NE(std::string(e.what()).find("patient SDH-046: implausible examination time"),
              std::string::npos)
        << e.what();
  }
  future.taken_at_us = *parseTimestamp("2026-12-01T12:30:00Z");
  EXPECT_EQ(service.record({future}, WriteMode::kRejectExisting), 1u);
}

}  // namespace
}  // namespace vicc_anatomy_viz
