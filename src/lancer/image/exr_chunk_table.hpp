// The header and chunk table of an OpenEXR file, checked against the file's bytes before OpenEXR
// allocates what they say: it checks an attribute or a chunk only as it reads it.
#pragma once

#include <cstdint>
#include <string>

namespace lancer {

// What the header says the scan-line chunks hold (OpenEXR file layout, "Line Offset Table" and
// "Scan Line Blocks").
struct ExrScanLineLayout {
  std::int64_t firstY = 0;         // the data window's min.y
  std::int64_t height = 0;         // rows in the data window
  std::int64_t linesPerChunk = 1;  // of the compression
  std::uint64_t bytesPerRow = 0;   // one decoded row of every channel
  std::uint64_t largestRatio = 0;  // decoded bytes per stored byte at most; 0 when not bounded
};

// Throws InputError naming `path` unless the single-part scan-line file at `path` (of `fileBytes`
// bytes) has, after its header, a table of one offset per chunk, each to a chunk inside the file that
// starts with the chunk's first row, no two chunks overlapping, and each large enough to hold its rows
// at the compression's largest ratio. Multi-part, tiled and deep files are left to OpenEXR.
// Throws InputError naming `path` when an attribute of the header (of any part) says its value is longer
// than the bytes left in the file (`fileBytes`): OpenEXR allocates an attribute of a type it does not
// know at the size the file gives (up to 2 GiB) before it reads it. Anything else is OpenEXR's to judge.
void checkExrHeaderSizes(const std::string& path, std::uint64_t fileBytes);

void checkExrScanLineChunks(const std::string& path, std::uint64_t fileBytes,
                            const ExrScanLineLayout& layout);

}  // namespace lancer
