#pragma once
// The fuzz harnesses of the patient-record importers and the validator. Each is a plain
// function shared by the libFuzzer entry point (fuzz/run_fuzz.sh) and the regression gtest,
// so that a replayed input runs exactly the code the fuzzer ran. A harness returns 0 for
// every allowed outcome; anything else escapes as an exception (FuzzInvariantError for a
// broken property, any other type for an unexpected error), which libFuzzer reports as a
// crash and the gtest as a failure.

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "vicc_anatomy_viz/encoding_model.hpp"
#include "vicc_anatomy_viz/patient_record.hpp"

namespace vicc_anatomy_viz::fuzz {

/// A property the harness checks does not hold (e.g. an export does not import back).
class FuzzInvariantError : public std::logic_error {
 public:
  using std::logic_error::logic_error;
};

/// Our JSON import (parseJsonText + examinationsFromJson): a result, ExchangeError or
/// ValidationError; every imported value is the one written in the document.
int fuzzJsonImport(const std::uint8_t* data, std::size_t size);
/// FHIR import with skip_unknown false and true: a result, ExchangeError or ValidationError;
/// a bundle accepted strictly is imported identically when skipping unknown codes.
int fuzzFhirImport(const std::uint8_t* data, std::size_t size);
/// Examinations drawn from the bytes through ExaminationValidator::validate: what passes
/// encodes without throwing and comes back equal through our JSON export and import.
int fuzzValidator(const std::uint8_t* data, std::size_t size);

/// The shipped configuration and anatomy from the package source directory, loaded once.
const EncodingModel& fuzzModel();

// The only place the harnesses touch the examination time (its unit is about to change).
inline TimestampUs takenAtOf(const Examination& examination) { return examination.taken_at_us; }
inline void setTakenAt(Examination& examination, TimestampUs time) {
  examination.taken_at_us = time;
}
inline void setTakenAtSeconds(Examination& examination, std::int64_t seconds) {
  examination.taken_at_us = seconds * kMicrosPerSecond;
}

}  // namespace vicc_anatomy_viz::fuzz
