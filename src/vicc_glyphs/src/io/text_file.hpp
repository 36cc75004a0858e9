#pragma once
// Reading whole input files with a size limit, so that no importer can be made to allocate
// without bound.

#include <cstddef>
#include <string>

namespace vicc_glyphs {
namespace io_detail {

/// Largest input file any importer accepts (bytes).
constexpr std::size_t kMaxInputFileBytes = 64u * 1024u * 1024u;

/// Returns the file's content; throws FormatError if it cannot be read or is too large.
std::string readTextFile(const std::string& path);

/// Writes `text` to `path`; throws FormatError on failure.
void writeTextFile(const std::string& path, const std::string& text);

}  // namespace io_detail
}  // namespace vicc_glyphs
