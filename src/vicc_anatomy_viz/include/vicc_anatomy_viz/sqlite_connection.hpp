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
  /// Opens (and with `create` creates) the file; waits up to `busy_timeout_ms` on locks.
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
  sqlite3* handle() { return db_; }

  /// Throws the StoreError matching an sqlite result code.
  [[noreturn]] void fail(int result_code, const std::string& doing) const;

 private:
  std::string path_;
  int busy_timeout_ms_;
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
