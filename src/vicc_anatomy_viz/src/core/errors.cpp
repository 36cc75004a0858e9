#include "vicc_anatomy_viz/errors.hpp"

#include <sstream>

namespace vicc_anatomy_viz {

std::string joinProblems(const std::vector<std::string>& problems, std::size_t max_listed) {
  std::ostringstream out;
  for (std::size_t i = 0; i < problems.size() && i < max_listed; ++i) {
    out << (i == 0 ? "" : "\n") << "  - " << problems[i];
  }
  if (problems.size() > max_listed) {
    out << "\n  ... and " << (problems.size() - max_listed) << " more";
  }
  return out.str();
}

namespace {
std::string validationMessage(const std::vector<std::string>& problems) {
  std::ostringstream out;
  out << problems.size() << (problems.size() == 1 ? " problem" : " problems")
      << ", nothing was written:\n"
      << joinProblems(problems);
  return out.str();
}
}  // namespace

ValidationError::ValidationError(std::vector<std::string> problems)
    : std::runtime_error(validationMessage(problems)), problems_(std::move(problems)) {}

StoreError::StoreError(Kind kind, const std::string& message)
    : std::runtime_error(message), kind_(kind) {}

}  // namespace vicc_anatomy_viz
