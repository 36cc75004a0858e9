// vicc_patient_bench: times the encode path (database query of the examination at or before a
// date + visual encoding, and the JSON serialization) in-process, for bench/patient_status.
// Process start-up and configuration loading are excluded; the CLI's wall time is measured by
// the bench script separately.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <string>
#include <vector>

#include "vicc_anatomy_viz/encoded_status_json.hpp"
#include "vicc_anatomy_viz/patient_status_service.hpp"

namespace {

double percentile(std::vector<double> values, double fraction) {
  std::sort(values.begin(), values.end());
  const auto index = static_cast<std::size_t>(fraction * static_cast<double>(values.size() - 1));
  return values[index];
}

}  // namespace

int main(int argc, char** argv) {
  using Clock = std::chrono::steady_clock;
  vicc_anatomy_viz::PatientStatusConfig config;
  config.encoding_config = vicc_anatomy_viz::defaultEncodingConfigPath();
  config.anatomy_config = vicc_anatomy_viz::defaultAnatomyConfigPath();
  std::string patient, date;
  int repeat = 200;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string key = argv[i], value = argv[i + 1];
    if (key == "--db") {
      config.store.path = value;
    } else if (key == "--patient") {
      patient = value;
    } else if (key == "--date") {
      date = value;
    } else if (key == "--repeat") {
      repeat = std::max(1, std::stoi(value));
    } else {
      std::cerr << "unknown option " << key << "\n";
      return 2;
    }
  }
  if (config.store.path.empty() || patient.empty()) {
    std::cerr << "usage: vicc_patient_bench --db FILE --patient P [--date D] [--repeat N]\n";
    return 2;
  }
  try {
    vicc_anatomy_viz::PatientStatusService service(config);
    std::vector<double> encode_ms, json_ms;
    std::size_t structures = 0, findings = 0;
    for (int i = 0; i < repeat + 5; ++i) {  // the first 5 warm the caches
      const auto start = Clock::now();
      const auto status = service.encodedStatus(patient, date);
      const auto encoded = Clock::now();
      const std::string json = vicc_anatomy_viz::toJson(status).dump();
      const auto serialized = Clock::now();
      if (i < 5) continue;
      encode_ms.push_back(std::chrono::duration<double, std::milli>(encoded - start).count());
      json_ms.push_back(std::chrono::duration<double, std::milli>(serialized - encoded).count());
      structures = status.structures.size();
    }
    findings = service.examinationAt(patient, date)->findings.size();
    std::printf(
        "{\"patient\": \"%s\", \"findings\": %zu, \"encoded_structures\": %zu, \"repeat\": %d, "
        "\"encode_ms\": {\"median\": %.4f, \"p95\": %.4f, \"max\": %.4f}, "
        "\"json_ms\": {\"median\": %.4f, \"p95\": %.4f}}\n",
        patient.c_str(), findings, structures, repeat, percentile(encode_ms, 0.5),
        percentile(encode_ms, 0.95), percentile(encode_ms, 1.0), percentile(json_ms, 0.5),
        percentile(json_ms, 0.95));
  } catch (const std::exception& e) {
    std::cerr << "vicc_patient_bench: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
