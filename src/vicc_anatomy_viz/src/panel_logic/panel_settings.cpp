#include "vicc_anatomy_viz/panel_logic/panel_settings.hpp"

#include <cctype>

#include "vicc_anatomy_viz/patient_record.hpp"
#include "vicc_anatomy_viz/time_format.hpp"

namespace vicc_anatomy_viz::panel {

namespace {

std::string trimmed(const std::string& text) {
  const auto first = text.find_first_not_of(" \t");
  if (first == std::string::npos) return "";
  return text.substr(first, text.find_last_not_of(" \t") - first + 1);
}

/// "" when `name` is a ROS graph name the panel can prefix services with ("/ns", "ns/sub").
std::string graphNameProblem(const std::string& name) {
  if (name.empty()) return "is empty";
  if (!(name.front() == '/' || std::isalpha(static_cast<unsigned char>(name.front())))) {
    return "must start with '/' or a letter";
  }
  if (name.size() > 1 && name.back() == '/') return "must not end with '/'";
  if (name.find("//") != std::string::npos) return "must not contain '//'";
  for (const char c : name) {
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '/')) {
      return "may only contain letters, digits, '_' and '/'";
    }
  }
  return "";
}

bool isCategoryId(const std::string& id) {
  if (id.empty()) return false;
  for (const char c : id) {
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-')) return false;
  }
  return true;
}

const std::string* find(const KeyValues& values, const char* key) {
  const auto it = values.find(key);
  return it == values.end() ? nullptr : &it->second;
}

}  // namespace

std::string joinCategories(const std::vector<std::string>& ids) {
  std::string text;
  for (const auto& id : ids) text += (text.empty() ? "" : ",") + id;
  return text;
}

std::vector<std::string> splitCategories(const std::string& text) {
  std::vector<std::string> ids;
  std::size_t start = 0;
  while (start <= text.size()) {
    const auto comma = text.find(',', start);
    const auto end = comma == std::string::npos ? text.size() : comma;
    const std::string id = trimmed(text.substr(start, end - start));
    if (!id.empty()) ids.push_back(id);
    start = end + 1;
  }
  return ids;
}

KeyValues toKeyValues(const PanelSettings& settings) {
  return {{kServerKey, settings.server},
          {kPatientKey, settings.patient_id},
          {kDateKey, settings.date},
          {kHiddenCategoriesKey, joinCategories(settings.hidden_categories)}};
}

SettingsReading settingsFromKeyValues(const KeyValues& values) {
  SettingsReading reading;
  const auto reject = [&](const char* key, const std::string& value, const std::string& why) {
    reading.problems.push_back(std::string("panel configuration '") + key + "': '" + value + "' " +
                               why);
  };
  if (const auto* server = find(values, kServerKey)) {
    const std::string value = trimmed(*server);
    const std::string problem = graphNameProblem(value);
    if (problem.empty()) {
      reading.settings.server = value;
    } else {
      reject(kServerKey, *server, problem + " (using " + kDefaultServer + ")");
    }
  }
  if (const auto* patient = find(values, kPatientKey); patient && !trimmed(*patient).empty()) {
    const std::string value = trimmed(*patient);
    const std::string problem = patientIdProblem(value);
    if (problem.empty()) {
      reading.settings.patient_id = value;
    } else {
      reject(kPatientKey, *patient, "is not a patient id: " + problem);
    }
  }
  if (const auto* date = find(values, kDateKey)) {
    const std::string value = trimmed(*date);
    std::string problem;
    if (value.empty() || parseTime(value, &problem)) {
      reading.settings.date = value;
    } else {
      reject(kDateKey, *date, "is rejected: " + problem + " (using the latest)");
    }
  }
  if (const auto* hidden = find(values, kHiddenCategoriesKey)) {
    for (const auto& id : splitCategories(*hidden)) {
      if (isCategoryId(id)) {
        reading.settings.hidden_categories.push_back(id);
      } else {
        reject(kHiddenCategoriesKey, id, "is not a category id (left out)");
      }
    }
  }
  return reading;
}

}  // namespace vicc_anatomy_viz::panel
