// Open modes of SqliteConnection, above all read-only access to a WAL database.
#include <filesystem>

#include <gtest/gtest.h>

#include "database_test_support.hpp"

namespace vicc_anatomy_viz::test {
namespace {

std::string patientCount(const std::string& path) {
  SqliteConnection reader(path, 1000, OpenMode::kReadOnly);
  return std::to_string(reader.queryInt("SELECT count(*) FROM patients")) +
         (reader.immutable() ? " immutable" : "");
}

TEST(SqliteConnectionTest, ReadOnlyOnMissingFileThrowsNotFoundAndCreatesNothing) {
  TempDir dir;
  for (const std::string& path : {dir.file("p.db"), dir.file("sub/dir/p.db")}) {
    std::string message;
    EXPECT_EQ(storeErrorKind([&] { SqliteConnection(path, 100, OpenMode::kReadOnly); }, &message),
              StoreError::Kind::kNotFound);
    EXPECT_EQ(message, "patient database '" + path + "' does not exist");
  }
  EXPECT_TRUE(std::filesystem::is_empty(dir.file("")));  // no file, -wal, -shm or directory
}

TEST(SqliteConnectionTest, ReadWriteWithoutCreateOnMissingFileThrowsNotFound) {
  TempDir dir;
  std::string message;
  EXPECT_EQ(storeErrorKind([&] { SqliteConnection(dir.file("p.db"), 100, false); }, &message),
            StoreError::Kind::kNotFound);
  EXPECT_FALSE(pathExists(dir.file("p.db")));
}

TEST(SqliteConnectionTest, ReadOnlySeesCommittedWalDataOfAnOpenWriterAndRefusesWrites) {
  TempDir dir;
  const std::string path = dir.file("p.db");
  createPatientDatabase(path, 2);
  SqliteConnection writer(path, 1000, OpenMode::kReadWrite);
  writer.exec("PRAGMA wal_autocheckpoint = 0");  // the new rows stay in the -wal file
  addPatients(writer, 2, 3);
  ASSERT_GT(std::filesystem::file_size(path + "-wal"), 0u);

  SqliteConnection reader(path, 100, OpenMode::kReadOnly);
  EXPECT_TRUE(reader.readOnly());
  EXPECT_FALSE(reader.immutable());
  EXPECT_EQ(reader.queryInt("SELECT count(*) FROM patients"), 5);
  std::string message;
  EXPECT_EQ(storeErrorKind([&] { reader.exec("DELETE FROM patients"); }, &message),
            StoreError::Kind::kIo);
  EXPECT_NE(message.find("readonly"), std::string::npos) << message;
  EXPECT_EQ(writer.queryInt("SELECT count(*) FROM patients"), 5);
}

TEST(SqliteConnectionTest, ReadOnlyOnAFileThatIsNoDatabaseReportsCorrupt) {
  TempDir dir;
  writeFile(dir.file("notes.db"), std::string(8192, 'n'));
  std::string message;
  EXPECT_EQ(storeErrorKind([&] { patientCount(dir.file("notes.db")); }, &message),
            StoreError::Kind::kCorrupt);
  EXPECT_NE(message.find("not an SQLite database"), std::string::npos) << message;
}

TEST(SqliteConnectionTest, ReadOnlyReadsAClosedWalDatabaseInAnUnwritableDirectory) {
  TempDir dir;
  // URI characters in the name check the escaping of the immutable=1 fallback.
  const std::string path = dir.file("p?#% 1.db");
  createPatientDatabase(path, 3);
  ASSERT_FALSE(pathExists(path + "-wal"));
  const ChildResult result =
      inUnwritableDirectory(dir.file(""), [&] { return patientCount(path); });
  if (result.state == ChildResult::State::kNotArranged) {
    GTEST_SKIP() << "cannot make a directory unwritable here: " << result.output;
  }
  ASSERT_EQ(result.state, ChildResult::State::kRan) << result.output;
  EXPECT_EQ(result.output, "3 immutable");
  EXPECT_FALSE(pathExists(path + "-shm"));
}

TEST(SqliteConnectionTest, ReadOnlyReadsTheWalOfARunningWriterInAnUnwritableDirectory) {
  TempDir dir;
  const std::string path = dir.file("p.db");
  createPatientDatabase(path, 2);
  const WalWriterProcess writer(path, 2);
  ASSERT_TRUE(writer.ready());
  ASSERT_TRUE(pathExists(path + "-shm"));
  ASSERT_GT(std::filesystem::file_size(path + "-wal"), 0u);
  const ChildResult result =
      inUnwritableDirectory(dir.file(""), [&] { return patientCount(path); });
  if (result.state == ChildResult::State::kNotArranged) {
    GTEST_SKIP() << "cannot make a directory unwritable here: " << result.output;
  }
  ASSERT_EQ(result.state, ChildResult::State::kRan) << result.output;
  EXPECT_EQ(result.output, "4");  // SQLite's read-only -shm: the rows in the -wal are seen
}

TEST(SqliteConnectionTest, ReadOnlyRefusesPendingWalChangesItCannotReadInsteadOfOldData) {
  TempDir source_dir, copy_dir;
  const std::string source = source_dir.file("p.db");
  const std::string copy = copy_dir.file("p.db");
  createPatientDatabase(source, 2);
  {
    SqliteConnection writer(source, 1000, OpenMode::kReadWrite);
    writer.exec("PRAGMA wal_autocheckpoint = 0");
    addPatients(writer, 2, 2);
    // A copy of the files as a crash would leave them: changes in the -wal, no -shm.
    std::filesystem::copy_file(source, copy);
    std::filesystem::copy_file(source + "-wal", copy + "-wal");
  }
  const ChildResult result =
      inUnwritableDirectory(copy_dir.file(""), [&] { return patientCount(copy); });
  if (result.state == ChildResult::State::kNotArranged) {
    GTEST_SKIP() << "cannot make a directory unwritable here: " << result.output;
  }
  ASSERT_EQ(result.state, ChildResult::State::kRan) << result.output;
  EXPECT_NE(result.output.find("StoreError 4: patient database '" + copy + "' cannot be read here"),
            std::string::npos)
      << result.output;
  EXPECT_EQ(patientCount(copy), "4");  // where the directory is writable, all rows are there
}

}  // namespace
}  // namespace vicc_anatomy_viz::test
