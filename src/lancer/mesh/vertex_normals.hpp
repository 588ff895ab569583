// Smooth vertex normals for Gouraud and Phong shading: the angle-weighted average of the normals of
// the faces around a vertex, split where faces meet at a crease or a physical-group boundary.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "lancer/mesh/mesh.hpp"

namespace lancer {

struct CornerNormals {
  std::vector<Vec3> normals;                             // unit vectors, shared by corners that agree
  std::vector<std::array<std::uint32_t, 4>> faceCorner;  // per face, per corner: index into normals
};

// The vertices whose faces computeCornerNormals walked one by one (a crease, a group border, faces
// whose normals cancel), with the corners on each: what updateCornerNormals needs to walk them
// again at new positions without finding every vertex's faces.
struct CornerNormalWalks {
  std::vector<std::uint32_t> vertex;    // increasing
  std::vector<std::uint32_t> rowStart;  // vertex.size() + 1 offsets into corner
  std::vector<std::uint32_t> corner;    // per walked vertex, its corners: face << 2 | corner, face order
};

// Two faces sharing a vertex are smoothed together when the angle between their normals is at most
// creaseAngleDegrees and they have the same physical tag (Thurmer & Wuthrich 1998 angle weights).
// On `threads` threads (0: every core); the result is the same for any number. The unit face
// normals it works from (faceNormal of face_geometry.hpp) go to `unitFaceNormals` when given, the
// walked vertices to `walks`.
CornerNormals computeCornerNormals(std::span<const Vec3> positions, std::span<const MeshFace> faces,
                                   std::span<const std::int32_t> facePhysicalTag, float creaseAngleDegrees,
                                   int threads = 0, std::vector<Vec3>* unitFaceNormals = nullptr,
                                   CornerNormalWalks* walks = nullptr);

// Where a mesh's faces, vertices and normals lie in arrays shared with other meshes (a scene's):
// its faces index vertices from vertexBase on, its corners normals from normalBase on.
struct CornerNormalsSpan {
  std::span<const MeshFace> faces;
  std::uint32_t vertexBase = 0;
  std::size_t vertexCount = 0;
  std::uint32_t normalBase = 0;
};

// Working memory updateCornerNormals can keep from one call to the next (an animation's frames): its
// per-vertex sums, whose pages would otherwise be faulted in and zeroed by the kernel every frame.
class CornerNormalsScratch {
 public:
  CornerNormalsScratch();
  ~CornerNormalsScratch();
  CornerNormalsScratch(CornerNormalsScratch&&) noexcept;
  CornerNormalsScratch& operator=(CornerNormalsScratch&&) noexcept;
  void release();  // gives the memory back (before something larger is built)
  struct Sums;
  std::unique_ptr<Sums> sums;
};

enum class NormalsUpdate {
  Updated,
  SmoothingChanged,  // some vertex may be smoothed otherwise: computeCornerNormals again
  FaceDegenerate,    // a face has no normal: it must be dropped (scene_update.hpp builds again)
};

// The normals computeCornerNormals gave `mesh.faces` (with `walks`), again for the vertices at new
// `positions`, written over `normals` (the normals' values; their indices in faceCorner stay) and
// `unitFaceNormals` (per face of the mesh): the same bits computeCornerNormals would give, as long
// as every vertex is smoothed as before. Otherwise, with the arrays partly written, says why: a
// vertex whose smoothing may have changed (a new crease, faces that now cancel), or a face without
// a normal. `scratch`, when given, holds the working memory between calls.
NormalsUpdate updateCornerNormals(std::span<const Vec3> positions, const CornerNormalsSpan& mesh,
                                  std::span<const std::int32_t> facePhysicalTag, float creaseAngleDegrees,
                                  const CornerNormalWalks& walks, int threads, std::span<Vec3> normals,
                                  std::span<const std::array<std::uint32_t, 4>> faceCorner,
                                  std::span<Vec3> unitFaceNormals, CornerNormalsScratch* scratch = nullptr);

}  // namespace lancer
