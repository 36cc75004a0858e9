#pragma once
// The database of the rviz rostests (avatar display, status glyph): the file the launch gives
// the test and the patient status server as ~db, sample patients (the thesis's Fig. 4.6
// patient SDH-046, ...) recorded into it through the status service, and its removal after
// the suite.

#include <ros/ros.h>

#include <cstdio>
#include <string>
#include <vector>

#include "vicc_anatomy_viz/patient_status_service.hpp"
#include "vicc_anatomy_viz/record_json.hpp"

namespace vicc_anatomy_viz::rviz_test {

/// The test's private parameter ~db ("" when the launch file gives none).
inline std::string databasePath() {
  std::string db;
  ros::param::get("~db", db);
  return db;
}

/// The examinations of a sample file of the package (data/samples/README.md).
inline std::vector<Examination> sampleExaminations(const std::string& file) {
  const std::string path = std::string(VICC_TEST_PACKAGE_DIR) + "/data/samples/" + file;
  return examinationsFromJson(parseJsonText(readTextFile(path), path));
}

/// SDH-046's examinations (pre-operative 2023-03-06, post-operative 2023-03-10).
inline std::vector<Examination> figurePatientExaminations() {
  return sampleExaminations("fig4_6_patient.json");
}

/// Written straight into the server's database file (the server opens it on first use).
inline void recordExaminations(const std::vector<Examination>& examinations) {
  PatientStatusConfig config;
  config.encoding_config = defaultEncodingConfigPath();
  config.anatomy_config = defaultAnatomyConfigPath();
  config.store.path = databasePath();
  PatientStatusService service(config);
  service.record(examinations, WriteMode::kRejectExisting);
}

/// Removes the database and its SQLite companions.
inline void removeDatabase() {
  for (const char* suffix : {"", "-wal", "-shm"}) std::remove((databasePath() + suffix).c_str());
}

}  // namespace vicc_anatomy_viz::rviz_test
