// Orients every closed shell of a surface mesh out of its solid, whatever winding the file used:
// refraction and caps decide "entering" or "leaving" a solid from the side a ray hits.
#pragma once

#include <climits>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "lancer/mesh/mesh.hpp"

namespace lancer {

struct ShellOrientationReport {
  std::uint64_t shells = 0;
  std::uint64_t closedShells = 0;
  std::uint64_t flippedFaces = 0;
  // Closed shells with no consistent orientation (a non-orientable or non-manifold surface); their
  // faces keep the file's winding and are treated as open (two-sided, thin).
  std::uint64_t unorientableShells = 0;
  // Closed, oriented shells that are cavity walls (shell_nesting.hpp), now facing into the cavity.
  std::uint64_t cavityShells = 0;
  // Per face: 1 when it belongs to a closed, consistently oriented shell, or is a volume's face in a
  // mesh with interfaces (it bounds a solid).
  std::vector<std::uint8_t> faceBoundsSolid;
  // Interface faces that were reversed: their inner and outer volumes swap (the caller's tags).
  std::vector<std::uint32_t> reversedInterfaces;
  // In meshes without interfaces: per face, the physical tag of the solid of another group that its
  // closed shell lies in (the innermost, when it is not a cavity), else kNotEnclosed; empty when no
  // solid lies in another.
  static constexpr std::int32_t kNotEnclosed = INT32_MIN;
  std::vector<std::int32_t> faceEnclosedBy;
  // Faces between two regions of a surface that meets three or more on edges (shell_regions.hpp):
  // the group of the region behind each, in face order (its material is that group's, whatever
  // groups the face itself is in); faceEnclosedBy holds the group of the region in front.
  std::vector<std::pair<std::uint32_t, std::int32_t>> faceRegionTags;
};

// The closed shells orientClosedShellsOutward turned out of their solids, kept by an animation to
// tell whether a later step's positions would turn them otherwise (shellsKeepOrientation). The
// solid shells are numbered 0, 1, ...; which face belongs to which is kept as runs of faces when
// the shells' faces follow each other (a part of one solid: one run), else face by face (the skin of
// a volume mesh with a cavity interleaves its shells).
struct OrientedShells {
  static constexpr std::uint32_t kNotSolid = 0xFFFFFFFFu;
  // The faces from firstFace up to the next run's belong to `shell` (kNotSolid: to no closed,
  // oriented shell), in face order.
  struct Run {
    std::uint32_t firstFace;
    std::uint32_t shell;
  };
  std::vector<Run> runs;
  static constexpr std::uint16_t kNotSolidFace = 0xFFFF;
  std::vector<std::uint16_t> faceShell;  // when not in runs: per face, its shell (kNotSolidFace: none)
  std::vector<std::uint8_t> cavity;      // per shell: a cavity wall, facing into the cavity (negative volume)
  // False when the orientation also depends on where faces lie in other ways (regions of a
  // non-manifold surface), or there are too many shells to keep.
  bool kept = true;
};

// For each shell (faces joined through shared edges, see findFaceShells): when every edge is shared
// by exactly two faces, the orientation of one face is propagated across shared edges to the whole
// shell, and the shell is flipped as a whole so that it faces out of the material: its signed volume
// (divergence theorem) positive, or negative for a cavity wall (a shell nested inside an odd number of
// closed shells of its physical group, see findCavityShells), whose faces point into the cavity.
// Open shells keep the file's winding: they are rendered two-sided. `positions` are the vertices the
// faces index (any frame: the sign of the volume does not depend on translation).
// `threads` bounds the threads used (0: every core); the result is the same for any count.
// `edgeMasks`, when not empty, holds one mask per face and is kept in step with the faces.
// `facePhysicalTag` holds one tag per face (empty: all faces in one group).
// `faceSide` (Mesh::volumeSides, empty when the mesh has no interfaces): a closed shell of interfaces
// (a ball inside a block) faces out of the volume it encloses and is never a cavity wall; a volume's
// faces in a shell that is not a closed 2-manifold (where an interface meets the skin, three faces
// share each edge of the rim) keep their elements' winding, out of their volume, and bound solids.
ShellOrientationReport orientClosedShellsOutward(std::span<const Vec3> positions,
                                                 std::vector<MeshFace>& faces,
                                                 std::vector<std::uint8_t>& edgeMasks,
                                                 std::span<const std::int32_t> facePhysicalTag,
                                                 std::span<const FaceSide> faceSide = {}, int threads = 0,
                                                 OrientedShells* oriented = nullptr);

// Whether `faces` (as orientClosedShellsOutward left them, with `oriented` from it) still face out of
// their solids at new `positions`: every closed shell's signed volume has the sign it was turned to
// (a shell the positions turned inside out, or flattened, has not). The nesting of shells is taken
// as it was. Same result for any thread count.
bool shellsKeepOrientation(std::span<const Vec3> positions, std::span<const MeshFace> faces,
                           const OrientedShells& oriented, int threads = 0);

}  // namespace lancer
