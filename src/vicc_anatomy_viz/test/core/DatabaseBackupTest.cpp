// Online backup and restore of the patient database.
#include <atomic>
#include <chrono>
#include <filesystem>
#include <thread>

#include <gtest/gtest.h>

#include "database_test_support.hpp"
#include "vicc_anatomy_viz/database_files.hpp"

namespace vicc_anatomy_viz::test {
namespace {

std::string dumpOf(const std::string& path) {
  SqliteConnection connection(path, 1000, OpenMode::kReadOnly);
  return recordDump(connection);
}

TEST(DatabaseBackupTest, BackupWhileAnotherConnectionWritesIsAConsistentPrivateCopy) {
  TempDir dir;
  const std::string path = dir.file("p.db");
  createPatientDatabase(path, 0);
  {
    SqliteConnection filler(path, 1000, OpenMode::kReadWrite);
    addPatients(filler, 0, 20000, 200);  // some megabytes, so the copy takes a while
  }
  std::atomic<bool> stop{false};
  std::atomic<int> commits{0};
  std::thread writer([&] {
    SqliteConnection connection(path, 5000, OpenMode::kReadWrite);
    connection.exec("PRAGMA synchronous = OFF");
    for (int next = 100000; !stop; ++next) {
      addPatients(connection, next, 1);  // a patient with its examinations, atomically
      ++commits;
    }
  });
  while (commits < 5) std::this_thread::sleep_for(std::chrono::milliseconds(1));
  SqliteConnection source(path, 5000, OpenMode::kReadWrite);
  const int commits_before = commits;
  backupDatabase(source, dir.file("backup.db"));
  const int commits_during = commits - commits_before;
  stop = true;
  writer.join();

  EXPECT_GT(commits_during, 0) << "the backup blocked the writer";
  EXPECT_EQ(fileMode(dir.file("backup.db")), 0600u);
  // One self-contained file: rollback journal mode (header bytes 18 and 19 are 1, WAL has 2).
  const std::string header = fileBytes(dir.file("backup.db")).substr(0, 100);
  EXPECT_EQ(header.substr(18, 2), std::string("\x01\x01"));
  EXPECT_FALSE(pathExists(dir.file("backup.db-wal")));
  SqliteConnection copy(dir.file("backup.db"), 1000, OpenMode::kReadOnly);
  EXPECT_EQ(copy.queryInt("PRAGMA application_id"), kApplicationId);
  const std::int64_t patients = copy.queryInt("SELECT count(*) FROM patients");
  EXPECT_GE(patients, 20005);
  // Each writer transaction adds a patient with two examinations: a torn copy would differ.
  EXPECT_EQ(copy.queryInt("SELECT count(*) FROM examinations"), 2 * patients);
  EXPECT_EQ(copy.queryInt("SELECT count(*) FROM finding_values"), 2 * patients);
  SqliteStatement check(copy, "PRAGMA integrity_check");
  ASSERT_TRUE(check.step());
  EXPECT_EQ(check.columnText(0), "ok");
}

TEST(DatabaseBackupTest, BackupRefusesAnExistingFileAndTheDatabasesOwnFiles) {
  TempDir dir;
  const std::string path = dir.file("p.db");
  createPatientDatabase(path, 1);
  writeFile(dir.file("old.db"), "keep me");
  std::filesystem::create_symlink(path, dir.file("link.db"));
  SqliteConnection source(path, 1000, OpenMode::kReadWrite);
  std::string message;
  EXPECT_EQ(storeErrorKind([&] { backupDatabase(source, dir.file("old.db")); }, &message),
            StoreError::Kind::kConflict);
  EXPECT_EQ(message, "backup file '" + dir.file("old.db") +
                         "' exists already; a backup never overwrites a file, choose a new name");
  EXPECT_EQ(fileBytes(dir.file("old.db")), "keep me");
  for (const std::string& own : {path, path + "-wal", dir.file("link.db")}) {
    EXPECT_EQ(storeErrorKind([&] { backupDatabase(source, own); }, &message),
              StoreError::Kind::kConflict);
    EXPECT_NE(message.find("is the patient database '" + path + "'"), std::string::npos);
  }
  EXPECT_EQ(source.queryInt("SELECT count(*) FROM patients"), 1);
}

TEST(DatabaseBackupTest, RestoreGivesBackExactlyTheRecordsOfTheBackup) {
  TempDir dir;
  const std::string path = dir.file("p.db");
  createPatientDatabase(path, 4);
  const std::string backed_up = dumpOf(path);
  SqliteConnection live(path, 1000, OpenMode::kReadWrite);
  backupDatabase(live, dir.file("backup.db"));
  live.exec("DELETE FROM patients WHERE id = 2; UPDATE finding_values SET int_value = 0");
  addPatients(live, 10, 2);
  ASSERT_NE(recordDump(live), backed_up);

  restoreDatabase(dir.file("backup.db"), live);
  EXPECT_EQ(recordDump(live), backed_up);
  EXPECT_EQ(live.queryInt("PRAGMA user_version"), latestSchemaVersion());
  EXPECT_EQ(dumpOf(path), backed_up);  // also for another connection
}

class RestoreRefusalTest : public ::testing::Test {
 protected:
  void SetUp() override {
    createPatientDatabase(live_path_, 3);
    live_ = std::make_unique<SqliteConnection>(live_path_, 200, OpenMode::kReadWrite);
    before_ = recordDump(*live_);
  }
  /// The kind of the refusal; the live database must be exactly as before.
  StoreError::Kind refusal(const std::string& backup_path, std::string* message) {
    const StoreError::Kind kind =
        storeErrorKind([&] { restoreDatabase(backup_path, *live_); }, message);
    EXPECT_NE(message->find("restore refused, '" + live_path_ + "' was not changed"),
              std::string::npos)
        << *message;
    EXPECT_EQ(recordDump(*live_), before_);
    return kind;
  }
  TempDir dir_;
  const std::string live_path_ = dir_.file("live.db");
  std::unique_ptr<SqliteConnection> live_;
  std::string before_;
};

TEST_F(RestoreRefusalTest, ForeignDatabase) {
  {
    SqliteConnection other(dir_.file("other.db"), 1000, OpenMode::kCreateReadWrite);
    other.exec("CREATE TABLE invoices (id INTEGER PRIMARY KEY); INSERT INTO invoices VALUES (1)");
  }
  std::string message;
  EXPECT_EQ(refusal(dir_.file("other.db"), &message), StoreError::Kind::kForeign);
  EXPECT_NE(message.find("another application"), std::string::npos) << message;
}

TEST_F(RestoreRefusalTest, EmptyFileAndEmptyDatabase) {
  writeFile(dir_.file("empty.db"), "");
  std::string message;
  EXPECT_EQ(refusal(dir_.file("empty.db"), &message), StoreError::Kind::kForeign);
  EXPECT_NE(message.find("is not a VICC patient database backup"), std::string::npos) << message;
}

TEST_F(RestoreRefusalTest, CorruptBackup) {
  backupDatabase(*live_, dir_.file("backup.db"));
  std::string bytes = fileBytes(dir_.file("backup.db"));
  ASSERT_GT(bytes.size(), 3 * 4096u);
  for (std::size_t i = 2 * 4096 + 8; i < 2 * 4096 + 200; ++i) bytes[i] = '\x5a';  // page 3
  writeFile(dir_.file("backup.db"), bytes);
  std::string message;
  EXPECT_EQ(refusal(dir_.file("backup.db"), &message), StoreError::Kind::kCorrupt);
}

TEST_F(RestoreRefusalTest, NotADatabaseAndMissingFile) {
  writeFile(dir_.file("notes.txt"), std::string(5000, 'n'));
  std::string message;
  EXPECT_EQ(refusal(dir_.file("notes.txt"), &message), StoreError::Kind::kCorrupt);
  EXPECT_EQ(refusal(dir_.file("missing.db"), &message), StoreError::Kind::kNotFound);
}

TEST_F(RestoreRefusalTest, NewerSchema) {
  backupDatabase(*live_, dir_.file("backup.db"));
  {
    SqliteConnection backup(dir_.file("backup.db"), 1000, OpenMode::kReadWrite);
    backup.exec("PRAGMA user_version = 99");
  }
  std::string message;
  EXPECT_EQ(refusal(dir_.file("backup.db"), &message), StoreError::Kind::kNewerSchema);
}

TEST_F(RestoreRefusalTest, LockedLiveDatabaseIsWaitedForThenReported) {
  backupDatabase(*live_, dir_.file("backup.db"));
  addPatients(*live_, 50, 1);
  before_ = recordDump(*live_);
  SqliteConnection other_writer(live_path_, 1000, OpenMode::kReadWrite);
  other_writer.exec("BEGIN IMMEDIATE");
  const auto start = std::chrono::steady_clock::now();
  std::string message;
  EXPECT_EQ(refusal(dir_.file("backup.db"), &message), StoreError::Kind::kLocked);
  EXPECT_GE(std::chrono::steady_clock::now() - start, std::chrono::milliseconds(180));
  other_writer.exec("ROLLBACK");
}

TEST(DatabaseBackupTest, RestoreRefusesTheLiveDatabaseItself) {
  TempDir dir;
  const std::string path = dir.file("p.db");
  createPatientDatabase(path, 1);
  SqliteConnection live(path, 1000, OpenMode::kReadWrite);
  std::string message;
  EXPECT_EQ(storeErrorKind([&] { restoreDatabase(path + "-wal", live); }, &message),
            StoreError::Kind::kConflict);
}

TEST(DatabaseBackupTest, RestoreOfAnOlderSchemaBackupIsMigrated) {
  TempDir dir;
  {
    SqliteConnection old(dir.file("v1.db"), 1000, OpenMode::kCreateReadWrite);
    migrateSchema(old, 1);
    old.exec("INSERT INTO patients (id, pseudonym, created_at) VALUES (1, 'SDH-001', 0)");
  }
  createPatientDatabase(dir.file("live.db"), 2);
  SqliteConnection live(dir.file("live.db"), 1000, OpenMode::kReadWrite);
  restoreDatabase(dir.file("v1.db"), live);
  EXPECT_EQ(live.queryInt("PRAGMA user_version"), latestSchemaVersion());
  EXPECT_EQ(live.queryInt("SELECT count(*) FROM patients"), 1);
  EXPECT_EQ(live.queryInt("SELECT count(*) FROM pragma_table_info('examinations') "
                          "WHERE name = 'recorded_at'"),
            1);
}

}  // namespace
}  // namespace vicc_anatomy_viz::test
