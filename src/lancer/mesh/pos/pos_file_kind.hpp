// Files given as a list-based .pos view that are something else: an empty file, a .msh mesh, gmsh's
// older $PostFormat view files (ASCII or binary), binary data. Each is refused with what it looks like
// and, where gmsh can convert it, the command that does.
#pragma once

#include <span>
#include <string>

namespace lancer {

// Throws InputError (file, and line:col where there is one) when `bytes` cannot be a list-based .pos
// file; returns otherwise. file: the name errors show (its stem names the converted file).
void refuseOtherFormats(std::span<const char> bytes, const std::string& file);

}  // namespace lancer
