#include "text_file.hpp"

#include <fstream>
#include <sstream>

#include "vicc_glyphs/io/format_error.hpp"

namespace vicc_glyphs {
namespace io_detail {

std::string readTextFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  if (!in) throw FormatError(path, "", "cannot open file");
  const std::streamoff size = in.tellg();
  if (size < 0) throw FormatError(path, "", "cannot determine file size");
  if (static_cast<std::size_t>(size) > kMaxInputFileBytes) {
    throw FormatError(path, "",
                      "file larger than " + std::to_string(kMaxInputFileBytes) + " bytes");
  }
  std::string text(static_cast<std::size_t>(size), '\0');
  in.seekg(0);
  if (!in.read(text.data(), size)) throw FormatError(path, "", "cannot read file");
  return text;
}

void writeTextFile(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (!out) throw FormatError(path, "", "cannot open file for writing");
  out << text;
  out.flush();
  if (!out) throw FormatError(path, "", "write failed");
}

}  // namespace io_detail
}  // namespace vicc_glyphs
