#include "vicc_anatomy_viz/record_json.hpp"

#include <climits>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "vicc_anatomy_viz/errors.hpp"
#include "vicc_anatomy_viz/time_format.hpp"

namespace vicc_anatomy_viz {

using nlohmann::json;

namespace {

/// Collects problems by JSON path instead of stopping at the first one.
class Reader {
 public:
  Reader(std::string source, std::vector<std::string>* warnings, const JsonImportOptions& options)
      : source_(std::move(source)), warnings_(warnings), options_(options) {}

  void warning(const std::string& path, const std::string& message) {
    if (warnings_) warnings_->push_back(path + ": " + message);
  }

  void problem(const std::string& path, const std::string& message) {
    problems_.push_back(path + ": " + message);
  }
  const std::vector<std::string>& problems() const { return problems_; }

  std::string text(const json& object, const std::string& key, const std::string& path,
                   bool required = true) {
    const auto it = object.find(key);
    if (it == object.end() || it->is_null()) {
      if (required) problem(path + "." + key, "missing");
      return "";
    }
    if (!it->is_string()) {
      problem(path + "." + key, "must be text");
      return "";
    }
    return it->get<std::string>();
  }

  const json* array(const json& object, const std::string& key, const std::string& path) {
    const auto it = object.find(key);
    if (it == object.end() || !it->is_array()) {
      problem(path + "." + key, "must be a list");
      return nullptr;
    }
    return &*it;
  }

  TimestampUs timestamp(const json& object, const std::string& path) {
    const std::string text = this->text(object, "taken_at", path);
    if (text.empty()) return 0;
    std::string why;
    const auto parsed = parseTime(text, &why);
    if (!parsed) {
      problem(path + ".taken_at", "'" + text + "' is not an ISO 8601 date or date-time: " + why);
      return 0;
    }
    if (const std::string implausible = options_.plausibility.problem(parsed->us);
        !implausible.empty()) {
      problem(path + ".taken_at", "implausible examination time: " + implausible);
    }
    if (!parsed->has_offset && !parsed->date_only) {
      warning(path + ".taken_at", "'" + text + "' has no UTC offset; taken as UTC");
    }
    return parsed->us;
  }

  /// "status" and "partial"/"partial_reason" of an examination.
  void completeness(const json& object, Examination& examination, const std::string& path) {
    const std::string status = text(object, "status", path, false);
    if (!status.empty()) {
      const auto parsed = examinationStatusFromString(status);
      if (!parsed) {
        problem(path + ".status", "'" + status + "' is not final or preliminary");
      } else {
        examination.status = *parsed;
      }
    }
    const auto partial = object.find("partial");
    if (partial != object.end() && !partial->is_boolean()) {
      problem(path + ".partial", "must be true or false");
    } else if (partial != object.end()) {
      examination.partial = partial->get<bool>();
    }
    examination.partial_reason = text(object, "partial_reason", path, false);
    if (!examination.partial && !examination.partial_reason.empty()) {
      problem(path + ".partial_reason", "given for an examination that is not partial");
    }
    if (examination.partial && examination.partial_reason.empty()) {
      examination.partial_reason = "marked partial in the imported file";
    }
  }

  Finding finding(const json& object, const std::string& path) {
    Finding finding;
    if (!object.is_object()) {
      problem(path, "a finding must be an object");
      return finding;
    }
    finding.category = text(object, "category", path);
    finding.structure = text(object, "structure", path);
    const std::string side_text = text(object, "side", path, false);
    const auto side = sideFromString(side_text);
    if (!side) {
      problem(path + ".side", "'" + side_text + "' is not left, right or none");
    } else {
      finding.side = *side;
    }
    const auto values = object.find("values");
    if (values == object.end() || !values->is_object()) {
      problem(path + ".values", "must be an object of property values");
      return finding;
    }
    for (const auto& [prop_type, value] : values->items()) {
      const std::string where = path + ".values." + prop_type;
      if (value.is_number_integer()) {
        // get<long long>() would wrap an unsigned number above LLONG_MAX to a negative one.
        const bool too_large =
            value.is_number_unsigned() && value.get<unsigned long long>() > INT_MAX;
        const auto number = too_large ? 0LL : value.get<long long>();
        if (too_large || number < INT_MIN || number > INT_MAX) {
          problem(where, "number out of range");
        } else {
          finding.values[prop_type] = Value::number(static_cast<int>(number));
        }
      } else if (value.is_number()) {
        problem(where, "is not an integer");
      } else if (value.is_string()) {
        finding.values[prop_type] = Value::label(value.get<std::string>());
      } else if (value.is_boolean()) {
        finding.values[prop_type] = Value::label(value.get<bool>() ? "true" : "false");
      } else {
        problem(where, "must be an integer, a label or a boolean");
      }
    }
    return finding;
  }

  Examination examination(const json& object, const std::string& patient_id,
                          const std::string& path) {
    Examination examination;
    examination.patient_id = patient_id;
    examination.source = source_;
    if (!object.is_object()) {
      problem(path, "an examination must be an object");
      return examination;
    }
    examination.taken_at_us = timestamp(object, path);
    completeness(object, examination, path);
    if (const json* findings = array(object, "findings", path)) {
      for (std::size_t i = 0; i < findings->size(); ++i) {
        examination.findings.push_back(
            finding((*findings)[i], path + ".findings[" + std::to_string(i) + "]"));
      }
    }
    return examination;
  }

  std::string patientId(const json& object, const std::string& key, const std::string& path) {
    const std::string id = text(object, key, path);
    const std::string reason = id.empty() ? "" : patientIdProblem(id);
    if (!reason.empty()) problem(path + "." + key, reason);
    return id;
  }

 private:
  std::string source_;
  std::vector<std::string>* warnings_;
  JsonImportOptions options_;
  std::vector<std::string> problems_;
};

json valueToJson(const Value& value) {
  if (value.isNumber()) return value.asNumber();
  // Only binary domains use these labels; they travel as JSON booleans.
  if (value.asLabel() == "true") return true;
  if (value.asLabel() == "false") return false;
  return value.asLabel();
}

json findingsToJson(const Examination& examination) {
  json findings = json::array();
  for (const auto& finding : examination.findings) {
    json values = json::object();
    for (const auto& [prop_type, value] : finding.values) values[prop_type] = valueToJson(value);
    findings.push_back({{"category", finding.category},
                        {"structure", finding.structure},
                        {"side", toString(finding.side)},
                        {"values", values}});
  }
  return findings;
}

/// Status, completeness, provenance and findings of an examination (both formats).
json examinationBody(const Examination& examination) {
  json body = {{"status", toString(examination.status)}};
  if (examination.partial) {
    body["partial"] = true;
    body["partial_reason"] = examination.partial_reason;
  }
  if (examination.recorded_at != 0) {
    body["provenance"] = {
        {"source", examination.source},
        {"recorded_at", formatTimestamp(examination.recorded_at * kMicrosPerSecond)}};
  }
  body["findings"] = findingsToJson(examination);
  return body;
}

/// nlohmann's parse errors quote the text last read ("last read: '9x'"), which may be a
/// recorded value: the message keeps the position and the reason only.
std::string withoutQuotedInput(const std::string& message) {
  const std::size_t quoted = message.find("; last read: ");
  if (quoted == std::string::npos) return message;
  const std::size_t rest = message.find("'; ", quoted + 14);
  return message.substr(0, quoted) + (rest == std::string::npos ? "" : message.substr(rest + 1));
}

/// Rejects an object that repeats a key: nlohmann keeps the last one silently.
class DuplicateKeyCheck {
 public:
  explicit DuplicateKeyCheck(const std::string& origin) : origin_(origin) {}

  bool operator()(int /*depth*/, json::parse_event_t event, json& parsed) {
    switch (event) {
      case json::parse_event_t::object_start:
        objects_.emplace_back();
        break;
      case json::parse_event_t::object_end:
        if (!objects_.empty()) objects_.pop_back();
        break;
      case json::parse_event_t::key: {
        const std::string key = parsed.get<std::string>();
        if (!objects_.empty() && !objects_.back().keys.insert(key).second) {
          throw ExchangeError(origin_ + ": key \"" + key + "\" appears twice in the object at " +
                              path() + " (which value is meant is ambiguous)");
        }
        if (!objects_.empty()) objects_.back().current = key;
        break;
      }
      default:
        break;
    }
    return true;
  }

 private:
  struct Frame {
    std::set<std::string> keys;
    std::string current;
  };
  std::string path() const {
    std::string out = "$";
    for (std::size_t i = 0; i + 1 < objects_.size(); ++i) out += "." + objects_[i].current;
    return out;
  }

  std::string origin_;
  std::vector<Frame> objects_;
};

}  // namespace

std::vector<Examination> examinationsFromJson(const json& document, const std::string& source,
                                              std::vector<std::string>* warnings,
                                              const JsonImportOptions& options) {
  if (!document.is_object()) throw ExchangeError("a records document must be a JSON object");
  // json::value() would throw type_error for a "format" that is not text.
  const auto format_field = document.find("format");
  const std::string format = format_field != document.end() && format_field->is_string()
                                 ? format_field->get<std::string>()
                                 : "";
  if (format != kRecordsFormat && format != kExaminationFormat) {
    throw ExchangeError("unknown document format '" + format + "' (expected '" + kRecordsFormat +
                        "', '" + kExaminationFormat + "' or a FHIR Bundle)");
  }
  if (!document.contains("version") || document["version"] != 1) {
    throw ExchangeError("unsupported " + format + " version (this program reads version 1)");
  }
  options.plausibility.validate();
  Reader reader(source, warnings, options);
  std::vector<Examination> examinations;
  if (format == kExaminationFormat) {
    const std::string patient = reader.patientId(document, "patient", "$");
    examinations.push_back(reader.examination(document, patient, "$"));
  } else if (const json* patients = reader.array(document, "patients", "$")) {
    for (std::size_t p = 0; p < patients->size(); ++p) {
      const json& patient = (*patients)[p];
      const std::string path = "$.patients[" + std::to_string(p) + "]";
      if (!patient.is_object()) {
        reader.problem(path, "a patient must be an object");
        continue;
      }
      const std::string id = reader.patientId(patient, "id", path);
      if (const auto history = patient.find("superseded");
          history != patient.end() && history->is_array() && !history->empty()) {
        reader.warning(path + ".superseded",
                       std::to_string(history->size()) +
                           " superseded version(s) are history and are not imported (use "
                           "vicc_patient backup/restore to move a database with its history)");
      }
      if (const json* list = reader.array(patient, "examinations", path)) {
        for (std::size_t e = 0; e < list->size(); ++e) {
          examinations.push_back(reader.examination(
              (*list)[e], id, path + ".examinations[" + std::to_string(e) + "]"));
        }
      }
    }
  }
  if (!reader.problems().empty()) throw ValidationError(reader.problems());
  return examinations;
}

json examinationToJson(const Examination& examination) {
  json document = {{"format", kExaminationFormat},
                   {"version", 1},
                   {"patient", examination.patient_id},
                   {"taken_at", formatTimestamp(examination.taken_at_us)}};
  document.update(examinationBody(examination));
  return document;
}

json recordsToJson(const std::vector<Examination>& examinations,
                   const std::vector<SupersededExamination>& history) {
  json patients = json::array();
  std::map<std::string, std::size_t> index;
  auto patientEntry = [&](const std::string& patient_id) -> json& {
    auto it = index.find(patient_id);
    if (it == index.end()) {
      it = index.emplace(patient_id, patients.size()).first;
      patients.push_back({{"id", patient_id}, {"examinations", json::array()}});
    }
    return patients[it->second];
  };
  for (const auto& examination : examinations) {
    json entry = {{"taken_at", formatTimestamp(examination.taken_at_us)}};
    entry.update(examinationBody(examination));
    patientEntry(examination.patient_id)["examinations"].push_back(entry);
  }
  for (const auto& version : history) {
    json entry = {{"taken_at", formatTimestamp(version.examination.taken_at_us)},
                  {"superseded_at", formatTimestamp(version.superseded_at * kMicrosPerSecond)},
                  {"replaced_by_source", version.replaced_by_source}};
    entry.update(examinationBody(version.examination));
    json& patient = patientEntry(version.examination.patient_id);
    if (!patient.contains("superseded")) patient["superseded"] = json::array();
    patient["superseded"].push_back(entry);
  }
  return {{"format", kRecordsFormat}, {"version", 1}, {"patients", patients}};
}

json parseJsonText(const std::string& text, const std::string& origin) {
  try {
    return json::parse(text, DuplicateKeyCheck(origin));
  } catch (const json::parse_error& e) {
    throw ExchangeError(origin + ": invalid JSON (" + withoutQuotedInput(e.what()) + ")");
  } catch (const json::out_of_range&) {
    // Not e.what(): it quotes the number, which may be a recorded value.
    throw ExchangeError(origin + ": invalid JSON (a number is too large)");
  }
}

std::string readTextFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ExchangeError("cannot read '" + path + "'");
  std::ostringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

}  // namespace vicc_anatomy_viz
