#pragma once
// What the patient panel saves in the rviz configuration, as key/value text (the panel maps it
// onto rviz::Config). Reading validates every key; a bad value is reported naming its key and
// replaced by the default, never passed on.

#include <map>
#include <string>
#include <vector>

namespace vicc_anatomy_viz::panel {

/// Configuration keys.
inline constexpr const char* kServerKey = "Server";
inline constexpr const char* kPatientKey = "Patient";
inline constexpr const char* kDateKey = "Date";
inline constexpr const char* kHiddenCategoriesKey = "Hidden Categories";
inline constexpr const char* kDefaultServer = "/patient_status_server";

struct PanelSettings {
  std::string server = kDefaultServer;  ///< namespace of the status server's services and topic
  std::string patient_id;               ///< "" = show what the server publishes
  std::string date;                     ///< "" = latest examination
  std::vector<std::string> hidden_categories;
};

using KeyValues = std::map<std::string, std::string>;

KeyValues toKeyValues(const PanelSettings& settings);

struct SettingsReading {
  PanelSettings settings;
  std::vector<std::string> problems;  ///< one per rejected key or entry
};
/// Keys not listed above are ignored (rviz stores its own, e.g. "Class" and "Name").
SettingsReading settingsFromKeyValues(const KeyValues& values);

/// "a,b" <-> {"a","b"}; entries are trimmed, empty ones dropped.
std::string joinCategories(const std::vector<std::string>& ids);
std::vector<std::string> splitCategories(const std::string& text);

}  // namespace vicc_anatomy_viz::panel
