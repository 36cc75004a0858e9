#include "vicc_paths/package_share.hpp"

#include <dlfcn.h>

#include <stdexcept>
#include <system_error>

namespace vicc_paths {

namespace fs = std::filesystem;

fs::path binaryContaining(const void* anchor) {
  Dl_info info{};
  if (anchor != nullptr && dladdr(anchor, &info) != 0 && info.dli_fname != nullptr &&
      info.dli_fname[0] != '\0') {
    std::error_code error;
    const fs::path resolved = fs::weakly_canonical(info.dli_fname, error);
    if (!error) return resolved;
  }
  // dladdr names the main program by argv[0] at worst; /proc says where it really is.
  std::error_code error;
  const fs::path self = fs::read_symlink("/proc/self/exe", error);
  if (error) throw std::runtime_error("vicc_paths: cannot tell which file holds the running code");
  return self;
}

std::vector<fs::path> shareCandidates(const fs::path& binary, const std::string& package) {
  std::vector<fs::path> candidates;
  fs::path dir = binary.parent_path();
  for (int level = 0; level < 3 && !dir.empty(); ++level) {
    candidates.push_back(dir / "share" / package);
    if (dir == dir.root_path()) break;
    dir = dir.parent_path();
  }
  return candidates;
}

fs::path packageDataPath(const std::string& package, const std::string& relative,
                         const void* anchor) {
  const fs::path binary = binaryContaining(anchor);
  std::string searched;
  for (const fs::path& share : shareCandidates(binary, package)) {
    const fs::path candidate = share / relative;
    std::error_code error;
    if (fs::exists(candidate, error)) return candidate;
    searched += "\n  " + candidate.string();
  }
  throw std::runtime_error("package '" + package + "': '" + relative + "' not found next to " +
                           binary.string() + " (devel or install space); looked at:" + searched);
}

}  // namespace vicc_paths
