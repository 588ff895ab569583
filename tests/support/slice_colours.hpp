// A slice's colour at every pixel, for the volume tests whose oracle is a linear field: the unit
// cube seen straight down at its slice z = 0.3, unlit, f = x + 2y + 3z on viridis over [0, 6].
#pragma once

#include <string>

#include "support/files.hpp"

namespace lancer::test {

// The scene, `side` pixels square: orthographic straight down at z = 0.3, unlit, a light above; its
// [[mesh]] has `fileKeys` (file, views) and color_by f over [0, 6], then `rest` (more of the mesh's
// keys and what follows it: a [[mesh.slice]], a [[clip]]).
std::string topViewSliceScene(int side, const std::string& fileKeys, const std::string& rest);

// Renders `scene` with the CLI in `folder` and checks every pixel that sees the unit square at
// z = 0.3 (away from its border) against viridis at f there, within one 8-bit step; returns the
// pixels checked (0 when the CLI failed, which is a failure too).
int expectSliceColours(const ScratchFolder& folder, const std::string& scene);

}  // namespace lancer::test
