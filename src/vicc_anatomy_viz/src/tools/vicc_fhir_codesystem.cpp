// vicc_fhir_codesystem: prints our FHIR R4 CodeSystem resources (property codes, value codes,
// anatomy structure codes) as a Bundle, generated from the encoding configuration.
#include <fstream>
#include <iostream>
#include <map>
#include <string>
#include <vector>

#include "vicc_anatomy_viz/encoding_model.hpp"
#include "vicc_anatomy_viz/errors.hpp"
#include "vicc_anatomy_viz/fhir_code_system.hpp"
#include "vicc_anatomy_viz/patient_status_service.hpp"

namespace {

constexpr const char* kUsage =
    "usage: vicc_fhir_codesystem [--config FILE] [--anatomy FILE] [--out FILE]\n"
    "  Prints the FHIR R4 CodeSystem resources of the encoding configuration as a Bundle\n"
    "  (to FILE with --out). Exit code 0 on success, 1 on error, 2 on a usage error.\n";

struct UsageError {
  std::string message;
};

/// --option VALUE or --option=VALUE for the three options; anything else is a usage error.
std::map<std::string, std::string> parseOptions(const std::vector<std::string>& args) {
  std::map<std::string, std::string> options;
  for (std::size_t i = 0; i < args.size(); ++i) {
    std::string name = args[i];
    std::string value;
    const auto equals = name.find('=');
    if (equals != std::string::npos) {
      value = name.substr(equals + 1);
      name = name.substr(0, equals);
    } else if (i + 1 < args.size()) {
      value = args[++i];
    } else {
      throw UsageError{"'" + name + "' needs a value"};
    }
    if (name != "--config" && name != "--anatomy" && name != "--out") {
      throw UsageError{"unknown argument '" + name + "'"};
    }
    options[name] = value;
  }
  return options;
}

std::string optionOr(const std::map<std::string, std::string>& options, const std::string& name,
                     const std::string& fallback) {
  const auto found = options.find(name);
  return found == options.end() ? fallback : found->second;
}

int run(const std::vector<std::string>& args) {
  using namespace vicc_anatomy_viz;
  const auto options = parseOptions(args);
  const EncodingModel model =
      EncodingModel::load(optionOr(options, "--config", defaultEncodingConfigPath()),
                          optionOr(options, "--anatomy", defaultAnatomyConfigPath()));
  const std::string text = codeSystemResources(model).dump(2) + "\n";
  const std::string out_path = optionOr(options, "--out", "");
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
  const std::vector<std::string> args(argv + 1, argv + argc);
  if (args.size() == 1 && (args[0] == "--help" || args[0] == "-h")) {
    std::cout << kUsage;
    return 0;
  }
  try {
    return run(args);
  } catch (const UsageError& e) {
    std::cerr << "vicc_fhir_codesystem: " << e.message << "\n" << kUsage;
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "vicc_fhir_codesystem: " << e.what() << "\n";
    return 1;
  }
}
