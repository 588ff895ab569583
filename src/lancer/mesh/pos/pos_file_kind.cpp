#include "lancer/mesh/pos/pos_file_kind.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <string_view>

#include "lancer/mesh/pos/pos_scanner.hpp"

namespace lancer {
namespace {

// The first byte that no text file holds (NUL and the control characters other than whitespace),
// within the first 4 KiB; npos when there is none.
std::size_t firstBinaryByte(std::string_view text) {
  text = text.substr(0, 4096);
  for (std::size_t i = 0; i < text.size(); ++i) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (c < 32 && c != '\t' && c != '\n' && c != '\r' && c != '\f' && c != '\v') return i;
  }
  return std::string_view::npos;
}

// "1.3 1 8" after $PostFormat: version, file type (0 ASCII, 1 binary), size of a double.
std::string describePostFormat(std::string_view rest) {
  const std::size_t line = rest.find('\n');
  rest = line == std::string_view::npos ? std::string_view{} : rest.substr(line + 1);
  const std::size_t end = std::min(rest.find('\n'), std::size_t{32});
  std::string_view header = rest.substr(0, end);
  std::string version(header.substr(0, header.find(' ')));
  header.remove_prefix(std::min(header.size(), version.size() + 1));
  const bool binary = !header.empty() && header.front() == '1';
  return fmt::format("{} {}", binary ? "binary" : "ASCII", version.empty() ? "" : "version " + version);
}

}  // namespace

bool looksLikePosFile(std::span<const char> head) {
  std::string_view text(head.data(), head.size());
  for (;;) {
    const std::size_t start = text.find_first_not_of(" \t\r\n\f\v");
    if (start == std::string_view::npos) return false;
    text.remove_prefix(start);
    if (text.starts_with("//")) {
      const std::size_t end = text.find('\n');
      if (end == std::string_view::npos) return false;
      text.remove_prefix(end);
    } else if (text.starts_with("/*")) {
      const std::size_t end = text.find("*/", 2);
      if (end == std::string_view::npos) return false;
      text.remove_prefix(end + 2);
    } else {
      break;
    }
  }
  if (text.starts_with("$PostFormat")) return true;
  if (!text.starts_with("View")) return false;
  text.remove_prefix(4);
  return !text.empty() &&
         (text.front() == '"' || std::string_view(" \t\r\n").find(text.front()) != text.npos);
}

void refuseOtherFormats(std::span<const char> bytes, const std::string& file) {
  const std::string_view text(bytes.data(), bytes.size());
  if (text.empty())
    throw InputError(
        SourceLocation{file},
        "the file is empty: a list-based .pos file holds views like View \"name\" { ST(...){...}; };");
  PosScanner scan(bytes, file);
  scan.skipSpace();
  const char* at = scan.position();
  const std::string_view rest(at, static_cast<std::size_t>(text.data() + text.size() - at));
  if (rest.starts_with("$MeshFormat") || rest.starts_with("$NOD") || rest.starts_with("$NOE"))
    scan.failAt(at, "this is a gmsh mesh (.msh), not a list-based .pos view: give it to lancer as a mesh");
  if (rest.starts_with("$PostFormat")) {
    const std::string stem = std::filesystem::path(file).stem().string();
    scan.failAt(at,
                fmt::format("this is a view in gmsh's older post-processing format ($PostFormat, {}), which "
                            "lancer does not read: convert it to a text view by writing "
                            "'PostProcessing.Format = 2; Save View[0] \"{}_text.pos\";' in save.geo and "
                            "running 'gmsh {} save.geo -' (Save View[1], ... for its other views)",
                            describePostFormat(rest), stem, file));
  }
  const std::size_t binary = firstBinaryByte(text);
  if (binary != std::string_view::npos)
    throw InputError(
        SourceLocation{file},
        fmt::format("this is binary data (byte 0x{:02x} at offset {}), not a list-based .pos file, "
                    "which is text: views like View \"name\" {{ ST(...){{...}}; }};",
                    static_cast<unsigned char>(text[binary]), binary));
}

}  // namespace lancer
