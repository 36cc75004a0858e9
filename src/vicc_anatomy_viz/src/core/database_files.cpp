#include "vicc_anatomy_viz/database_files.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include "vicc_anatomy_viz/errors.hpp"

namespace vicc_anatomy_viz {

namespace fs = std::filesystem;

namespace {

/// The files SQLite may keep with a database: the database itself and its companions.
constexpr const char* kDatabaseFileSuffixes[] = {"", "-wal", "-shm", "-journal"};

void createPrivateDirectories(const fs::path& directory) {
  std::error_code ignored;
  if (directory.empty() || fs::exists(directory, ignored)) return;  // existing: left alone
  createPrivateDirectories(directory.parent_path());
  if (::mkdir(directory.c_str(), 0700) != 0) {
    const int error = errno;
    if (error == EEXIST) return;  // created by someone else meanwhile
    throw StoreError(StoreError::Kind::kIo,
                     "cannot create directory '" + directory.string() +
                         "' for the patient database: " + std::strerror(error));
  }
  // The umask may have taken away bits that we need.
  ::chmod(directory.c_str(), 0700);
}

void warnIfShared(const fs::path& path, const char* private_mode,
                  std::vector<std::string>& warnings) {
  std::error_code error;
  const fs::file_status status = fs::status(path, error);
  if (error || !fs::exists(status)) return;
  const fs::perms shared = status.permissions() & (fs::perms::group_all | fs::perms::others_all);
  if (shared == fs::perms::none) return;
  char mode[8];
  std::snprintf(mode, sizeof(mode), "%04o",
                static_cast<unsigned>(status.permissions() & fs::perms::mask));
  warnings.push_back("'" + path.string() + "' is accessible to group or others (mode " + mode +
                     "), but patient data must be private; fix: chmod " + private_mode + " '" +
                     path.string() + "'");
}

/// The absolute, normalized path, with symbolic links followed also where their target does not
/// exist yet (weakly_canonical stops at the first missing component).
fs::path resolvedPath(const fs::path& path) {
  std::error_code error;
  fs::path current = fs::absolute(path, error);
  if (error) return path.lexically_normal();
  constexpr int kMaxLinks = 40;  // as the kernel's ELOOP limit
  for (int links = 0; links < kMaxLinks && fs::is_symlink(fs::symlink_status(current, error));
       ++links) {
    const fs::path target = fs::read_symlink(current, error);
    if (error) break;
    current = target.is_absolute() ? target : current.parent_path() / target;
  }
  const fs::path canonical = fs::weakly_canonical(current, error);
  return error ? current.lexically_normal() : canonical;
}

}  // namespace

bool createPrivateDatabaseFile(const std::string& db_path) {
  createPrivateDirectories(fs::path(db_path).parent_path());
  const int fd = ::open(db_path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
  if (fd < 0) {
    const int error = errno;
    if (error == EEXIST) return false;
    throw StoreError(StoreError::Kind::kIo,
                     "cannot create patient database '" + db_path + "': " + std::strerror(error));
  }
  // The umask may have taken away bits that we need.
  const bool private_mode = ::fchmod(fd, 0600) == 0;
  ::close(fd);
  if (!private_mode) {
    throw StoreError(StoreError::Kind::kIo,
                     "cannot make patient database '" + db_path + "' private (mode 0600)");
  }
  return true;
}

std::vector<std::string> permissionWarnings(const std::string& db_path) {
  std::vector<std::string> warnings;
  for (const char* suffix : kDatabaseFileSuffixes) warnIfShared(db_path + suffix, "600", warnings);
  const fs::path directory = fs::path(db_path).parent_path();
  warnIfShared(directory.empty() ? fs::path(".") : directory, "700", warnings);
  return warnings;
}

bool isDatabaseOrCompanion(const std::string& candidate, const std::string& db_path) {
  const fs::path resolved_candidate = resolvedPath(candidate);
  // SQLite puts the companions next to the file a symbolic link points to; match both places.
  for (const std::string& database : {db_path, resolvedPath(db_path).string()}) {
    for (const char* suffix : kDatabaseFileSuffixes) {
      const std::string file = database + suffix;
      std::error_code error;
      if (fs::equivalent(candidate, file, error)) return true;  // also hard links
      if (resolved_candidate == resolvedPath(file)) return true;
    }
  }
  return false;
}

}  // namespace vicc_anatomy_viz
