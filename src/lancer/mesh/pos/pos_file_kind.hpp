// What a file given as a mesh or a view is: a list-based .pos view (recognised by its first
// token), and the files given as one that are something else: an empty file, a .msh mesh, gmsh's
// older $PostFormat view files (ASCII or binary), binary data. Each of those is refused with what it
// looks like and, where gmsh can convert it, the command that does.
#pragma once

#include <span>
#include <string>

namespace lancer {

// Throws InputError (file, and line:col where there is one) when `bytes` cannot be a list-based .pos
// file; returns otherwise. file: the name errors show (its stem names the converted file).
void refuseOtherFormats(std::span<const char> bytes, const std::string& file);

// Whether the bytes (the whole file or its first few KiB) start like a gmsh view file: `View` after
// whitespace and // or /* */ comments (the list-based format), or $PostFormat (gmsh's older one,
// which the reader refuses with the command that converts it).
bool looksLikePosFile(std::span<const char> head);

}  // namespace lancer
