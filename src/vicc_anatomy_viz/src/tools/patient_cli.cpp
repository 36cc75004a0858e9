#include "vicc_anatomy_viz/patient_cli.hpp"

#include <cstdio>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <set>
#include <sstream>

#include "cli_command_line.hpp"
#include "record_commands.hpp"
#include "vicc_anatomy_viz/encoded_status_json.hpp"
#include "vicc_anatomy_viz/errors.hpp"
#include "vicc_anatomy_viz/fhir_bundle.hpp"
#include "vicc_anatomy_viz/patient_status_service.hpp"
#include "vicc_anatomy_viz/record_json.hpp"
#include "vicc_anatomy_viz/time_format.hpp"

namespace vicc_anatomy_viz {

namespace {

using cli::commandBackup;
using cli::commandCheck;
using cli::commandExport;
using cli::commandHistory;
using cli::CommandLine;
using cli::commandRestore;
using cli::UsageError;

PatientStatusConfig serviceConfig(const CommandLine& line) {
  PatientStatusConfig config;
  config.encoding_config = line.option("--config", defaultEncodingConfigPath());
  config.anatomy_config = line.option("--anatomy", defaultAnatomyConfigPath());
  config.view_id = line.option("--view", config.view_id);
  config.store.path = line.option("--db", defaultDatabasePath());
  config.store.busy_timeout_ms = line.integerOption("--busy-timeout", 5000);
  config.store.read_only = cli::kReadCommands.count(line.command) > 0;
  config.plausibility.max_future_seconds = line.integerOption("--max-future", 24 * 3600);
  return config;
}

std::string hexColor(const Rgba& color) {
  char buffer[16];
  auto byte = [](float v) { return static_cast<int>(v * 255.0f + 0.5f); };
  std::snprintf(buffer, sizeof(buffer), "#%02x%02x%02x", byte(color.r), byte(color.g),
                byte(color.b));
  return buffer;
}

/// Reads a records document of ours or a FHIR Bundle; prints the import's warnings.
std::vector<Examination> readExaminations(const CommandLine& line, const std::string& path,
                                          const EncodingModel& model, std::ostream& err) {
  const nlohmann::json document = parseJsonText(readTextFile(path), path);
  TimePlausibility plausibility;
  plausibility.max_future_seconds = line.integerOption("--max-future", 24 * 3600);
  std::vector<std::string> warnings;
  std::vector<Examination> examinations;
  if (isFhirBundle(document)) {
    FhirImportOptions options;
    options.skip_unknown = line.flag("--skip-unknown");
    options.grouping_window_seconds = line.integerOption("--group-window", 600);
    options.plausibility = plausibility;
    FhirImport imported = examinationsFromFhirBundle(document, model, options);
    warnings = std::move(imported.warnings);
    examinations = std::move(imported.examinations);
  } else {
    JsonImportOptions options;
    options.plausibility = plausibility;
    examinations = examinationsFromJson(document, "json", &warnings, options);
  }
  for (const auto& warning : warnings) err << "warning: " << path << ": " << warning << "\n";
  return examinations;
}

WriteMode writeMode(const CommandLine& line) {
  if (line.flag("--replace-with-empty")) return WriteMode::kReplaceEvenWithEmpty;
  return line.flag("--replace") ? WriteMode::kReplace : WriteMode::kRejectExisting;
}

/// "preliminary, partial (2 observations not imported)"; "" for a complete final one.
std::string completeness(ExaminationStatus status, bool partial, const std::string& reason) {
  std::string text = status == ExaminationStatus::kPreliminary ? "PRELIMINARY" : "";
  if (partial) text += (text.empty() ? "" : ", ") + std::string("PARTIAL (") + reason + ")";
  return text;
}

int commandImport(const CommandLine& line, PatientStatusService& service, std::ostream& out,
                  std::ostream& err, bool single) {
  line.expectPositional(1);
  const std::string& path = line.positional.front();
  auto examinations = readExaminations(line, path, service.model(), err);
  if (single && examinations.size() != 1) {
    throw ValidationError({path + ": record takes exactly one examination, the file holds " +
                           std::to_string(examinations.size()) + " (use import)"});
  }
  std::set<std::string> patients;
  for (const auto& examination : examinations) patients.insert(examination.patient_id);
  const WriteMode mode = writeMode(line);
  const Examination first = examinations.empty() ? Examination() : examinations.front();
  const std::size_t written = service.record(std::move(examinations), mode);
  if (single) {
    out << "recorded " << first.describe() << " in " << service.config().store.path << "\n";
  } else {
    out << "imported " << written << " examination(s) of " << patients.size() << " patient(s) from "
        << path << " into " << service.config().store.path << "\n";
  }
  return 0;
}

int commandList(PatientStatusService& service, std::ostream& out) {
  const auto patients = service.listPatients();
  out << std::left << std::setw(20) << "patient" << std::setw(14) << "examinations" << std::setw(22)
      << "first"
      << "last\n";
  for (const auto& patient : patients) {
    out << std::setw(20) << patient.patient_id << std::setw(14) << patient.examination_count
        << std::setw(22)
        << (patient.examination_count ? formatTimestamp(patient.first_examination) : "-")
        << (patient.examination_count ? formatTimestamp(patient.last_examination) : "-") << "\n";
  }
  return 0;
}

int commandShow(const CommandLine& line, PatientStatusService& service, std::ostream& out) {
  const std::string patient = line.required("--patient");
  const std::string date = line.option("--date");
  const auto examination = service.examinationAt(patient, date);
  if (!examination) {
    out << "patient " << patient << " has no examination at or before " << date << "\n";
    return 0;
  }
  const EncodingModel& model = service.model();
  out << "patient " << patient << ", examination " << formatTimestamp(examination->taken_at_us)
      << " (view " << examination->view_id << ", source " << examination->source << ")\n";
  const std::string incomplete =
      completeness(examination->status, examination->partial, examination->partial_reason);
  if (!incomplete.empty()) out << "  " << incomplete << "\n";
  if (examination->findings.empty()) {
    out << "  no findings recorded"
        << (examination->partial ? " (partial: missing findings are unknown)" : "") << "\n";
  }
  for (const auto& finding : examination->findings) {
    const Category* category = model.config().category(finding.category);
    const Structure* structure = model.anatomy().structure(finding.structure);
    out << "  " << std::left << std::setw(20) << (category ? category->label : finding.category)
        << std::setw(44)
        << (structure ? model.anatomy().displayName(*structure, finding.side) : finding.structure);
    for (const auto& [prop_type, value] : finding.values) {
      out << " " << prop_type << "=" << value.toString();
    }
    out << "\n";
  }
  return 0;
}

void printStatus(const EncodedStatus& status, std::ostream& out) {
  if (!status.has_examination) {
    out << "patient " << status.patient_id << ": no examination at or before "
        << status.requested_date << "\n";
    return;
  }
  out << "patient " << status.patient_id << ", examination "
      << formatTimestamp(status.examination_time) << ", view " << status.view_id << "\n";
  const std::string incomplete =
      completeness(status.examination_status, status.partial, status.partial_reason);
  if (!incomplete.empty()) out << "  " << incomplete << "\n";
  if (status.structures.empty()) {
    out << (status.partial ? "  no abnormal findings among what was recorded (partial "
                             "examination: the rest is unknown)\n"
                           : "  no abnormal findings\n");
  }
  for (const auto& entry : status.structures) {
    out << "  " << std::left << std::setw(20) << entry.category << std::setw(44)
        << entry.display_name << hexColor(entry.color) << "  level " << entry.intensity_level << "/"
        << entry.intensity_levels;
    if (!entry.texture_id.empty()) {
      out << "  texture " << entry.texture_id << " " << entry.texture_level << "/"
          << entry.texture_levels;
    }
    if (entry.proxy) out << "  proxy";
    if (entry.alternation_group >= 0) out << "  alternates(" << entry.alternation_group << ")";
    out << "\n      " << entry.overlay_text << "\n";
  }
  for (const auto& alternation : status.alternations) {
    out << "  alternating on " << alternation.display_name << ":";
    for (const auto& category : alternation.categories) out << " " << category;
    out << "\n";
  }
  for (const auto& note : status.notes) out << "  note: " << note << "\n";
}

int commandEncode(const CommandLine& line, PatientStatusService& service, std::ostream& out) {
  const EncodedStatus status = service.encodedStatus(
      line.required("--patient"), line.option("--date"), cli::splitList(line.option("--hide")));
  if (line.flag("--json")) {
    out << toJson(status).dump(2) << "\n";
  } else {
    printStatus(status, out);
  }
  return 0;
}

int commandConfig(PatientStatusService& service, std::ostream& out) {
  const EncodingModel& model = service.model();
  const View& view = service.view();
  out << "view " << view.id << ": " << view.label << "\n";
  for (const auto& entry : view.categories) {
    const Category& category = model.category(entry.category);
    out << "  " << std::left << std::setw(20) << category.id << std::setw(8) << entry.hue;
    for (std::size_t i = 0; i < category.spatial_refs.size(); ++i) {
      out << (i ? "|" : "") << category.spatial_refs[i];
    }
    out << "\n";
    for (const auto& prop : category.props) {
      const LevelMapping& levels = model.levels(category.id, prop.prop_type);
      out << "      " << std::setw(14) << prop.prop_type << std::setw(12)
          << toString(prop.domain.type) << std::setw(32) << prop.domain.describe() << " "
          << prop.visual_variable << " (" << levels.levelCount() << ")"
          << (levels.quantized() ? " quantized" : "") << "\n";
    }
  }
  for (const auto& note : model.notes(view)) out << "note: " << note << "\n";
  for (const auto& warning : model.report().global_warnings) out << "warning: " << warning << "\n";
  return 0;
}

/// Says what is wrong with the database files (e.g. readable by others) whenever a command
/// opened them, also when the command failed.
struct StoreWarningsOnExit {
  PatientStatusService& service;
  std::ostream& err;
  ~StoreWarningsOnExit() {
    if (!service.storeIsOpen()) return;
    for (const auto& warning : service.store().warnings()) err << "warning: " << warning << "\n";
  }
};

int dispatch(const CommandLine& line, std::ostream& out, std::ostream& err) {
  PatientStatusService service(serviceConfig(line));
  const StoreWarningsOnExit warn_about_files{service, err};
  const std::string& command = line.command;
  if (command == "init") {
    line.expectPositional(0);
    RecordStore& store = service.store();
    out << "patient database ready: " << store.path() << " (schema version "
        << store.schemaVersion() << ")\n";
    return 0;
  }
  if (command == "import") return commandImport(line, service, out, err, false);
  if (command == "record") return commandImport(line, service, out, err, true);
  if (command == "export") return commandExport(line, service, out);
  if (command == "list") return commandList(service, out);
  if (command == "dates") {
    for (const auto time : service.examinationDates(line.required("--patient"))) {
      out << formatTimestamp(time) << "\n";
    }
    return 0;
  }
  if (command == "show") return commandShow(line, service, out);
  if (command == "encode") return commandEncode(line, service, out);
  if (command == "check") return commandCheck(service, out);
  if (command == "history") return commandHistory(line, service, out);
  if (command == "backup") return commandBackup(line, service, out);
  if (command == "restore") return commandRestore(line, service, out);
  if (command == "config") return commandConfig(service, out);
  throw UsageError("unknown command '" + command + "'");
}

}  // namespace

std::string patientCliUsage() {
  return "usage: vicc_patient <command> [options]\n"
         "commands:\n"
         "  init                                  create or migrate the database\n"
         "  import FILE [--replace [--replace-with-empty]] [--skip-unknown]\n"
         "         [--group-window S] [--max-future S]\n"
         "                                        import our JSON records or a FHIR R4 Bundle\n"
         "  export [--patient P] [--format json|fhir] [--out FILE]\n"
         "                                        (FILE is written 0600; never the database)\n"
         "  list                                  patients with examination counts\n"
         "  dates --patient P                     examination dates, oldest first\n"
         "  show --patient P [--date D]           recorded findings at or before D\n"
         "  encode --patient P [--date D] [--json] [--hide CAT,...]\n"
         "                                        visually encoded status at or before D\n"
         "  record FILE [--replace [--replace-with-empty]]\n"
         "                                        record one examination\n"
         "  history --patient P                   examinations and their superseded versions\n"
         "  check                                 database integrity check\n"
         "  backup --out FILE                     consistent copy (online, 0600)\n"
         "  restore FILE                          replace the record by a backup (the current\n"
         "                                        one is first saved next to the database)\n"
         "  config                                the view's encoding and its reports\n"
         "options for all commands:\n"
         "  --db FILE          patient database (default ~/.ros/vicc/patients.db)\n"
         "  --config FILE      encoding configuration (default: the package's)\n"
         "  --anatomy FILE     anatomy catalogue (default: the package's)\n"
         "  --view ID          view (default neurological_status_sdh)\n"
         "  --busy-timeout MS  wait for a locked database (default 5000)\n"
         "import options:\n"
         "  --replace           an examination at a recorded time replaces it; the old version\n"
         "                      is kept as history (see history)\n"
         "  --replace-with-empty  also when the new examination has no findings\n"
         "  --skip-unknown      import what is known; the examination is stored as PARTIAL\n"
         "  --group-window S    FHIR observations naming no examination group per patient\n"
         "                      within S seconds (default 600)\n"
         "  --max-future S      reject examination times more than S s ahead (default 86400)\n"
         "read commands (list, dates, show, encode, export, history, check, backup) open the\n"
         "database read-only and never create it.\n"
         "dates: YYYY-MM-DD (the end of that day) or YYYY-MM-DDTHH:MM[:SS[.ffffff]][Z|+HH:MM]\n";
}

int runPatientCli(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  try {
    const CommandLine line = cli::parseCommandLine(args);
    if (line.flag("--help") || line.command.empty()) {
      (line.command.empty() && !line.flag("--help") ? err : out) << patientCliUsage();
      return line.command.empty() && !line.flag("--help") ? 2 : 0;
    }
    if (!cli::kCommands.count(line.command))
      throw UsageError("unknown command '" + line.command + "'");
    return dispatch(line, out, err);
  } catch (const UsageError& e) {
    err << "vicc_patient: " << e.what() << "\n" << patientCliUsage();
    return 2;
  } catch (const std::exception& e) {
    err << "vicc_patient: error: " << e.what() << "\n";
    return 1;
  }
}

}  // namespace vicc_anatomy_viz
