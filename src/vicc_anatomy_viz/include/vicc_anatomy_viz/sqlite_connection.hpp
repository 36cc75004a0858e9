#pragma once
// A thin RAII layer over the sqlite3 C API that turns every failure into a StoreError naming
// the database file and telling a locked database from a corrupt or unreadable one.

#include <cstdint>
#include <string>

struct sqlite3;
struct sqlite3_stmt;

namespace vicc_anatomy_viz {

class SqliteConnection;

class SqliteStatement {
 public:
  SqliteStatement(SqliteConnection& connection, const std::string& sql);
  ~SqliteStatement();
  SqliteStatement(const SqliteStatement&) = delete;
  SqliteStatement& operator=(const SqliteStatement&) = delete;
  SqliteStatement(SqliteStatement&& other) noexcept;
  SqliteStatement& operator=(SqliteStatement&&) = delete;

  SqliteStatement& bind(int index, std::int64_t value);
  SqliteStatement& bind(int index, const std::string& value);
  SqliteStatement& bindNull(int index);
  /// true while a row is available; false when done. Throws StoreError on failure.
  bool step();
  /// Ready for new bindings and a new run.
  void reset();

  std::int64_t columnInt(int column) const;
  std::string columnText(int column) const;
  bool columnIsNull(int column) const;

 private:
  SqliteConnection* connection_;
  sqlite3_stmt* statement_ = nullptr;
};

class SqliteConnection {
 public:
  enum class OpenMode {
    /// Creates a missing file first (mode 0600, missing parent directories 0700), then opens
    /// it read-write.
    kCreateReadWrite,
    /// The file must exist (else StoreError kNotFound); read-write.
    kReadWrite,
    /// The file must exist (else StoreError kNotFound, and nothing is created); writes fail.
    /// A WAL-mode database normally needs its -shm (and -wal) file, which SQLite creates in
    /// the database's directory. When that directory is not writable and no -wal or -journal
    /// holds changes, the file is opened as immutable (URI parameter immutable=1): SQLite then
    /// takes no locks and assumes nobody changes the file while it is open, so a writer that
    /// appears later (through another mount or user) is not seen. With changes pending in a
    /// -wal or -journal file that cannot be read that way, the open is refused (StoreError
    /// kIo) instead of answering from stale data.
    kReadOnly,
  };

  /// Opens `path` as `mode` says; waits up to `busy_timeout_ms` on locks.
  SqliteConnection(const std::string& path, int busy_timeout_ms, OpenMode mode);
  /// OpenMode::kCreateReadWrite when `create`, else OpenMode::kReadWrite.
  SqliteConnection(const std::string& path, int busy_timeout_ms, bool create);
  ~SqliteConnection();
  SqliteConnection(const SqliteConnection&) = delete;
  SqliteConnection& operator=(const SqliteConnection&) = delete;

  /// Runs one or more statements without results.
  void exec(const std::string& sql);
  /// Single integer result of a query such as "PRAGMA user_version".
  std::int64_t queryInt(const std::string& sql);
  std::int64_t lastInsertRowid() const;
  const std::string& path() const { return path_; }
  int busyTimeoutMs() const { return busy_timeout_ms_; }
  bool readOnly() const { return mode_ == OpenMode::kReadOnly; }
  /// true when a read-only connection fell back to immutable=1 (see OpenMode::kReadOnly).
  bool immutable() const { return immutable_; }
  sqlite3* handle() { return db_; }

  /// Throws the StoreError matching an sqlite result code.
  [[noreturn]] void fail(int result_code, const std::string& doing) const;

 private:
  /// sqlite3_open_v2 of `filename` (the path or a URI); StoreError when that fails.
  void openHandle(const std::string& filename, int flags);
  void openReadOnly();

  std::string path_;
  int busy_timeout_ms_;
  OpenMode mode_;
  bool immutable_ = false;
  sqlite3* db_ = nullptr;
};

/// BEGIN ... COMMIT; rolls back when destroyed uncommitted (an exception). A write
/// transaction (BEGIN IMMEDIATE) takes the write lock up front, so a busy database is detected
/// before anything is written; a read transaction gives a consistent snapshot.
class SqliteTransaction {
 public:
  enum class Mode { kWrite, kRead };
  explicit SqliteTransaction(SqliteConnection& connection, Mode mode = Mode::kWrite);
  ~SqliteTransaction();
  SqliteTransaction(const SqliteTransaction&) = delete;
  SqliteTransaction& operator=(const SqliteTransaction&) = delete;
  void commit();

 private:
  SqliteConnection& connection_;
  bool open_ = true;
};

}  // namespace vicc_anatomy_viz
