#pragma once
// The patient_status_server node's parameters: plain data with validate() and one
// (key, field) table, read by vicc_common's ROS reader (wrong types and typos named, never the
// silent default of NodeHandle::param).

#include <string>
#include <type_traits>

#include "vicc_anatomy_viz/patient_status_service.hpp"

namespace vicc_anatomy_viz::ros_adapter {

struct PatientStatusServerSettings {
  std::string db;               ///< SQLite file; defaultDatabasePath() unless set
  std::string encoding_config;  ///< defaultEncodingConfigPath() unless set
  std::string anatomy_config;   ///< defaultAnatomyConfigPath() unless set
  std::string view = PatientStatusConfig{}.view_id;
  int busy_timeout_ms = StoreConfig{}.busy_timeout_ms;
  /// Examination times more than this far ahead of the clock are rejected.
  int max_future_s = static_cast<int>(TimePlausibility{}.max_future_seconds);
  std::string patient;  ///< initial selection; empty: none
  std::string date;     ///< with `patient`: the examination date shown first; empty: latest

  /// The defaults, with the package's configuration files and the user's database.
  static PatientStatusServerSettings withDefaultPaths();
  /// What the service is built from.
  PatientStatusConfig serviceConfig() const;
  /// Throws std::invalid_argument naming the field.
  void validate() const;
};

template <typename Config, typename Visitor>
std::enable_if_t<std::is_same_v<std::remove_const_t<Config>, PatientStatusServerSettings>>
visitParameters(Config& config, Visitor& visit) {
  visit("db", config.db);
  visit("encoding_config", config.encoding_config);
  visit("anatomy_config", config.anatomy_config);
  visit("view", config.view);
  visit("busy_timeout_ms", config.busy_timeout_ms);
  visit("max_future_s", config.max_future_s);
  visit("patient", config.patient);
  visit("date", config.date);
}

}  // namespace vicc_anatomy_viz::ros_adapter
