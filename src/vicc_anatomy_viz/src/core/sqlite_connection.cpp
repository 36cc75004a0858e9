#include "vicc_anatomy_viz/sqlite_connection.hpp"

#include <sqlite3.h>

#include <filesystem>

#include "vicc_anatomy_viz/database_files.hpp"
#include "vicc_anatomy_viz/errors.hpp"

namespace vicc_anatomy_viz {

namespace {

StoreError::Kind kindOf(int result_code) {
  switch (result_code & 0xff) {
    case SQLITE_BUSY:
    case SQLITE_LOCKED:
      return StoreError::Kind::kLocked;
    case SQLITE_CORRUPT:
    case SQLITE_NOTADB:
      return StoreError::Kind::kCorrupt;
    case SQLITE_CANTOPEN:
    case SQLITE_IOERR:
    case SQLITE_READONLY:
    case SQLITE_FULL:
    case SQLITE_PERM:
      return StoreError::Kind::kIo;
    case SQLITE_CONSTRAINT:
      return StoreError::Kind::kConflict;
    default:
      return StoreError::Kind::kOther;
  }
}

/// `file:` URI of a path with immutable=1; characters with a meaning in URIs are escaped.
std::string immutableUri(const std::string& path) {
  const std::string absolute = std::filesystem::absolute(path).string();
  std::string uri = "file://";
  for (const unsigned char c : absolute) {
    if (c == '%' || c == '?' || c == '#' || c < 0x21 || c > 0x7e) {
      static const char kHex[] = "0123456789abcdef";
      uri += '%';
      uri += kHex[c >> 4];
      uri += kHex[c & 0xf];
    } else {
      uri += static_cast<char>(c);
    }
  }
  return uri + "?immutable=1";
}

/// true when a -wal or -journal file next to the database is not empty.
bool hasPendingChanges(const std::string& path) {
  for (const char* suffix : {"-wal", "-journal"}) {
    std::error_code error;
    const auto size = std::filesystem::file_size(path + suffix, error);
    if (error == std::errc::no_such_file_or_directory) continue;
    // A file that cannot even be measured may hold changes too.
    if (error || size > 0) return true;
  }
  return false;
}

}  // namespace

SqliteConnection::SqliteConnection(const std::string& path, int busy_timeout_ms, OpenMode mode)
    : path_(path), busy_timeout_ms_(busy_timeout_ms), mode_(mode) {
  if (mode == OpenMode::kCreateReadWrite) {
    // We create the file so that it is private from the start; SQLite would use 0644.
    createPrivateDatabaseFile(path);
  } else if (std::error_code ignored; !std::filesystem::exists(path, ignored)) {
    throw StoreError(StoreError::Kind::kNotFound, "patient database '" + path + "' does not exist");
  }
  if (mode != OpenMode::kReadOnly) {
    openHandle(path, SQLITE_OPEN_READWRITE);
    return;
  }
  try {
    openReadOnly();
  } catch (...) {
    // The destructor does not run for a throwing constructor.
    sqlite3_close_v2(db_);
    db_ = nullptr;
    throw;
  }
}

SqliteConnection::SqliteConnection(const std::string& path, int busy_timeout_ms, bool create)
    : SqliteConnection(path, busy_timeout_ms,
                       create ? OpenMode::kCreateReadWrite : OpenMode::kReadWrite) {}

void SqliteConnection::openHandle(const std::string& filename, int flags) {
  const int rc = sqlite3_open_v2(filename.c_str(), &db_, flags | SQLITE_OPEN_NOMUTEX, nullptr);
  if (rc != SQLITE_OK) {
    const std::string detail = db_ ? sqlite3_errmsg(db_) : sqlite3_errstr(rc);
    sqlite3_close(db_);
    db_ = nullptr;
    throw StoreError(kindOf(rc), "cannot open patient database '" + path_ + "': " + detail);
  }
  sqlite3_extended_result_codes(db_, 1);
  // The busy handler retries a locked database until the timeout (another writer, or a
  // checkpoint in progress) instead of failing at once.
  sqlite3_busy_timeout(db_, busy_timeout_ms_);
}

void SqliteConnection::openReadOnly() {
  openHandle(path_, SQLITE_OPEN_READONLY);
  // SQLite opens the -wal and -shm files at the first read, so only a read shows whether
  // they can be used here.
  const int rc = sqlite3_exec(db_, "SELECT count(*) FROM sqlite_master", nullptr, nullptr, nullptr);
  if (rc == SQLITE_OK) return;
  const int primary = rc & 0xff;
  if (primary != SQLITE_CANTOPEN && primary != SQLITE_READONLY) fail(rc, "reading the schema");
  if (hasPendingChanges(path_)) {
    // immutable=1 would ignore those changes and show an outdated record.
    throw StoreError(StoreError::Kind::kIo,
                     "patient database '" + path_ +
                         "' cannot be read here: its -wal or -journal file holds changes not yet "
                         "in the database file, and SQLite cannot create the -shm file it needs "
                         "to read them (the directory is not writable); open it once with write "
                         "access, or copy the database with its -wal file to a writable place");
  }
  sqlite3_close_v2(db_);
  db_ = nullptr;
  openHandle(immutableUri(path_), SQLITE_OPEN_READONLY | SQLITE_OPEN_URI);
  immutable_ = true;
}

SqliteConnection::~SqliteConnection() { sqlite3_close_v2(db_); }

void SqliteConnection::fail(int result_code, const std::string& doing) const {
  const StoreError::Kind kind = kindOf(result_code);
  std::string message = "patient database '" + path_ + "': ";
  switch (kind) {
    case StoreError::Kind::kLocked:
      message += "locked by another process; gave up " + doing + " after waiting " +
                 std::to_string(busy_timeout_ms_) + " ms";
      break;
    case StoreError::Kind::kCorrupt:
      message += (result_code & 0xff) == SQLITE_NOTADB
                     ? "the file is not an SQLite database (or it is encrypted) while " + doing
                     : "the database file is corrupt (" + std::string(sqlite3_errmsg(db_)) +
                           ") while " + doing + "; restore it from a backup";
      break;
    default:
      message += std::string(sqlite3_errmsg(db_)) + " while " + doing;
      break;
  }
  throw StoreError(kind, message);
}

void SqliteConnection::exec(const std::string& sql) {
  char* error = nullptr;
  const int rc = sqlite3_exec(db_, sql.c_str(), nullptr, nullptr, &error);
  sqlite3_free(error);
  if (rc != SQLITE_OK) fail(rc, "running \"" + sql.substr(0, 60) + "\"");
}

std::int64_t SqliteConnection::queryInt(const std::string& sql) {
  SqliteStatement statement(*this, sql);
  if (!statement.step()) return 0;
  return statement.columnInt(0);
}

std::int64_t SqliteConnection::lastInsertRowid() const { return sqlite3_last_insert_rowid(db_); }

SqliteStatement::SqliteStatement(SqliteConnection& connection, const std::string& sql)
    : connection_(&connection) {
  const int rc = sqlite3_prepare_v2(connection.handle(), sql.c_str(), static_cast<int>(sql.size()),
                                    &statement_, nullptr);
  if (rc != SQLITE_OK) connection.fail(rc, "preparing \"" + sql.substr(0, 60) + "\"");
}

SqliteStatement::~SqliteStatement() { sqlite3_finalize(statement_); }

SqliteStatement::SqliteStatement(SqliteStatement&& other) noexcept
    : connection_(other.connection_), statement_(other.statement_) {
  other.statement_ = nullptr;
}

SqliteStatement& SqliteStatement::bind(int index, std::int64_t value) {
  const int rc = sqlite3_bind_int64(statement_, index, value);
  if (rc != SQLITE_OK) connection_->fail(rc, "binding a value");
  return *this;
}

SqliteStatement& SqliteStatement::bind(int index, const std::string& value) {
  const int rc = sqlite3_bind_text(statement_, index, value.c_str(), static_cast<int>(value.size()),
                                   SQLITE_TRANSIENT);
  if (rc != SQLITE_OK) connection_->fail(rc, "binding a value");
  return *this;
}

SqliteStatement& SqliteStatement::bindNull(int index) {
  const int rc = sqlite3_bind_null(statement_, index);
  if (rc != SQLITE_OK) connection_->fail(rc, "binding a value");
  return *this;
}

bool SqliteStatement::step() {
  const int rc = sqlite3_step(statement_);
  if (rc == SQLITE_ROW) return true;
  if (rc == SQLITE_DONE) return false;
  const std::string sql = sqlite3_sql(statement_) ? sqlite3_sql(statement_) : "";
  sqlite3_reset(statement_);
  connection_->fail(rc, "running \"" + sql.substr(0, 60) + "\"");
}

void SqliteStatement::reset() {
  sqlite3_reset(statement_);
  sqlite3_clear_bindings(statement_);
}

std::int64_t SqliteStatement::columnInt(int column) const {
  return sqlite3_column_int64(statement_, column);
}

std::string SqliteStatement::columnText(int column) const {
  const unsigned char* text = sqlite3_column_text(statement_, column);
  return text ? reinterpret_cast<const char*>(text) : "";
}

bool SqliteStatement::columnIsNull(int column) const {
  return sqlite3_column_type(statement_, column) == SQLITE_NULL;
}

SqliteTransaction::SqliteTransaction(SqliteConnection& connection, Mode mode)
    : connection_(connection) {
  connection_.exec(mode == Mode::kWrite ? "BEGIN IMMEDIATE" : "BEGIN");
}

SqliteTransaction::~SqliteTransaction() {
  if (!open_) return;
  // Never throw from a destructor: a failed rollback leaves SQLite to roll back on close.
  sqlite3_exec(connection_.handle(), "ROLLBACK", nullptr, nullptr, nullptr);
}

void SqliteTransaction::commit() {
  connection_.exec("COMMIT");
  open_ = false;
}

}  // namespace vicc_anatomy_viz
