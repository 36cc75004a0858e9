// vicc_avatar_model: builds the avatar model offline (same core as the rviz display) and
// reports it or exports its meshes.
//   vicc_avatar_model [--manifest FILE] [--anatomy FILE] --report
//   vicc_avatar_model [--manifest FILE] [--anatomy FILE] --export DIR
#include <cstdio>
#include <exception>
#include <iostream>
#include <string>
#include <vector>

#include "vicc_anatomy_viz/avatar/avatar_builder.hpp"
#include "vicc_anatomy_viz/avatar/avatar_report.hpp"
#include "vicc_anatomy_viz/errors.hpp"
#include "vicc_anatomy_viz/patient_status_service.hpp"

namespace {

constexpr const char* kUsage =
    "usage: vicc_avatar_model [--manifest FILE] [--anatomy FILE] (--report | --export DIR)\n";

struct Options {
  std::string manifest = vicc_anatomy_viz::avatar::defaultAvatarManifestPath();
  std::string anatomy = vicc_anatomy_viz::defaultAnatomyConfigPath();
  bool report = false;
  std::string export_directory;
};

bool parse(const std::vector<std::string>& arguments, Options& options) {
  for (std::size_t i = 0; i < arguments.size(); ++i) {
    const std::string& argument = arguments[i];
    const bool has_value = i + 1 < arguments.size();
    if (argument == "--report") {
      options.report = true;
    } else if (argument == "--manifest" && has_value) {
      options.manifest = arguments[++i];
    } else if (argument == "--anatomy" && has_value) {
      options.anatomy = arguments[++i];
    } else if (argument == "--export" && has_value) {
      options.export_directory = arguments[++i];
    } else {
      std::cerr << "vicc_avatar_model: unexpected argument '" << argument << "'\n" << kUsage;
      return false;
    }
  }
  if (!options.report && options.export_directory.empty()) {
    std::cerr << kUsage;
    return false;
  }
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace vicc_anatomy_viz;
  Options options;
  if (!parse(std::vector<std::string>(argv + 1, argv + argc), options)) return 2;
  try {
    const AnatomyCatalog catalog = AnatomyCatalog::load(options.anatomy);
    const avatar::AvatarBuild build = avatar::buildAvatar(options.manifest, catalog);
    if (options.report) avatar::writeReport(build, std::cout);
    if (!options.export_directory.empty()) {
      const std::size_t files = avatar::exportPly(build.model, options.export_directory);
      std::cout << "exported " << files << " PLY files to " << options.export_directory << "\n";
    }
  } catch (const std::exception& error) {
    std::cerr << "vicc_avatar_model: " << error.what() << "\n";
    return 1;
  }
  return 0;
}
