#pragma once
// A package's data in the space (devel or install prefix) that holds the calling binary.
//
// catkin installs a package's libraries to <prefix>/lib, its executables to
// <prefix>/lib/<package> and its data to <prefix>/share/<package>; the devel space has the
// same layout once vicc_link_devel_share() has linked the data directories there. So the
// binary that contains `anchor` (found with dladdr) tells the prefix: no source-tree path is
// compiled in, and no ROS environment is needed, which the ROS-free CLIs rely on.

#include <filesystem>
#include <string>
#include <vector>

namespace vicc_paths {

/// The file that holds the code or data at `anchor` (a shared library or an executable).
std::filesystem::path binaryContaining(const void* anchor);

/// The share/<package> directories that may hold the package's data for the binary at
/// `binary`, nearest prefix first (<dir>/share/<package> for the binary's directory and up to
/// two parents: lib/ and lib/<package>/ layouts).
std::vector<std::filesystem::path> shareCandidates(const std::filesystem::path& binary,
                                                   const std::string& package);

/// <share>/<relative> for the first candidate where it exists; throws std::runtime_error
/// naming the package, the relative path and every place looked at.
std::filesystem::path packageDataPath(const std::string& package, const std::string& relative,
                                      const void* anchor);

}  // namespace vicc_paths
