#pragma once
// Error types of the patient-status core. Every message names the offending item (a
// configuration entry, a finding, a file) so that a user can fix it without a debugger.

#include <stdexcept>
#include <string>
#include <vector>

namespace vicc_anatomy_viz {

/// An invalid view/anatomy configuration (uniqueness rules, local injectivity, bad YAML).
class ConfigError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Input that does not fit the view: the whole batch is rejected, every problem is listed.
class ValidationError : public std::runtime_error {
 public:
  explicit ValidationError(std::vector<std::string> problems);
  const std::vector<std::string>& problems() const { return problems_; }

 private:
  std::vector<std::string> problems_;
};

/// The record database could not do what was asked. `kind` lets callers tell a locked
/// database (try again later) from a corrupt or foreign file (needs a person).
class StoreError : public std::runtime_error {
 public:
  enum class Kind { kLocked, kCorrupt, kForeign, kNewerSchema, kIo, kNotFound, kConflict, kOther };
  StoreError(Kind kind, const std::string& message);
  Kind kind() const { return kind_; }

 private:
  Kind kind_;
};

/// A malformed exchange document (our JSON format, FHIR) that cannot even be read.
class ExchangeError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Joins problems into one message, at most `max_listed` of them plus a count of the rest.
std::string joinProblems(const std::vector<std::string>& problems, std::size_t max_listed = 20);

}  // namespace vicc_anatomy_viz
