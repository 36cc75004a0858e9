// vicc_fhir_codesystem: prints our FHIR R4 CodeSystem resources (property codes, value codes,
// anatomy structure codes) as a Bundle, generated from the encoding configuration.
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include "vicc_anatomy_viz/encoding_model.hpp"
#include "vicc_anatomy_viz/errors.hpp"
#include "vicc_anatomy_viz/fhir_code_system.hpp"
#include "vicc_anatomy_viz/patient_status_service.hpp"
#include "vicc_common/command_line.hpp"

namespace {

constexpr const char* kUsage =
    "usage: vicc_fhir_codesystem [--config FILE] [--anatomy FILE] [--out FILE]\n"
    "  Prints the FHIR R4 CodeSystem resources of the encoding configuration as a Bundle\n"
    "  (to FILE with --out). Exit code 0 on success, 1 on error, 2 on a usage error.\n";

namespace cli = vicc_common::cli;

const std::vector<cli::OptionSpec> kOptionSpecs = {
    {"config", "FILE", "encoding configuration"},
    {"anatomy", "FILE", "anatomy catalogue"},
    {"out", "FILE", "write the bundle here instead of standard output"},
};

int run(const std::vector<std::string>& args) {
  using namespace vicc_anatomy_viz;
  const cli::ParsedArguments options = cli::parseArguments(args, kOptionSpecs);
  if (!options.positional.empty()) {
    throw cli::UsageError("unknown argument '" + options.positional.front() + "'");
  }
  const EncodingModel model =
      EncodingModel::load(options.value("config", defaultEncodingConfigPath()),
                          options.value("anatomy", defaultAnatomyConfigPath()));
  const std::string text = codeSystemResources(model).dump(2) + "\n";
  const std::string out_path = options.value("out");
  if (out_path.empty()) {
    std::cout << text;
    return 0;
  }
  std::ofstream file(out_path, std::ios::binary);
  if (!(file << text) || !file.flush()) {
    std::cerr << "vicc_fhir_codesystem: cannot write '" << out_path << "'\n";
    return 1;
  }
  std::cout << "wrote the FHIR CodeSystem bundle to " << out_path << "\n";
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return cli::runTool("vicc_fhir_codesystem", argc, argv, kUsage,
                      [](const std::vector<std::string>& arguments) { return run(arguments); });
}
