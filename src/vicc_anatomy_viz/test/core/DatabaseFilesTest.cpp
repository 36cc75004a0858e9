// Private permissions of the database files and recognition of the database's own files.
#include "vicc_anatomy_viz/database_files.hpp"

#include <unistd.h>

#include <filesystem>

#include <gtest/gtest.h>

#include "database_test_support.hpp"

namespace vicc_anatomy_viz::test {
namespace {

namespace fs = std::filesystem;

TEST(DatabaseFilesTest, CreatedDatabaseAndDirectoriesArePrivateEvenWithAPermissiveUmask) {
  TempDir dir;
  const std::string shared = dir.file("shared");
  fs::create_directory(shared);
  fs::permissions(shared, fs::perms(0755));
  const ScopedUmask permissive(0);
  const std::string path = shared + "/vicc/2024/p.db";
  { SqliteConnection connection(path, 1000, OpenMode::kCreateReadWrite); }
  EXPECT_EQ(fileMode(path), 0600u);
  EXPECT_EQ(fileMode(shared + "/vicc/2024"), 0700u);
  EXPECT_EQ(fileMode(shared + "/vicc"), 0700u);
  EXPECT_EQ(fileMode(shared), 0755u);  // existing directories are left alone
}

TEST(DatabaseFilesTest, ExistingFileIsNeitherRecreatedNorChmodded) {
  TempDir dir;
  const std::string path = dir.file("p.db");
  writeFile(path, "");
  fs::permissions(path, fs::perms(0640));
  EXPECT_FALSE(createPrivateDatabaseFile(path));
  EXPECT_EQ(fileMode(path), 0640u);
  EXPECT_TRUE(createPrivateDatabaseFile(dir.file("q.db")));
}

TEST(DatabaseFilesTest, WalAndShmFilesAreAsPrivateAsTheDatabase) {
  TempDir dir;
  const std::string path = dir.file("p.db");
  const ScopedUmask permissive(0);
  SqliteConnection connection(path, 1000, OpenMode::kCreateReadWrite);
  connection.exec("PRAGMA journal_mode = WAL");
  migrateSchema(connection);
  addPatients(connection, 0, 2);
  ASSERT_TRUE(pathExists(path + "-wal"));
  ASSERT_TRUE(pathExists(path + "-shm"));
  // SQLite gives its companion files the mode of the database file.
  EXPECT_EQ(fileMode(path + "-wal"), 0600u);
  EXPECT_EQ(fileMode(path + "-shm"), 0600u);
  EXPECT_TRUE(permissionWarnings(path).empty());
}

TEST(DatabaseFilesTest, PermissionWarningsNameEachSharedFileItsModeAndTheFix) {
  TempDir dir;
  const std::string directory = dir.file("store");
  const std::string path = directory + "/p.db";
  createPatientDatabase(path, 1);
  writeFile(path + "-wal", "");
  fs::permissions(path, fs::perms(0644));
  fs::permissions(path + "-wal", fs::perms(0660));
  fs::permissions(directory, fs::perms(0755));
  const std::vector<std::string> warnings = permissionWarnings(path);
  ASSERT_EQ(warnings.size(), 3u);
  EXPECT_EQ(warnings[0], "'" + path +
                             "' is accessible to group or others (mode 0644), but patient data "
                             "must be private; fix: chmod 600 '" +
                             path + "'");
  EXPECT_NE(warnings[1].find("'" + path + "-wal' is accessible"), std::string::npos);
  EXPECT_NE(warnings[1].find("(mode 0660)"), std::string::npos);
  EXPECT_NE(warnings[2].find("(mode 0755)"), std::string::npos);
  EXPECT_NE(warnings[2].find("fix: chmod 700 '" + directory + "'"), std::string::npos);
}

TEST(DatabaseFilesTest, NoPermissionWarningsForPrivateOrMissingFiles) {
  TempDir dir;
  const std::string path = dir.file("p.db");
  EXPECT_TRUE(permissionWarnings(path).empty());  // nothing exists but the 0700 directory
  createPatientDatabase(path, 1);
  EXPECT_TRUE(permissionWarnings(path).empty());
}

class CompanionPathTest : public ::testing::Test {
 protected:
  void SetUp() override {
    fs::create_directory(dir_.file("data"));
    createPatientDatabase(db_, 1);
  }
  TempDir dir_;
  const std::string db_ = dir_.file("data/p.db");
};

TEST_F(CompanionPathTest, TheDatabaseAndItsCompanionsByTheirNames) {
  for (const char* suffix : {"", "-wal", "-shm", "-journal"}) {
    EXPECT_TRUE(isDatabaseOrCompanion(db_ + suffix, db_)) << suffix;
  }
  for (const char* other : {".bak", "-walx", "-wal.json", ".json"}) {
    EXPECT_FALSE(isDatabaseOrCompanion(db_ + other, db_)) << other;
  }
  EXPECT_FALSE(isDatabaseOrCompanion(dir_.file("p.db"), db_));
}

TEST_F(CompanionPathTest, RelativePathsAndDotDot) {
  EXPECT_TRUE(isDatabaseOrCompanion(dir_.file("data/../data/./p.db-wal"), db_));
  const std::string relative = fs::relative(db_, fs::current_path()).string();
  EXPECT_TRUE(isDatabaseOrCompanion(relative, db_)) << relative;
  EXPECT_TRUE(isDatabaseOrCompanion(db_ + "-shm", relative));
  EXPECT_FALSE(isDatabaseOrCompanion(dir_.file("data/../p.db"), db_));
}

TEST_F(CompanionPathTest, SymbolicLinksAlsoToFilesThatDoNotExistYet) {
  fs::create_symlink(db_, dir_.file("link.db"));
  fs::create_symlink("data/p.db-wal", dir_.file("dangling_wal"));  // no -wal while closed
  fs::create_directory_symlink(dir_.file("data"), dir_.file("data_link"));
  EXPECT_TRUE(isDatabaseOrCompanion(dir_.file("link.db"), db_));
  EXPECT_TRUE(isDatabaseOrCompanion(dir_.file("dangling_wal"), db_));
  EXPECT_TRUE(isDatabaseOrCompanion(dir_.file("data_link/p.db-journal"), db_));
  // A database opened through a link keeps its companions next to the link's target.
  EXPECT_TRUE(isDatabaseOrCompanion(db_ + "-wal", dir_.file("link.db")));
}

TEST_F(CompanionPathTest, HardLinks) {
  fs::create_hard_link(db_, dir_.file("hard.db"));
  EXPECT_TRUE(isDatabaseOrCompanion(dir_.file("hard.db"), db_));
  writeFile(dir_.file("other.db"), "x");
  EXPECT_FALSE(isDatabaseOrCompanion(dir_.file("other.db"), db_));
}

}  // namespace
}  // namespace vicc_anatomy_viz::test
