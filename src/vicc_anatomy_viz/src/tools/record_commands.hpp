#pragma once
// vicc_patient commands that keep the record as a whole: export, history, backup, restore and
// the integrity check (patient_cli.cpp dispatches to them).

#include <iosfwd>
#include <string>

#include "cli_command_line.hpp"
#include "vicc_anatomy_viz/patient_status_service.hpp"

namespace vicc_anatomy_viz::cli {

int commandExport(const CommandLine& line, PatientStatusService& service, std::ostream& out);
int commandHistory(const CommandLine& line, PatientStatusService& service, std::ostream& out);
int commandBackup(const CommandLine& line, PatientStatusService& service, std::ostream& out);
int commandRestore(const CommandLine& line, PatientStatusService& service, std::ostream& out);
int commandCheck(PatientStatusService& service, std::ostream& out);

}  // namespace vicc_anatomy_viz::cli
