// FHIR R4 import: Observations -> examinations and findings. An examination is identified
// explicitly (our grouping Observation, else a shared encounter), and only for feeds without
// either by patient and a time window; every grouping across different times is reported.
// Unknown codes are reported, never dropped silently.
#include <algorithm>
#include <map>
#include <stdexcept>
#include <tuple>

#include "fhir_codes.hpp"
#include "fhir_observation_reader.hpp"
#include "vicc_anatomy_viz/errors.hpp"
#include "vicc_anatomy_viz/fhir_bundle.hpp"

namespace vicc_anatomy_viz {

using fhir_import::ImportReport;
using fhir_import::ObservationEntry;
using nlohmann::json;

namespace {

/// The observations of one examination.
struct ExaminationGroup {
  std::string how;  ///< "grouping Observation", "encounter", "time window"
  const ObservationEntry* panel = nullptr;
  std::vector<const ObservationEntry*> members;
};

/// Assigns every member observation to a panel that lists it; reports dangling, shared and
/// foreign-patient members. Returns member index -> group key.
std::map<std::size_t, std::string> assignToPanels(const std::vector<ObservationEntry>& entries,
                                                  std::map<std::string, ExaminationGroup>& groups,
                                                  ImportReport& report) {
  std::map<std::string, const ObservationEntry*> by_reference;
  for (const auto& entry : entries) {
    for (const auto& reference : entry.references) by_reference[reference] = &entry;
  }
  std::map<std::size_t, std::string> assigned;
  for (const auto& panel : entries) {
    if (!panel.is_panel) continue;
    const std::string key = "panel:" + std::to_string(panel.index);
    ExaminationGroup& group = groups[key];
    group.how = "its grouping Observation";
    group.panel = &panel;
    for (const auto& reference : panel.members) {
      const auto found = by_reference.find(reference);
      if (found == by_reference.end() || found->second->is_panel) {
        report.malformed(panel.where + ": hasMember '" + reference +
                         "' is not an Observation of this bundle (the examination would be "
                         "incomplete)");
        continue;
      }
      const ObservationEntry& member = *found->second;
      if (member.patient != panel.patient) {
        report.malformed(member.where + ": belongs to the examination of " + panel.where +
                         " but names another patient");
      } else if (!assigned.emplace(member.index, key).second) {
        report.malformed(member.where + ": is a member of two examinations");
      }
    }
  }
  return assigned;
}

/// Members without a panel: by encounter, else per patient in windows of `window_us` from
/// the first observation of each window.
void groupLooseMembers(const std::vector<ObservationEntry>& entries,
                       const std::map<std::size_t, std::string>& assigned, TimestampUs window_us,
                       std::map<std::string, ExaminationGroup>& groups) {
  std::map<std::string, std::vector<const ObservationEntry*>> by_patient;
  for (const auto& entry : entries) {
    if (entry.is_panel) continue;
    if (const auto it = assigned.find(entry.index); it != assigned.end()) {
      groups[it->second].members.push_back(&entry);
    } else if (!entry.encounter.empty()) {
      ExaminationGroup& group = groups["encounter:" + entry.patient + "|" + entry.encounter];
      group.how = "encounter " + entry.encounter;
      group.members.push_back(&entry);
    } else {
      by_patient[entry.patient].push_back(&entry);
    }
  }
  for (auto& [patient, list] : by_patient) {
    std::stable_sort(list.begin(), list.end(),
                     [](const auto* a, const auto* b) { return a->time < b->time; });
    std::string key;
    TimestampUs window_start = 0;
    for (const ObservationEntry* entry : list) {
      if (key.empty() || entry->time - window_start > window_us) {
        window_start = entry->time;
        key = "time:" + patient + "|" + std::to_string(entry->index);
        groups[key].how = "time window";
      }
      groups[key].members.push_back(entry);
    }
  }
}

/// One examination from a group: time, status, completeness, findings.
std::optional<Examination> buildExamination(const ExaminationGroup& group, ImportReport& report) {
  const ObservationEntry& first = group.panel ? *group.panel : *group.members.front();
  Examination examination;
  examination.patient_id = first.patient;
  examination.source = "fhir";
  TimestampUs earliest = first.time, latest = first.time;
  std::size_t skipped = 0;
  std::map<std::tuple<std::string, std::string, Side>, Finding> findings;
  std::map<std::tuple<std::string, std::string, Side, std::string>, std::string> seen;
  const std::size_t problems_before = report.problems().size();
  for (const ObservationEntry* member : group.members) {
    earliest = std::min(earliest, member->time);
    latest = std::max(latest, member->time);
    if (member->status == ExaminationStatus::kPreliminary) {
      examination.status = ExaminationStatus::kPreliminary;
    }
    if (!member->skipped.empty()) {
      ++skipped;
      continue;
    }
    const auto key =
        std::make_tuple(member->category, member->structure, member->side, member->prop_type);
    if (const auto [it, fresh] = seen.emplace(key, member->where); !fresh) {
      report.malformed(member->where + ": repeats the observation of " + it->second);
      continue;
    }
    Finding& finding = findings[{member->category, member->structure, member->side}];
    finding.category = member->category;
    finding.structure = member->structure;
    finding.side = member->side;
    finding.values[member->prop_type] = member->value;
  }
  examination.taken_at_us = group.panel ? group.panel->time : earliest;
  if (group.panel && group.panel->status == ExaminationStatus::kPreliminary) {
    examination.status = ExaminationStatus::kPreliminary;
  }
  for (auto& [unused, finding] : findings) examination.findings.push_back(std::move(finding));
  const std::string name = examination.describe();
  if (group.panel && group.panel->states_all_normal) {
    const bool all_normal = *group.panel->states_all_normal;
    if (all_normal && !group.members.empty()) {
      report.malformed(group.panel->where + ": states no abnormal findings but has members");
    } else if (!all_normal && group.members.empty()) {
      report.malformed(group.panel->where + ": states abnormal findings but has no members");
    }
  }
  if (group.panel && !group.panel->partial_reason.empty()) {
    examination.partial = true;
    examination.partial_reason = group.panel->partial_reason;
  }
  if (skipped > 0) {
    examination.partial = true;
    examination.partial_reason += std::string(examination.partial_reason.empty() ? "" : "; ") +
                                  std::to_string(skipped) + " observation(s) not imported";
  }
  if (latest != earliest || (group.panel && !group.members.empty() && latest != first.time)) {
    report.warn(name + ": " + std::to_string(group.members.size()) +
                " observation(s) at different times grouped by " + group.how + " (" +
                formatTimestamp(earliest) + " .. " + formatTimestamp(latest) + ")");
  }
  if (report.problems().size() != problems_before) return std::nullopt;
  return examination;
}

}  // namespace

void FhirImportOptions::validate() const {
  if (grouping_window_seconds < 0) {
    throw std::invalid_argument("grouping_window_seconds must be >= 0");
  }
  plausibility.validate();
}

bool isFhirBundle(const json& document) {
  return fhir_codes::textOr(document, "resourceType", "") == "Bundle";
}

FhirImport examinationsFromFhirBundle(const json& bundle, const EncodingModel& model,
                                      const FhirImportOptions& options) {
  options.validate();
  if (!isFhirBundle(bundle)) throw ExchangeError("not a FHIR Bundle (resourceType != Bundle)");
  const json entries = bundle.value("entry", json::array());
  if (!entries.is_array()) throw ExchangeError("Bundle.entry must be a list");
  FhirImport result;
  ImportReport report(options.skip_unknown, result.warnings);
  std::vector<ObservationEntry> observations;
  for (std::size_t i = 0; i < entries.size(); ++i) {
    const json resource = entries[i].is_object() ? entries[i].value("resource", json()) : json();
    const json type_json = resource.is_object() ? resource.value("resourceType", json()) : json();
    const std::string type = type_json.is_string() ? type_json.get<std::string>() : "";
    if (type != "Observation") {
      // Other resources (Patient, Encounter, ...) may carry names: only the type is reported.
      report.warn("entry " + std::to_string(i) + ": " +
                  (type.empty() ? std::string("entry without a resource") : type + " resource") +
                  " ignored (only Observation is imported)");
      continue;
    }
    if (auto entry = fhir_import::readObservationEntry(entries[i], i, model, options, report)) {
      observations.push_back(std::move(*entry));
    }
  }
  std::map<std::string, ExaminationGroup> groups;
  const auto assigned = assignToPanels(observations, groups, report);
  groupLooseMembers(observations, assigned,
                    static_cast<TimestampUs>(options.grouping_window_seconds) * kMicrosPerSecond,
                    groups);
  for (const auto& [key, group] : groups) {
    if (auto examination = buildExamination(group, report)) {
      result.examinations.push_back(std::move(*examination));
    }
  }
  if (!report.problems().empty()) throw ValidationError(report.problems());
  std::sort(result.examinations.begin(), result.examinations.end(),
            [](const Examination& a, const Examination& b) {
              return std::tie(a.patient_id, a.taken_at_us) < std::tie(b.patient_id, b.taken_at_us);
            });
  return result;
}

}  // namespace vicc_anatomy_viz
