#pragma once
// Fixtures of the SQLite file-layer tests: small VICC patient databases, an exact dump of their
// records, file modes, and a child process in which a directory cannot be written.

#include <fcntl.h>
#include <sched.h>
#include <sys/mount.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstring>
#include <filesystem>
#include <functional>
#include <string>

#include "test_support.hpp"
#include "vicc_anatomy_viz/errors.hpp"
#include "vicc_anatomy_viz/schema_migrations.hpp"
#include "vicc_anatomy_viz/sqlite_connection.hpp"

namespace vicc_anatomy_viz::test {

using OpenMode = SqliteConnection::OpenMode;

/// Patients `first` .. `first + count - 1`, each with two examinations with one finding, in one
/// transaction. `padding` lengthens the pseudonyms to make the database larger.
inline void addPatients(SqliteConnection& connection, int first, int count,
                        std::size_t padding = 0) {
  SqliteTransaction transaction(connection);
  SqliteStatement patient(connection, "INSERT INTO patients (pseudonym, created_at) VALUES (?, ?)");
  SqliteStatement examination(connection,
                              "INSERT INTO examinations (patient_id, taken_at, view_id, source) "
                              "VALUES (?, ?, 'neurological_status_sdh', 'json')");
  SqliteStatement finding(connection,
                          "INSERT INTO findings (examination_id, category, structure, side) "
                          "VALUES (?, 'radicular_pain', 'dermatome_L5', 'left')");
  SqliteStatement value(connection,
                        "INSERT INTO finding_values (finding_id, prop_type, int_value) "
                        "VALUES (?, 'intensity', ?)");
  for (int i = first; i < first + count; ++i) {
    patient.bind(1, "SDH-" + std::to_string(i) + std::string(padding, 'x')).bind(2, i);
    patient.step();
    patient.reset();
    const std::int64_t patient_row = connection.lastInsertRowid();
    for (int day = 0; day < 2; ++day) {
      examination.bind(1, patient_row).bind(2, 1678094100 + 86400 * day);
      examination.step();
      examination.reset();
      finding.bind(1, connection.lastInsertRowid());
      finding.step();
      finding.reset();
      value.bind(1, connection.lastInsertRowid()).bind(2, (i + day) % 11);
      value.step();
      value.reset();
    }
  }
  transaction.commit();
}

/// A VICC patient database in WAL mode with `patients` patients, closed again.
inline void createPatientDatabase(const std::string& path, int patients) {
  SqliteConnection connection(path, 1000, OpenMode::kCreateReadWrite);
  connection.exec("PRAGMA journal_mode = WAL");
  migrateSchema(connection);
  addPatients(connection, 0, patients);
}

/// Every stored record in a fixed order, to compare two databases exactly.
inline std::string recordDump(SqliteConnection& connection) {
  SqliteStatement dump(
      connection,
      "SELECT (SELECT group_concat(r, ';') FROM (SELECT id || ',' || pseudonym || ',' || "
      "created_at AS r FROM patients ORDER BY id)) || '|' || "
      "(SELECT group_concat(r, ';') FROM (SELECT id || ',' || patient_id || ',' || taken_at || ',' "
      "|| view_id || ',' || source || ',' || recorded_at AS r FROM examinations ORDER BY id)) || "
      "'|' || (SELECT group_concat(r, ';') FROM (SELECT id || ',' || examination_id || ',' || "
      "category || ',' || structure || ',' || side AS r FROM findings ORDER BY id)) || '|' || "
      "(SELECT group_concat(r, ';') FROM (SELECT finding_id || ',' || prop_type || ',' || "
      "quote(int_value) || ',' || quote(text_value) AS r FROM finding_values "
      "ORDER BY finding_id, prop_type))");
  return dump.step() ? dump.columnText(0) : "";
}

inline unsigned fileMode(const std::string& path) {
  struct stat status {};
  if (::stat(path.c_str(), &status) != 0) return 0;
  return status.st_mode & 07777;
}

inline bool pathExists(const std::string& path) {
  std::error_code ignored;
  return std::filesystem::exists(std::filesystem::symlink_status(path, ignored));
}

/// Sets the umask for the lifetime of the object.
class ScopedUmask {
 public:
  explicit ScopedUmask(mode_t mask) : previous_(::umask(mask)) {}
  ~ScopedUmask() { ::umask(previous_); }
  ScopedUmask(const ScopedUmask&) = delete;
  ScopedUmask& operator=(const ScopedUmask&) = delete;

 private:
  mode_t previous_;
};

struct ChildResult {
  enum class State { kRan, kNotArranged, kFailed };
  State state = State::kFailed;  ///< kNotArranged: the directory could not be made unwritable
  std::string output;            ///< what the probe returned, or why it could not run
};

namespace detail {

/// Makes `directory` unwritable for this (child) process; an empty string on success.
/// Root ignores file modes, so as root only a read-only bind mount in a private mount
/// namespace stops writes; other users get chmod.
inline std::string makeUnwritable(const std::string& directory) {
  if (::geteuid() == 0) {
    if (::unshare(CLONE_NEWNS) != 0) return std::string("unshare: ") + std::strerror(errno);
    if (::mount(nullptr, "/", nullptr, MS_REC | MS_PRIVATE, nullptr) != 0 ||
        ::mount(directory.c_str(), directory.c_str(), nullptr, MS_BIND, nullptr) != 0 ||
        ::mount(nullptr, directory.c_str(), nullptr, MS_BIND | MS_REMOUNT | MS_RDONLY, nullptr) !=
            0) {
      return std::string("read-only bind mount: ") + std::strerror(errno);
    }
  } else if (::chmod(directory.c_str(), 0555) != 0) {
    return std::string("chmod: ") + std::strerror(errno);
  }
  const std::string probe = directory + "/.write_probe";
  const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL, 0600);
  if (fd >= 0) {
    ::close(fd);
    ::unlink(probe.c_str());
    return "files can still be created in the directory";
  }
  return "";
}

inline std::string readAll(int fd) {
  std::string text;
  char buffer[512];
  for (ssize_t n; (n = ::read(fd, buffer, sizeof(buffer))) > 0;) text.append(buffer, n);
  return text;
}

}  // namespace detail

/// Runs `probe` in a child process that cannot write `directory`; its answer comes back through
/// a pipe (exceptions as "StoreError <kind number>: <message>").
inline ChildResult inUnwritableDirectory(const std::string& directory,
                                         const std::function<std::string()>& probe) {
  int pipe_fds[2];
  if (::pipe(pipe_fds) != 0) return {ChildResult::State::kFailed, "pipe failed"};
  const pid_t child = ::fork();
  if (child == 0) {
    ::close(pipe_fds[0]);
    std::string answer = detail::makeUnwritable(directory);
    int status = answer.empty() ? 0 : 3;
    if (status == 0) {
      try {
        answer = probe();
      } catch (const StoreError& e) {
        answer = "StoreError " + std::to_string(static_cast<int>(e.kind())) + ": " + e.what();
      } catch (const std::exception& e) {
        answer = std::string("exception: ") + e.what();
      }
    }
    const ssize_t written = ::write(pipe_fds[1], answer.data(), answer.size());
    ::_exit(written == static_cast<ssize_t>(answer.size()) ? status : 4);
  }
  ::close(pipe_fds[1]);
  ChildResult result;
  result.output = detail::readAll(pipe_fds[0]);
  ::close(pipe_fds[0]);
  int status = 0;
  ::waitpid(child, &status, 0);
  ::chmod(directory.c_str(), 0700);  // undoes the chmod of a non-root run
  const int code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  result.state = code == 0   ? ChildResult::State::kRan
                 : code == 3 ? ChildResult::State::kNotArranged
                             : ChildResult::State::kFailed;
  return result;
}

/// A child process that adds `patients` patients to the database without checkpointing and
/// keeps its connection open (so the -wal and -shm files stay) until the object is destroyed.
/// A process of its own, because SQLite connections must not be carried across fork().
class WalWriterProcess {
 public:
  WalWriterProcess(const std::string& path, int patients) {
    int ready[2];
    if (::pipe(ready) != 0 || ::pipe(release_) != 0) throw std::runtime_error("pipe failed");
    pid_ = ::fork();
    if (pid_ == 0) {
      char byte = 'r';
      {
        SqliteConnection writer(path, 1000, OpenMode::kReadWrite);
        writer.exec("PRAGMA wal_autocheckpoint = 0");
        addPatients(writer, 1000, patients);
        if (::write(ready[1], &byte, 1) != 1 || ::read(release_[0], &byte, 1) != 1) ::_exit(4);
      }
      ::_exit(0);
    }
    char byte = 0;
    ready_ = ::read(ready[0], &byte, 1) == 1;
    ::close(ready[0]);
    ::close(ready[1]);
  }
  ~WalWriterProcess() {
    const char byte = 'x';
    if (::write(release_[1], &byte, 1) != 1) ::kill(pid_, SIGKILL);
    ::waitpid(pid_, nullptr, 0);
    ::close(release_[0]);
    ::close(release_[1]);
  }
  WalWriterProcess(const WalWriterProcess&) = delete;
  WalWriterProcess& operator=(const WalWriterProcess&) = delete;
  bool ready() const { return ready_; }

 private:
  pid_t pid_ = -1;
  int release_[2] = {-1, -1};
  bool ready_ = false;
};

}  // namespace vicc_anatomy_viz::test
