// What a face contributes to its vertices' smooth normals (vertex_normals.hpp): its unit normal
// (faceNormal's formula) and the interior angles at its corners, its weights. With AVX2 (the
// x86-64-v3 copy), eight faces at a time: an animation of a deformed mesh computes its normals again every
// frame, and these terms (edge lengths, arc cosines, square roots) are most of that work. A face's terms
// never depend on the faces computed with it, so a face alone gets the same bits as in a block.
#pragma once

#include <array>
#include <span>

#include "lancer/mesh/mesh.hpp"
#include "lancer/util/isa.hpp"

namespace lancer {

// normals[i] and angles[i] (radians; a triangle's fourth is 0) for faces[i]. Returns false when
// some face is not clearly far from degenerate (twice its area under 1e-5 of its longest edge
// squared; isDegenerateFace, face_geometry.hpp, draws the line at 1e-12).
// On the copy of face_terms.cpp for the CPU (util/isa.hpp: x86-64-v3 takes eight faces at a time).
template <typename Isa>
bool faceTermsOn(std::span<const Vec3> positions, std::span<const MeshFace> faces, Vec3* normals,
                 std::array<float, 4>* angles);
inline bool faceTermsOf(std::span<const Vec3> positions, std::span<const MeshFace> faces, Vec3* normals,
                        std::array<float, 4>* angles) {
  return isa::dispatch(
      [&](auto isa) { return faceTermsOn<decltype(isa)>(positions, faces, normals, angles); });
}

}  // namespace lancer
