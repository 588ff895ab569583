// The surface mesh as lancer renders it: vertices and triangle/quad faces, with the physical and
// elementary tags gmsh attached, plus what the reader saw (format, counts) for `lancer info`.
// Map: docs/architecture.md (the path of a ray through the modules).
#pragma once

#include <algorithm>
#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "lancer/math/aabb.hpp"
#include "lancer/math/vec3.hpp"
#include "lancer/mesh/mesh_field.hpp"

namespace lancer {

inline constexpr std::uint32_t kNoVertex = 0xFFFFFFFFu;

// A face is a triangle (vertex[3] == kNoVertex) or a quad, vertices in the file's winding order.
struct MeshFace {
  std::uint32_t vertex[4] = {kNoVertex, kNoVertex, kNoVertex, kNoVertex};

  bool isQuad() const { return vertex[3] != kNoVertex; }
  int cornerCount() const { return isQuad() ? 4 : 3; }
};

// Where corner c's value is among a face's kCornerSlots element-node values (mesh_field.hpp): the
// rank of its vertex among the face's vertices, which no change of winding alters.
inline int cornerSlot(const MeshFace& face, int c) {
  int rank = 0;
  for (int k = 0; k < face.cornerCount(); ++k) rank += face.vertex[k] < face.vertex[c];
  return rank;
}

// Bit i of a face's edge mask: the edge from corner i to corner (i+1) % n is an edge of the
// original gmsh element (not one made by splitting a second-order element), so it is drawn by
// element-edge rendering.
inline constexpr std::uint8_t kAllEdges = 0x0F;

// Which volume lies on each side of a face, kept only for meshes with interfaces (faces shared by
// volume elements of two different volumes: two physical volumes, or two elementary volumes when
// neither is in a physical group). A face is wound out of its inner volume (the one its
// facePhysicalTag and faceEntityTag name) towards its outer volume, on the side its normal points.
enum class FaceSide : std::uint8_t {
  kSurface = 0,    // a surface element lancer cannot tie to a volume: its winding is the file's
  kSkin = 1,       // on a volume's boundary, nothing outside: wound out of the volume by its element
  kInterface = 2,  // between two volumes: faceOuterPhysicalTag/faceOuterEntityTag name the outer one
};

struct FaceVolumeSides {
  std::vector<FaceSide> side;
  std::vector<std::int32_t> outerPhysicalTag;  // meaningful for kInterface faces only
  std::vector<std::int32_t> outerEntityTag;
  bool empty() const { return side.empty(); }
  bool isInterface(std::size_t face) const { return !side.empty() && side[face] == FaceSide::kInterface; }
};

struct PhysicalGroup {
  int dimension = 0;
  int tag = 0;
  std::string name;  // empty when the file gives no $PhysicalNames entry
};

// An elementary entity that is in more than one physical group (gmsh lets a surface or volume belong
// to several; MSH 4 lists them all in $Entities, MSH 2 repeats each element once per group). Its faces
// carry the first group in Mesh::facePhysicalTag and the others here, so a mesh whose entities have
// at most one group each costs nothing extra. Matched by (entity, first): faces do not record
// whether they came from a surface or a volume entity.
struct ExtraPhysicalGroups {
  int dimension = 0;        // of the entity
  std::int32_t entity = 0;  // the faces' faceEntityTag
  std::int32_t first = 0;   // the faces' facePhysicalTag
  std::vector<std::int32_t> more;
};

// What the reader saw, for `lancer info` and for warnings.
struct MeshSourceInfo {
  std::string path;
  std::string format = "msh";  // "msh", or "pos": a list-based view file, its elements the mesh
  std::string formatVersion;   // "2.2", "4.0", "4.1" (msh)
  bool binary = false;
  std::uint64_t fileBytes = 0;
  std::uint64_t nodeCount = 0;
  std::map<int, std::uint64_t> elementsByType;       // gmsh element type -> count in the file
  std::map<int, std::uint64_t> unrenderableByType;   // element types lancer could not turn into faces
  std::uint64_t degenerateFacesDropped = 0;          // zero-area faces, removed with a warning
  std::uint64_t duplicateElementsSkipped = 0;        // MSH 2 copies of an element in further physical groups
  std::uint64_t volumeElements = 0;                  // volume elements replaced by their skin
  std::uint64_t skinFaces = 0;                       // faces that came from volume elements' skins
  std::uint64_t skinFacesCoveredBySurfaces = 0;      // skin faces already present as surface elements
  std::uint64_t interfaceFaces = 0;                  // faces shared by two volumes (counted in skinFaces)
  std::uint64_t interfaceSurfaceElementsMerged = 0;  // surface elements on interfaces, merged into them
  std::uint32_t partitionCount = 0;                  // mesh partitions the file declares (0: none)
  // Things the reader accepted but the user should know, each "file:line:col: warning: ..." (values
  // for nodes the file does not save, a field section it could not read and skipped, ...).
  std::vector<std::string> warnings;
  // Fields in sections the reader skipped (see warnings): name and the warning, for color_by.
  std::vector<std::pair<std::string, std::string>> skippedFields;
  // Sections read past because drawing needs nothing from them ($Periodic, $InterpolationScheme,
  // $Comments, an unknown one), by name, with how many times each came: `lancer info` lists them.
  std::map<std::string, std::uint32_t> skippedSections;
  double loadSeconds = 0;
};

// Structure of arrays: the renderer streams positions and faces; tags are read once per hit.
// Positions are float, relative to `origin` (double), so a part at x = 1e6 keeps float precision.
// Memory: 25 bytes per face (16 vertex indices, 4 + 4 tags, 1 edge mask) and 12 per vertex; a closed
// triangle mesh has about half a vertex per triangle, so about 31 bytes per triangle
// (bench/msh_load_bench.cpp reports it as bytes_per_face).
struct Mesh {
  Vec3d origin;
  std::vector<Vec3> positions;
  std::vector<MeshFace> faces;
  std::vector<std::int32_t> facePhysicalTag;  // first physical group of the element, 0 if none
  std::vector<std::int32_t> faceEntityTag;    // gmsh elementary entity
  std::vector<std::uint8_t> faceEdgeMask;     // see kAllEdges
  // Empty unless the mesh has interfaces between volumes (then 9 bytes more per face).
  FaceVolumeSides volumeSides;
  std::vector<PhysicalGroup> physicalGroups;
  std::vector<ExtraPhysicalGroups> extraPhysicalGroups;  // empty unless an entity has several groups
  std::vector<MeshField> fields;  // $NodeData then $ElementData steps, each in file order
  MeshSourceInfo source;

  std::size_t faceCount() const { return faces.size(); }
  Vec3d worldPosition(std::uint32_t vertex) const { return origin + toDouble(positions[vertex]); }
  // Name of the physical group with this tag (surfaces first), or "" when unnamed.
  std::string physicalName(std::int32_t tag) const;
  // The groups face f belongs to after its first (facePhysicalTag[f]); null when none.
  const std::vector<std::int32_t>* morePhysicalTags(std::size_t f) const {
    return extraPhysicalGroups.empty() ? nullptr : findMorePhysicalTags(faceEntityTag[f], facePhysicalTag[f]);
  }
  // Whether face f is in the physical group `tag` (its first group or any other).
  bool faceInPhysicalGroup(std::size_t f, std::int32_t tag) const {
    return inPhysicalGroup(facePhysicalTag[f], faceEntityTag[f], tag);
  }
  // The same for the entity `entity` whose first group is `first` (an interface's outer volume too).
  bool inPhysicalGroup(std::int32_t first, std::int32_t entity, std::int32_t tag) const {
    if (first == tag) return true;
    const std::vector<std::int32_t>* more =
        extraPhysicalGroups.empty() ? nullptr : findMorePhysicalTags(entity, first);
    return more && std::find(more->begin(), more->end(), tag) != more->end();
  }

 private:
  const std::vector<std::int32_t>* findMorePhysicalTags(std::int32_t entity, std::int32_t first) const;
};

// Bounding box of the vertices actually used by faces, in the mesh's local (origin-relative) frame.
Aabb faceBounds(const Mesh& mesh);

}  // namespace lancer
