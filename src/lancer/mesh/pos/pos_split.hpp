// Where a large .pos file can be cut for parsing on several threads: at the start of a line that
// begins with an element (ST(...), VQ2(...)), a guess each piece's parser confirms. The reader only
// uses a piece whose start the serial parse reaches exactly, inside a view, so a wrong guess (a cut
// inside a comment that looks like an element) costs time, never a different result.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

namespace lancer {

// A piece below this is parsed on the thread that reaches it: threads cost more than they save.
inline constexpr std::size_t kMinPosPieceBytes = std::size_t{1} << 20;

// Up to pieces - 1 cut points, increasing, each the first character of an element code at the start
// of a line, found from evenly spaced offsets forward; fewer where none is found.
std::vector<const char*> posPieceStarts(std::span<const char> bytes, std::size_t pieces);

}  // namespace lancer
