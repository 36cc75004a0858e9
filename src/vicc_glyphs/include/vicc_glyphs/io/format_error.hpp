#pragma once
// The single error type of all readers and importers: a file could not be turned into a valid
// DiffusionCurveImage. The message names the file (or "<string>"), the place and the problem.

#include <cstddef>
#include <stdexcept>
#include <string>

namespace vicc_glyphs {

struct FormatError : std::runtime_error {
  /// `source` is a file path or "<string>"; `place` says where (e.g. "line 12",
  /// "curve 3 control point 7", "path d offset 41"); `problem` says what is wrong.
  FormatError(const std::string& source, const std::string& place, const std::string& problem)
      : std::runtime_error(source + ": " + (place.empty() ? std::string() : place + ": ") +
                           problem) {}
  explicit FormatError(const std::string& message) : std::runtime_error(message) {}
};

/// Upper bound on the number of control points one file may produce (all curves together);
/// larger inputs are rejected with a FormatError instead of exhausting memory or time.
constexpr std::size_t kMaxControlPointsPerFile = 100000;

}  // namespace vicc_glyphs
