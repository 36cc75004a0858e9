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

/// Returns false (after a message) on a usage error.
bool parseOptions(int argc, char** argv, Options& options) {
  options.config.encoding_config = vicc_anatomy_viz::defaultEncodingConfigPath();
  options.config.anatomy_config = vicc_anatomy_viz::defaultAnatomyConfigPath();
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string key = argv[i], value = argv[i + 1];
    if (key == "--db") {
      options.config.store.path = value;
    } else if (key == "--patient") {
      options.patient = value;
    } else if (key == "--date") {
      options.date = value;
    } else if (key == "--repeat") {
      options.repeat = std::max(1, std::stoi(value));
    } else {
      std::cerr << "unknown option " << key << "\n";
      return false;
    }
  }
  if (options.config.store.path.empty() || options.patient.empty()) {
    std::cerr << "usage: vicc_patient_bench --db FILE --patient P [--date D] [--repeat N]\n";
    return false;
  }
  return true;
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
  try {
    Options options;
    if (!parseOptions(argc, argv, options)) return 2;
    return run(options);
  } catch (const std::exception& e) {
    std::cerr << "vicc_patient_bench: " << e.what() << "\n";
    return 1;
  }
}
