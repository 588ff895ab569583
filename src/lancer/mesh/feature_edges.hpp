// Feature edges of a surface mesh, for `edges = { only = "features" }`: the outline a drawing
// shows (open boundaries, boundaries between physical groups, creases sharper than an angle)
// instead of every element edge.
#pragma once

#include <cstdint>
#include <vector>

#include "lancer/mesh/mesh.hpp"

namespace lancer {

// One edge mask per face (bit i: corner i to corner i+1), set where the edge is a feature: shared
// by no other face, shared with a face of another physical group, or shared with a face whose
// normal differs by more than creaseDegrees. Edges shared by three or more faces count as
// features. Element-internal edges (cleared in mesh.faceEdgeMask) are never features.
std::vector<std::uint8_t> featureEdgeMasks(const Mesh& mesh, float creaseDegrees);

}  // namespace lancer
