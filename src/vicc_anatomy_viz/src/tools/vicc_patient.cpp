// vicc_patient: patient records and their visual encoding from the command line (the same
// core as the patient_status_server node). See `vicc_patient --help`.
#include <iostream>
#include <string>
#include <vector>

#include "vicc_anatomy_viz/patient_cli.hpp"

int main(int argc, char** argv) {
  const std::vector<std::string> args(argv + 1, argv + argc);
  return vicc_anatomy_viz::runPatientCli(args, std::cout, std::cerr);
}
