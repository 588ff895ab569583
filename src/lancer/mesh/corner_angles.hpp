// The interior angles of faces at their corners: the weights of a face in its vertices' smooth
// normals (vertex_normals.hpp). With AVX2, eight faces at a time: an animation of a deformed mesh
// computes its normals again every frame, and these angles (edge lengths and arc cosines) are most
// of that work. A face's angles never depend on the faces computed with it, so a face alone gets
// the same bits as in a block.
#pragma once

#include <array>
#include <span>

#include "lancer/mesh/mesh.hpp"

namespace lancer {

// angles[i]: the angles of faces[i] at its corners, in radians (a triangle's fourth is 0).
void cornerAnglesOf(std::span<const Vec3> positions, std::span<const MeshFace> faces,
                    std::array<float, 4>* angles);

}  // namespace lancer
