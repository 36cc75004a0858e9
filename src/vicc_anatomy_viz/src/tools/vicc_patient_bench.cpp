// vicc_patient_bench: in-process timings for bench/patient_status: the encode path (database
// query of the examination at or before a date + visual encoding), its JSON serialization,
// and what every vicc_patient process pays once: loading the configuration (both YAML files
// parsed, the view validated) and opening and closing the record database. Process start-up itself
// (exec, dynamic linking) is measured by the bench script, which runs vicc_patient as a whole.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <string>
#include <vector>

#include "vicc_anatomy_viz/encoded_status_json.hpp"
#include "vicc_anatomy_viz/patient_status_service.hpp"
#include "vicc_anatomy_viz/record_store.hpp"
#include "vicc_common/command_line.hpp"

namespace {

using Clock = std::chrono::steady_clock;

struct Options {
  vicc_anatomy_viz::PatientStatusConfig config;
  std::string patient, date;
  int repeat = 200;
};

struct Summary {
  double median, p95, max;
};

Summary summarize(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  auto at = [&](double fraction) {
    return values[static_cast<std::size_t>(fraction * static_cast<double>(values.size() - 1))];
  };
  return {at(0.5), at(0.95), values.back()};
}

double millisecondsSince(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

namespace cli = vicc_common::cli;

const std::vector<cli::OptionSpec> kOptionSpecs = {
    {"db", "FILE", "record database (vicc_patient's)"},
    {"patient", "P", "patient whose examination is encoded"},
    {"date", "D", "examination at or before this date (default: the latest)"},
    {"repeat", "N", "encode repetitions (default 200; loads and opens a tenth as many)"},
};

std::string usage() {
  return cli::helpText("vicc_patient_bench --db FILE --patient P [--date D] [--repeat N]",
                       "In-process timings of the encode path for bench/patient_status (JSON "
                       "on stdout).\nExit code 0 on success, 1 on error, 2 on a usage error.",
                       kOptionSpecs);
}

/// Throws cli::UsageError naming what is wrong.
Options parseOptions(const std::vector<std::string>& args) {
  const cli::ParsedArguments parsed = cli::parseArguments(args, kOptionSpecs);
  if (!parsed.positional.empty()) {
    throw cli::UsageError("unexpected argument '" + parsed.positional.front() + "'");
  }
  Options options;
  options.config.encoding_config = vicc_anatomy_viz::defaultEncodingConfigPath();
  options.config.anatomy_config = vicc_anatomy_viz::defaultAnatomyConfigPath();
  options.config.store.path = parsed.required("db", "vicc_patient_bench");
  options.patient = parsed.required("patient", "vicc_patient_bench");
  options.date = parsed.value("date");
  options.repeat = parsed.integer("repeat", options.repeat, 1, 1000000);
  return options;
}

/// Times `once` a tenth as often as the encode repetitions (each is a whole load or open).
template <typename Action>
Summary timeRepeated(const Options& options, Action once) {
  std::vector<double> elapsed_ms;
  const int count = std::max(1, options.repeat / 10);
  for (int i = 0; i < count; ++i) {
    const auto start = Clock::now();
    once();
    elapsed_ms.push_back(millisecondsSince(start));
  }
  return summarize(elapsed_ms);
}

void printSummary(const char* name, const Summary& summary, bool last = false) {
  std::printf("\"%s\": {\"median\": %.4f, \"p95\": %.4f, \"max\": %.4f}%s", name, summary.median,
              summary.p95, summary.max, last ? "" : ", ");
}

int run(const Options& options) {
  // What a vicc_patient process does before its query: construct the service (configuration),
  // open the store. Timed while no other connection is open, so that each open creates the
  // WAL index files and each close removes them again, as in a process of its own.
  const Summary load = timeRepeated(
      options, [&] { const vicc_anatomy_viz::PatientStatusService loaded(options.config); });
  const Summary store_open = timeRepeated(
      options, [&] { const vicc_anatomy_viz::RecordStore opened(options.config.store); });
  vicc_anatomy_viz::PatientStatusService service(options.config);
  std::vector<double> encode_ms, json_ms;
  std::size_t structures = 0;
  for (int i = 0; i < options.repeat + 5; ++i) {  // the first 5 warm the caches
    const auto start = Clock::now();
    const auto status = service.encodedStatus(options.patient, options.date);
    const double encoded = millisecondsSince(start);
    const auto serializing = Clock::now();
    const std::string json = vicc_anatomy_viz::toJson(status).dump();
    const double serialized = millisecondsSince(serializing);
    if (i < 5) continue;
    encode_ms.push_back(encoded);
    json_ms.push_back(serialized);
    structures = status.structures.size();
  }
  const std::size_t findings =
      service.examinationAt(options.patient, options.date)->findings.size();
  std::printf(
      "{\"patient\": \"%s\", \"findings\": %zu, \"encoded_structures\": %zu, \"repeat\": %d, ",
      options.patient.c_str(), findings, structures, options.repeat);
  printSummary("encode_ms", summarize(encode_ms));
  printSummary("json_ms", summarize(json_ms));
  printSummary("load_ms", load);
  printSummary("store_open_ms", store_open, true);
  std::printf("}\n");
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return cli::runTool(
      "vicc_patient_bench", argc, argv, usage(),
      [](const std::vector<std::string>& arguments) { return run(parseOptions(arguments)); });
}
