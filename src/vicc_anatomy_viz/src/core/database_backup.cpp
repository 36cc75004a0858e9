// Online backup and restore of a patient database with SQLite's backup API.
#include <sqlite3.h>

#include <filesystem>

#include "vicc_anatomy_viz/database_files.hpp"
#include "vicc_anatomy_viz/errors.hpp"
#include "vicc_anatomy_viz/schema_migrations.hpp"

namespace vicc_anatomy_viz {

namespace {

/// Copies all pages of `from` into `to` in one step: one read transaction on `from` (a
/// consistent snapshot under WAL) and one write transaction on `to`, whose busy handler waits
/// for the write lock.
void copyDatabase(SqliteConnection& from, SqliteConnection& to, const std::string& doing) {
  sqlite3_backup* backup = sqlite3_backup_init(to.handle(), "main", from.handle(), "main");
  if (!backup) to.fail(sqlite3_extended_errcode(to.handle()), doing);
  const int step_rc = sqlite3_backup_step(backup, -1);
  // finish reports the errors of step except busy and locked, and releases both locks.
  const int finish_rc = sqlite3_backup_finish(backup);
  const int rc = step_rc == SQLITE_DONE ? finish_rc : step_rc;
  if (rc != SQLITE_OK && rc != SQLITE_DONE) to.fail(rc, doing);
}

/// Throws StoreError kCorrupt unless PRAGMA integrity_check answers "ok".
void requireIntegrity(SqliteConnection& connection, const std::string& what) {
  SqliteStatement check(connection, "PRAGMA integrity_check");
  std::string result;
  std::size_t problems = 0;
  while (check.step()) {
    result = check.columnText(0);
    ++problems;
  }
  if (problems == 1 && result == "ok") return;
  // The problems name pages and tables, never recorded values.
  throw StoreError(StoreError::Kind::kCorrupt, what + " failed the integrity check (" +
                                                   std::to_string(problems) +
                                                   " problem(s), first: " + result + ")");
}

/// A sound VICC patient database of a schema this program knows, else StoreError.
void requirePatientDatabase(SqliteConnection& backup) {
  checkDatabaseIdentity(backup);
  // checkDatabaseIdentity accepts an empty file as a database still to be set up; restoring
  // one would erase every record.
  if (backup.queryInt("PRAGMA application_id") != kApplicationId) {
    throw StoreError(StoreError::Kind::kForeign,
                     "'" + backup.path() +
                         "' is not a VICC patient database backup (no VICC application id; it "
                         "is empty or was never set up by this program)");
  }
  requireIntegrity(backup, "backup '" + backup.path() + "'");
}

void removeDatabaseFiles(const std::string& path) {
  std::error_code ignored;
  for (const char* suffix : {"", "-wal", "-shm", "-journal"}) {
    std::filesystem::remove(path + suffix, ignored);
  }
}

}  // namespace

void backupDatabase(SqliteConnection& source, const std::string& out_path) {
  if (isDatabaseOrCompanion(out_path, source.path())) {
    throw StoreError(StoreError::Kind::kConflict,
                     "backup file '" + out_path + "' is the patient database '" + source.path() +
                         "' or one of its -wal, -shm or -journal files; choose another file");
  }
  std::error_code ignored;
  const bool exists = std::filesystem::exists(std::filesystem::symlink_status(out_path, ignored));
  if (exists || !createPrivateDatabaseFile(out_path)) {
    throw StoreError(StoreError::Kind::kConflict,
                     "backup file '" + out_path +
                         "' exists already; a backup never overwrites a file, choose a new name");
  }
  try {
    SqliteConnection copy(out_path, source.busyTimeoutMs(), SqliteConnection::OpenMode::kReadWrite);
    copyDatabase(source, copy, "writing the backup '" + out_path + "'");
    // One self-contained file that also reads from read-only media without a -shm file.
    copy.exec("PRAGMA journal_mode = DELETE");
    requireIntegrity(copy, "backup '" + out_path + "'");
  } catch (...) {
    removeDatabaseFiles(out_path);  // we created it: no partial backup is left behind
    throw;
  }
}

void restoreDatabase(const std::string& backup_path, SqliteConnection& live) {
  if (isDatabaseOrCompanion(backup_path, live.path())) {
    throw StoreError(StoreError::Kind::kConflict, "cannot restore '" + backup_path +
                                                      "': it is the live patient database '" +
                                                      live.path() + "' or one of its files");
  }
  try {
    SqliteConnection backup(backup_path, live.busyTimeoutMs(),
                            SqliteConnection::OpenMode::kReadOnly);
    requirePatientDatabase(backup);
    copyDatabase(backup, live, "restoring from '" + backup_path + "'");
  } catch (const StoreError& error) {
    throw StoreError(error.kind(), std::string(error.what()) + "; restore refused, '" +
                                       live.path() + "' was not changed");
  }
  // A backup written by an older version of this program gets the current schema.
  migrateSchema(live);
}

}  // namespace vicc_anatomy_viz
