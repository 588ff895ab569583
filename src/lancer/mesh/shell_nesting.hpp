// Which closed shells are cavity walls: a shell nested inside an odd number of other closed shells of
// its physical group bounds a hole in that group's material, so its faces must point into the hole.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "lancer/mesh/face_shells.hpp"
#include "lancer/mesh/mesh.hpp"

namespace lancer {

// Per shell of `shells`: 1 when the shell is one of `candidates` (per shell, nonzero: closed and
// usable as a solid's boundary) and lies inside an odd number of the other candidates that share a
// physical tag with it (`facePhysicalTag` per face; empty: every face in one group). A shell of
// another group nested inside is a separate solid (a steel ball in a glass block), not a cavity.
// Inside is decided for one vertex of the inner shell by the parity of a ray's crossings with the
// outer shell's faces, in double, retrying another direction (or vertex) when the ray grazes an edge
// or the vertex lies on the outer shell. Cost: O(faces) to group faces by shell, a sweep along x that
// box-tests each of the k candidate shells against the shells whose x-range spans its start (few
// for side-by-side shells, k at worst), and one pass over T's faces for each pair (S, T) whose boxes
// nest (T's strictly containing S's); a mesh of one shell, or of side-by-side shells, pays only the
// first two. Many shells nested in one another (k onion layers of n faces each) cost O(k² n).
inline constexpr std::uint32_t kNoShell = 0xFFFFFFFFu;

struct ShellNesting {
  std::vector<std::uint8_t> cavity;      // per shell, as findCavityShells
  std::vector<std::uint32_t> enclosing;  // per shell: the innermost candidate around it (any group), or
                                         // kNoShell; empty unless asked for
};

// findCavityShells, and with `withEnclosing` also the innermost candidate shell of any group around
// each shell (then shells of other groups whose boxes nest are tested too).
ShellNesting findShellNesting(std::span<const Vec3> positions, const std::vector<MeshFace>& faces,
                              const FaceShells& shells, std::span<const std::int32_t> facePhysicalTag,
                              std::span<const std::uint8_t> candidates, bool withEnclosing);

std::vector<std::uint8_t> findCavityShells(std::span<const Vec3> positions,
                                           const std::vector<MeshFace>& faces, const FaceShells& shells,
                                           std::span<const std::int32_t> facePhysicalTag,
                                           std::span<const std::uint8_t> candidates);

}  // namespace lancer
