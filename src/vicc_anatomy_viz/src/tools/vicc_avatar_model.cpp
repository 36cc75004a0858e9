// vicc_avatar_model: builds the avatar model offline (same core as the rviz display) and
// reports it or exports its meshes.
//   vicc_avatar_model [--manifest FILE] [--anatomy FILE] --report
//   vicc_avatar_model [--manifest FILE] [--anatomy FILE] --export DIR
#include <exception>
#include <iostream>
#include <string>
#include <vector>

#include "vicc_anatomy_viz/avatar/avatar_builder.hpp"
#include "vicc_anatomy_viz/avatar/avatar_report.hpp"
#include "vicc_anatomy_viz/errors.hpp"
#include "vicc_anatomy_viz/patient_status_service.hpp"
#include "vicc_common/command_line.hpp"

namespace {

namespace cli = vicc_common::cli;

const std::vector<cli::OptionSpec> kOptionSpecs = {
    {"manifest", "FILE", "avatar manifest (default: the package's)"},
    {"anatomy", "FILE", "anatomy catalogue (default: the package's)"},
    {"report", "", "print the model's structures, regions and landmarks"},
    {"export", "DIR", "write one PLY file per structure and region into DIR"},
};

std::string usage() {
  return cli::helpText(
      "vicc_avatar_model [--manifest FILE] [--anatomy FILE] (--report | --export DIR)",
      "Builds the avatar model offline (the rviz display's core) and reports or exports it.\n"
      "Exit code 0 on success, 1 on error, 2 on a usage error.",
      kOptionSpecs);
}

int run(const std::vector<std::string>& args) {
  using namespace vicc_anatomy_viz;
  const cli::ParsedArguments options = cli::parseArguments(args, kOptionSpecs);
  if (!options.positional.empty()) {
    throw cli::UsageError("unexpected argument '" + options.positional.front() + "'");
  }
  const std::string export_directory = options.value("export");
  if (!options.flag("report") && export_directory.empty()) {
    throw cli::UsageError("--report or --export DIR is needed");
  }
  const AnatomyCatalog catalog =
      AnatomyCatalog::load(options.value("anatomy", defaultAnatomyConfigPath()));
  const avatar::AvatarBuild build =
      avatar::buildAvatar(options.value("manifest", avatar::defaultAvatarManifestPath()), catalog);
  if (options.flag("report")) avatar::writeReport(build, std::cout);
  if (!export_directory.empty()) {
    const std::size_t files = avatar::exportPly(build.model, export_directory);
    std::cout << "exported " << files << " PLY files to " << export_directory << "\n";
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return cli::runTool("vicc_avatar_model", argc, argv, usage(),
                      [](const std::vector<std::string>& arguments) { return run(arguments); });
}
