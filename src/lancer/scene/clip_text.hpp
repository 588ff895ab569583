// A cutting plane written as text, as the command line's --clip and Python's clip= take it:
// AXIS=VALUE (x=0.5 removes x > 0.5, -z=0 removes z < 0) or PX,PY,PZ,NX,NY,NZ (a point on the
// plane, then the normal of the removed side), the plane [[clip]] describes.
#pragma once

#include <string>

#include "lancer/scene/scene_description.hpp"
#include "lancer/util/input_error.hpp"

namespace lancer {

// The plane `text` says (its normal as given: applyRenderOverrides checks and normalises it); an
// InputError at `where` (the option) when it says none.
ClipSettings clipFromText(const std::string& text, const SourceLocation& where);

}  // namespace lancer
