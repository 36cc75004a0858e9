#include "record_commands.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <ctime>
#include <ostream>
#include <set>
#include <utility>

#include "vicc_anatomy_viz/database_files.hpp"
#include "vicc_anatomy_viz/errors.hpp"
#include "vicc_anatomy_viz/fhir_bundle.hpp"
#include "vicc_anatomy_viz/record_json.hpp"
#include "vicc_anatomy_viz/time_format.hpp"

namespace vicc_anatomy_viz::cli {

namespace {

/// Writes patient data as a private file (0600), atomically: a failed write leaves any
/// earlier file as it was.
void writePrivateFile(const std::string& path, const std::string& text) {
  const std::string temporary = path + ".part";
  const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0600);
  bool ok = fd >= 0 && ::fchmod(fd, 0600) == 0;
  for (std::size_t done = 0; ok && done < text.size();) {
    const ssize_t written = ::write(fd, text.data() + done, text.size() - done);
    ok = written > 0;
    if (ok) done += static_cast<std::size_t>(written);
  }
  ok = ok && ::fsync(fd) == 0;
  if (fd >= 0) ok = ::close(fd) == 0 && ok;
  if (!ok || ::rename(temporary.c_str(), path.c_str()) != 0) {
    ::unlink(temporary.c_str());
    throw ExchangeError("cannot write '" + path + "': " + std::strerror(errno));
  }
}

}  // namespace

int commandExport(const CommandLine& line, PatientStatusService& service, std::ostream& out) {
  const std::string format = line.option("--format", "json");
  if (format != "json" && format != "fhir") throw UsageError("--format is json or fhir");
  const std::string path = line.option("--out");
  if (!path.empty() && isDatabaseOrCompanion(path, service.config().store.path)) {
    throw ExchangeError("--out '" + path +
                        "' is the patient database (or its journal); refusing "
                        "to overwrite it");
  }
  const std::string patient = line.option("--patient");
  const auto examinations = service.store().examinations(patient);
  const auto history = service.store().history(patient);
  nlohmann::json document;
  if (format == "fhir") {
    std::set<std::pair<std::string, TimestampUs>> amended;
    for (const auto& version : history) {
      amended.emplace(version.examination.patient_id, version.examination.taken_at_us);
    }
    document = examinationsToFhirBundle(examinations, service.model(), amended);
  } else {
    document = recordsToJson(examinations, history);
  }
  const std::string text = document.dump(2) + "\n";
  if (path.empty()) {
    out << text;
    return 0;
  }
  writePrivateFile(path, text);
  out << "exported " << examinations.size() << " examination(s) to " << path << "\n";
  return 0;
}

int commandHistory(const CommandLine& line, PatientStatusService& service, std::ostream& out) {
  const std::string patient = line.required("--patient");
  const auto current = service.store().examinations(patient);
  const auto history = service.store().history(patient);
  out << "patient " << patient << ": " << current.size() << " examination(s), " << history.size()
      << " superseded version(s)\n";
  for (const auto& examination : current) {
    out << "  " << formatTimestamp(examination.taken_at_us) << "  current     recorded "
        << formatTimestamp(examination.recorded_at * kMicrosPerSecond) << " from "
        << examination.source << ", " << examination.findings.size() << " finding(s)\n";
    for (const auto& version : history) {
      if (version.examination.taken_at_us != examination.taken_at_us) continue;
      out << "  " << std::string(formatTimestamp(examination.taken_at_us).size(), ' ')
          << "  superseded  recorded "
          << formatTimestamp(version.examination.recorded_at * kMicrosPerSecond) << " from "
          << version.examination.source << ", " << version.examination.findings.size()
          << " finding(s); replaced " << formatTimestamp(version.superseded_at * kMicrosPerSecond)
          << " from " << version.replaced_by_source << "\n";
    }
  }
  return 0;
}

int commandBackup(const CommandLine& line, PatientStatusService& service, std::ostream& out) {
  line.expectPositional(0);
  const std::string path = line.required("--out");
  service.store().backupTo(path);
  out << "backed up " << service.config().store.path << " to " << path << " (mode 0600)\n";
  return 0;
}

/// Replaces the record by a backup; the current record is kept as a backup of its own first,
/// so that a restore of the wrong file can be undone.
int commandRestore(const CommandLine& line, PatientStatusService& service, std::ostream& out) {
  line.expectPositional(1);
  const std::string& backup = line.positional.front();
  RecordStore& store = service.store();
  const std::string safety = store.path() + ".before-restore-" +
                             std::to_string(static_cast<long long>(std::time(nullptr)));
  store.backupTo(safety);
  store.restoreFrom(backup);
  out << "restored " << store.path() << " from " << backup << "; the previous record is kept in "
      << safety << "\n";
  return 0;
}

int commandCheck(PatientStatusService& service, std::ostream& out) {
  RecordStore& store = service.store();
  const auto rows = store.integrityCheck();
  const bool ok = rows.size() == 1 && rows.front() == "ok";
  out << store.path() << ": schema version " << store.schemaVersion() << ", integrity "
      << (ok ? "ok" : "FAILED") << "\n";
  if (!ok) {
    for (const auto& row : rows) out << "  " << row << "\n";
  }
  return ok ? 0 : 1;
}

}  // namespace vicc_anatomy_viz::cli
