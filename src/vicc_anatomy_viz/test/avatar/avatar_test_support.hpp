#pragma once
// The default avatar, built once for all avatar tests (about a second).

#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

#include "vicc_anatomy_viz/anatomy_catalog.hpp"
#include "vicc_anatomy_viz/avatar/avatar_builder.hpp"

namespace vicc_anatomy_viz::avatar::test {

inline std::string packagePath(const std::string& relative) {
  return std::string(VICC_TEST_PACKAGE_DIR) + "/" + relative;
}

inline const AnatomyCatalog& catalog() {
  static const AnatomyCatalog loaded =
      AnatomyCatalog::load(packagePath("config/anatomy/structures.yaml"));
  return loaded;
}

inline const AvatarBuild& defaultAvatar() {
  static const AvatarBuild build =
      buildAvatar(packagePath("config/anatomy/avatar.yaml"), catalog());
  return build;
}

/// A file in a fresh temporary directory.
inline std::string writeTemporary(const std::string& name, const std::string& text) {
  const std::filesystem::path directory =
      std::filesystem::temp_directory_path() / ("vicc_avatar_test_" + std::to_string(::getpid()));
  std::filesystem::create_directories(directory);
  const std::filesystem::path path = directory / name;
  std::ofstream(path) << text;
  return path.string();
}

}  // namespace vicc_anatomy_viz::avatar::test
