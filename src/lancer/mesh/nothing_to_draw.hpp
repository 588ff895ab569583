// Why a mesh that loaded has no face to render (only lines, an empty $Elements, Physical Volumes
// meshed in 2D, ...): `render` and `animate` refuse such a mesh with this reason, `info` prints it.
#pragma once

#include <string>

#include "lancer/mesh/mesh.hpp"

namespace lancer {

// "" when the mesh has a face to draw; otherwise the reason and what to do, as one sentence.
std::string nothingToDrawReason(const Mesh& mesh);

}  // namespace lancer
