#include "lancer/image/exr_chunk_table.hpp"

#include <algorithm>
#include <fstream>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "lancer/util/input_error.hpp"

namespace lancer {
namespace {

// The version field's flags (OpenEXR file layout, "Version Field").
constexpr std::uint32_t kTiled = 0x200, kDeep = 0x800, kMultiPart = 0x1000;

template <typename T>
bool readLittleEndian(std::istream& in, T& value) {
  unsigned char bytes[sizeof(T)];
  if (!in.read(reinterpret_cast<char*>(bytes), sizeof(T))) return false;
  std::uint64_t result = 0;
  for (std::size_t i = sizeof(T); i-- > 0;) result = (result << 8) | bytes[i];
  value = static_cast<T>(result);
  return true;
}

// Skips the header's attributes (name, type, size, value) up to the empty name that ends them.
bool skipHeader(std::istream& in) {
  for (;;) {
    std::string name, type;
    if (!std::getline(in, name, '\0') || name.size() > 255) return false;
    if (name.empty()) return true;
    std::int32_t size = 0;
    if (!std::getline(in, type, '\0') || !readLittleEndian(in, size) || size < 0) return false;
    if (!in.seekg(size, std::ios::cur)) return false;
  }
}

}  // namespace

void checkExrHeaderSizes(const std::string& path, std::uint64_t fileBytes) {
  constexpr std::uint32_t kMagic = 20000630;  // 76 2f 31 01
  std::ifstream in(path, std::ios::binary);
  std::uint32_t magic = 0, version = 0;
  if (!readLittleEndian(in, magic) || !readLittleEndian(in, version) || magic != kMagic) return;
  const bool multiPart = (version & kMultiPart) != 0;
  // A single part's header ends with an empty name; a multi-part file's headers, each so ended, end
  // with an empty header.
  for (bool partStarts = true;;) {
    std::string name, type;
    if (!std::getline(in, name, '\0') || name.size() > 255) return;
    if (name.empty()) {
      if (!multiPart || partStarts) return;
      partStarts = true;
      continue;
    }
    partStarts = false;
    std::int32_t size = 0;
    if (!std::getline(in, type, '\0') || type.size() > 255 || !readLittleEndian(in, size)) return;
    const auto at = static_cast<std::uint64_t>(in.tellg());
    if (size < 0 || at + static_cast<std::uint64_t>(size) > fileBytes)
      throw InputError(SourceLocation{path},
                       fmt::format("'{}' is truncated or corrupt: its header's attribute '{}' ({}) says its "
                                   "value is {} bytes, but the file has {} bytes after byte {}",
                                   path, name, type, size, fileBytes - std::min(at, fileBytes), at));
    if (!in.seekg(size, std::ios::cur)) return;
  }
}

void checkExrScanLineChunks(const std::string& path, std::uint64_t fileBytes,
                            const ExrScanLineLayout& layout) {
  std::ifstream in(path, std::ios::binary);
  std::uint32_t magic = 0, version = 0;
  if (!readLittleEndian(in, magic) || !readLittleEndian(in, version)) return;
  if ((version & (kTiled | kDeep | kMultiPart)) != 0 || !skipHeader(in)) return;  // OpenEXR's to judge
  const auto fail = [&](const std::string& what) {
    throw InputError(SourceLocation{path}, fmt::format("'{}' is truncated or corrupt: {}", path, what));
  };
  const std::uint64_t tableStart = static_cast<std::uint64_t>(in.tellg());
  const std::int64_t chunks = (layout.height + layout.linesPerChunk - 1) / layout.linesPerChunk;
  const std::uint64_t chunksStart = tableStart + 8 * static_cast<std::uint64_t>(chunks);
  if (chunksStart > fileBytes)
    fail(fmt::format("its table of {} chunks ends at byte {}, past the file's end ({} bytes)", chunks,
                     chunksStart, fileBytes));
  std::vector<std::uint64_t> offsets(static_cast<std::size_t>(chunks));
  for (std::uint64_t& offset : offsets)
    if (!readLittleEndian(in, offset)) fail("its table of chunks cannot be read");
  std::vector<std::pair<std::uint64_t, std::uint64_t>> extents;  // [start, end) of each chunk
  extents.reserve(offsets.size());
  for (std::int64_t i = 0; i < chunks; ++i) {
    const std::uint64_t offset = offsets[static_cast<std::size_t>(i)];
    const std::int64_t row = layout.firstY + i * layout.linesPerChunk;
    if (offset < chunksStart)
      fail(
          fmt::format("the chunk of row {} is at byte {}, inside the header or the chunk table (chunks "
                      "start at byte {})",
                      row, offset, chunksStart));
    if (offset > fileBytes - 8)
      fail(fmt::format("the chunk of row {} is at byte {}, but the file has {} bytes", row, offset,
                       fileBytes));
    std::int32_t y = 0, size = 0;
    in.seekg(static_cast<std::streamoff>(offset));
    if (!readLittleEndian(in, y) || !readLittleEndian(in, size)) fail("a chunk cannot be read");
    if (y != row) fail(fmt::format("the chunk of row {} at byte {} says it holds row {}", row, offset, y));
    const std::uint64_t end = offset + 8 + static_cast<std::uint64_t>(std::max(size, 0));
    if (size <= 0)
      fail(fmt::format("the chunk of row {} at byte {} says it holds {} bytes", row, offset, size));
    if (end > fileBytes)
      fail(fmt::format("the chunk of row {} at byte {} claims {} bytes, past the file's end ({} bytes)", row,
                       offset, size, fileBytes));
    const std::int64_t rows = std::min(layout.linesPerChunk, layout.height - i * layout.linesPerChunk);
    const std::uint64_t decoded = static_cast<std::uint64_t>(rows) * layout.bytesPerRow;
    if (layout.largestRatio != 0 && decoded > static_cast<std::uint64_t>(size) * layout.largestRatio)
      fail(fmt::format("the chunk of row {} holds {} bytes, too few for the {} bytes of its {} rows", row,
                       size, decoded, rows));
    extents.emplace_back(offset, end);
  }
  std::sort(extents.begin(), extents.end());
  for (std::size_t i = 1; i < extents.size(); ++i)
    if (extents[i].first < extents[i - 1].second)
      fail(fmt::format("two chunks overlap (at bytes {} and {})", extents[i - 1].first, extents[i].first));
}

}  // namespace lancer
