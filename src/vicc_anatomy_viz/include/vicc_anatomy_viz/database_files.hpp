#pragma once
// The files of a patient database on disk: private permissions, the companion files SQLite
// keeps next to it (-wal, -shm, -journal), and online backup and restore.

#include <string>
#include <vector>

#include "vicc_anatomy_viz/sqlite_connection.hpp"

namespace vicc_anatomy_viz {

/// Creates `db_path` empty with mode 0600 unless it exists, and the missing parent
/// directories with mode 0700; existing files and directories are left as they are.
/// Returns false when `db_path` existed (also as a dangling symbolic link); StoreError kIo
/// when it cannot be created.
bool createPrivateDatabaseFile(const std::string& db_path);

/// One warning for each existing database, -wal, -shm or -journal file, and for the containing
/// directory, that group or others may access: the path, its mode and the chmod that fixes it.
std::vector<std::string> permissionWarnings(const std::string& db_path);

/// true when `candidate` names the database file or its -wal, -shm or -journal file, also
/// through symbolic links, relative paths, ".." and hard links. Use it before writing an output
/// file, so that an export never overwrites the database.
bool isDatabaseOrCompanion(const std::string& candidate, const std::string& db_path);

/// Copies the database of `source` into the new file `out_path` (mode 0600) with SQLite's
/// online backup: a consistent snapshot even while other connections write. Refuses an existing
/// `out_path` and the database's own files (StoreError kConflict); checks the copy with
/// PRAGMA integrity_check and removes it when that fails (StoreError kCorrupt).
void backupDatabase(SqliteConnection& source, const std::string& out_path);

/// Replaces the content of `live` by the backup in `backup_path`, in one transaction (it waits
/// for the write lock up to the busy timeout of `live`, else StoreError kLocked). The backup
/// must pass PRAGMA integrity_check and be a VICC patient database whose schema this program
/// knows, else StoreError (kNotFound, kCorrupt, kForeign, kNewerSchema) and `live` is not
/// touched. A backup of an older schema version is migrated after the copy.
void restoreDatabase(const std::string& backup_path, SqliteConnection& live);

}  // namespace vicc_anatomy_viz
