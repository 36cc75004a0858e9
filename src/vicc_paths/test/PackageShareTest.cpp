#include <gtest/gtest.h>

#include <dlfcn.h>

#include <fstream>
#include <stdexcept>
#include <string>

#include "vicc_paths/package_share.hpp"

namespace fs = std::filesystem;
using vicc_paths::binaryContaining;
using vicc_paths::packageDataPath;
using vicc_paths::shareCandidates;

namespace {
int anchorInThisTest = 0;
}

TEST(PackageShareTest, BinaryContainingFindsThisTestExecutable) {
  const fs::path binary = binaryContaining(&anchorInThisTest);
  EXPECT_EQ(binary.filename(), "vicc_paths_test");
  EXPECT_TRUE(fs::is_regular_file(binary)) << binary;
}

TEST(PackageShareTest, BinaryContainingFindsTheSharedLibraryOfTheCode) {
  // dladdr itself is in the C library, not in this executable.
  const fs::path library = binaryContaining(reinterpret_cast<const void*>(&dladdr));
  EXPECT_EQ(library.filename().string().rfind("libc.so", 0), 0u) << library;
}

TEST(PackageShareTest, CandidatesCoverTheLibraryAndTheExecutableLayouts) {
  const auto from_library = shareCandidates("/opt/ws/install/lib/libx.so", "pkg");
  ASSERT_GE(from_library.size(), 2u);
  EXPECT_EQ(from_library[0], fs::path("/opt/ws/install/lib/share/pkg"));
  EXPECT_EQ(from_library[1], fs::path("/opt/ws/install/share/pkg"));
  const auto from_executable = shareCandidates("/opt/ws/install/lib/pkg/tool", "pkg");
  ASSERT_EQ(from_executable.size(), 3u);
  EXPECT_EQ(from_executable[2], fs::path("/opt/ws/install/share/pkg"));
  // At the root the walk stops instead of repeating "/".
  EXPECT_EQ(shareCandidates("/tool", "pkg").size(), 1u);
}

TEST(PackageShareTest, FindsOwnDevelShareAndNamesWhatIsMissing) {
  // This executable runs from <devel>/lib/vicc_paths/: <devel>/share/vicc_paths has the
  // catkin-generated cmake/ directory.
  const fs::path cmake_dir = packageDataPath("vicc_paths", "cmake", &anchorInThisTest);
  EXPECT_TRUE(fs::is_directory(cmake_dir)) << cmake_dir;
  EXPECT_EQ(cmake_dir.parent_path().filename(), "vicc_paths");
  try {
    packageDataPath("vicc_paths", "no/such/file.yaml", &anchorInThisTest);
    FAIL() << "a missing file was found";
  } catch (const std::runtime_error& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("package 'vicc_paths'"), std::string::npos) << message;
    EXPECT_NE(message.find("no/such/file.yaml"), std::string::npos) << message;
    EXPECT_NE(message.find("share/vicc_paths/no/such/file.yaml"), std::string::npos) << message;
  }
}
