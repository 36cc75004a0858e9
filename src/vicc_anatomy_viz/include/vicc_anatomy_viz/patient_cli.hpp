#pragma once
// The `vicc_patient` command line: init, import, export, list, dates, show, encode, record,
// check. Kept in the library (streams in, exit code out) so that it is unit-tested.

#include <iosfwd>
#include <string>
#include <vector>

namespace vicc_anatomy_viz {

/// Runs one command line (without the program name). Returns the exit code: 0 success,
/// 1 failure (message on `err`), 2 usage error.
int runPatientCli(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

std::string patientCliUsage();

}  // namespace vicc_anatomy_viz
