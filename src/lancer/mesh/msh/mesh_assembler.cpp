#include "lancer/mesh/msh/mesh_assembler.hpp"

#include <fmt/format.h>

#include "lancer/mesh/face_geometry.hpp"
#include "lancer/mesh/msh/high_order.hpp"
#include "lancer/util/check.hpp"
#include "lancer/util/huge_pages.hpp"
#include "lancer/util/input_error.hpp"
#include "lancer/util/parallel_for.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <optional>

namespace lancer {
namespace {

// Items per chunk of the parallel passes: big enough that a thread start is noise beside its work.
constexpr std::size_t kFaceGrain = 32768;
constexpr std::size_t kNodeGrain = 32768;
}  // namespace

void MshMeshAssembler::reserveFaces(std::size_t count) {
  faces_.reserve(count);
  facePhysical_.reserve(count);
  faceEntity_.reserve(count);
  faceEdgeMask_.reserve(count);
  adviseHugePages(faces_);
  adviseHugePages(facePhysical_);
  adviseHugePages(faceEntity_);
  if (trackElements_) {  // 16 bytes a face that grew by doubling, copied to fresh pages each time
    faceElement_.reserve(count);
    faceCornerNode_.reserve(count);
    adviseHugePages(faceElement_);
    adviseHugePages(faceCornerNode_);
  }
}

void MshMeshAssembler::adoptSurfaceMesh(std::span<const Vec3d> points, std::vector<MeshFace> faces,
                                        std::vector<std::int32_t> physical,
                                        std::vector<std::int32_t> entity) {
  LANCER_DCHECK(faces_.size(), ==, std::size_t{0});
  LANCER_DCHECK(nodes.size(), ==, std::size_t{0});
  adoptedPoints_ = points;
  LANCER_DCHECK(physical.size(), ==, faces.size());
  LANCER_DCHECK(entity.size(), ==, faces.size());
  faceEdgeMask_.resize(faces.size());
  std::uint64_t quads = 0;
  for (std::size_t f = 0; f < faces.size(); ++f) {
    const bool quad = faces[f].isQuad();
    quads += quad;
    faceEdgeMask_[f] = quad ? kAllEdges : std::uint8_t{0b111};
  }
  countByType_[2] += faces.size() - quads;
  countByType_[3] += quads;
  // Tags come in runs (faces of one group together): one set insertion per run.
  for (std::size_t f = 0; f < physical.size(); ++f)
    if (physical[f] != 0 && (f == 0 || physical[f] != physical[f - 1]))
      physicalsSeen_.insert({2, physical[f]});
  faces_ = std::move(faces);
  facePhysical_ = std::move(physical);
  faceEntity_ = std::move(entity);
}

void MshMeshAssembler::changeGroup(int dimension, std::int32_t physical, std::int32_t entity) {
  dimension_ = dimension;
  physical_ = physical;
  entity_ = entity;
  if (physical != 0 && dimension >= 2) physicalsSeen_.insert({dimension, physical});
  groups_.push_back({physical, entity});
  group_ = static_cast<std::uint32_t>(groups_.size() - 1);
}

// Mid-edge nodes split a 6-node triangle into four (corner triangles keep the two halves of the
// original edges they touch; the centre triangle has no original edge).
void MshMeshAssembler::addSplitTriangle(const std::uint32_t* corner, const std::uint32_t* mid) {
  addTriangle(corner[0], mid[0], mid[2], 0b101);
  addTriangle(mid[0], corner[1], mid[1], 0b011);
  addTriangle(mid[2], mid[1], corner[2], 0b110);
  addTriangle(mid[0], mid[1], mid[2], 0);
}

// A 9- or 8-node quad becomes four quads through its edge nodes and centre.
void MshMeshAssembler::addSplitQuad(const std::uint32_t* corner, const std::uint32_t* mid,
                                    std::uint32_t centre) {
  addQuad(corner[0], mid[0], centre, mid[3], 0b1001);
  addQuad(mid[0], corner[1], mid[1], centre, 0b0011);
  addQuad(centre, mid[1], corner[2], mid[2], 0b0110);
  addQuad(mid[3], centre, mid[2], corner[3], 0b1100);
}

// The centre of an 8-node (serendipity) quad: its shape functions there are -1/4 per corner and 1/2
// per edge node.
Vec3d MshMeshAssembler::serendipityCentre(const std::uint32_t* corner, const std::uint32_t* mid) const {
  const auto& p = nodes.coords();
  Vec3d centre{};
  for (int i = 0; i < 4; ++i) centre += p[corner[i]] * -0.25 + p[mid[i]] * 0.5;
  return centre;
}

std::uint32_t MshMeshAssembler::addDerivedCentre(const std::uint32_t* corner, const std::uint32_t* mid) {
  derivedSources_.push_back({corner[0], corner[1], corner[2], corner[3], mid[0], mid[1], mid[2], mid[3]});
  return nodes.addDerived(serendipityCentre(corner, mid));
}

void MshMeshAssembler::addOtherElement(int type, const std::uint32_t* n) {
  const auto first = static_cast<std::uint32_t>(faces_.size());
  switch (type) {
    case 9:
      secondOrderSurfaces_.push_back({mshFaceKey(n, 3), {n[0], n[1], n[2], kNoVertex}, first, 4});
      addSplitTriangle(n, n + 3);
      return;
    case 10:
      secondOrderSurfaces_.push_back({mshFaceKey(n, 4), {n[0], n[1], n[2], n[3]}, first, 4});
      addSplitQuad(n, n + 4, n[8]);
      return;
    case 16:
      secondOrderSurfaces_.push_back({mshFaceKey(n, 4), {n[0], n[1], n[2], n[3]}, first, 4});
      addSplitQuad(n, n + 4, addDerivedCentre(n, n + 4));
      return;
    default:
      // First and second order volumes, the bulk of a volume mesh, skip the high-order table lookup.
      if (!mshIsLowOrderVolume(type) && mshSurfaceCorners(type)) {
        addHighOrderSurface(type, n);
        return;
      }
      addVolumeElement(type, n);
      return;
  }
}

namespace {

// Where `node` is among an element's `count` nodes; kAddedCentre when it is not one of them.
std::uint16_t elementNodePosition(const std::uint32_t* nodes, int count, std::uint32_t node) {
  for (int i = 0; i < count && i < kAddedCentre; ++i)
    if (nodes[i] == node) return static_cast<std::uint16_t>(i);
  return kAddedCentre;
}

}  // namespace

// Where `node` is among the nodes of a volume face's element, `order` giving the element positions of
// the face's nodes; kAddedCentre when it is none of them.
std::uint16_t volumeFaceNodePosition(const MshVolumeFace& face, const std::array<std::uint16_t, 9>& order,
                                     std::uint32_t node) {
  for (int i = 0; i < 9; ++i)
    if (volumeFaceNode(face, i) == node) return order[static_cast<std::size_t>(i)];
  return kAddedCentre;
}

void MshMeshAssembler::recordCornerNodes() {
  const MeshFace& face = faces_.back();
  MshCornerNodes order{kNoElementNode, kNoElementNode, kNoElementNode, kNoElementNode};
  for (int c = 0; c < face.cornerCount(); ++c) {
    order[static_cast<std::size_t>(c)] = kAddedCentre;
    if (volumeFace_) {
      order[static_cast<std::size_t>(c)] =
          volumeFaceNodePosition(*volumeFace_, *volumeFaceNodeOrder_, face.vertex[c]);
    } else if (elementNodes_) {
      // A face of a surface element mostly keeps its nodes' order: corner c is node c.
      order[static_cast<std::size_t>(c)] =
          c < elementNodeCount_ && elementNodes_[c] == face.vertex[c]
              ? static_cast<std::uint16_t>(c)
              : elementNodePosition(elementNodes_, elementNodeCount_, face.vertex[c]);
    }
  }
  faceCornerNode_.push_back(order);
}

void MshMeshAssembler::addVolumeElement(int type, const std::uint32_t* n) {
  if (volumeCapture_) {
    if (const std::optional<CellShape> shape = mshVolumeShape(type))
      volumeCapture_->addCell(*shape, n, element_, physical_, entity_);
  }
  if (volumeElementFaceCount(type) > 0) volumeElements_.add(type, n, group_, element_);
  if (volumeGroups_.empty() || volumeGroups_.back() != group_) volumeGroups_.push_back(group_);
}

std::array<std::uint16_t, 9> MshMeshAssembler::volumeFaceNodeOrder(std::uint32_t volumeFace,
                                                                   const MshVolumeFace& face) const {
  int nodeCount = 0;
  const std::uint32_t* n = volumeElements_.elementNodesOfFace(volumeFace, &nodeCount);
  std::array<std::uint16_t, 9> order{};
  for (int i = 0; i < 9; ++i) {
    const std::uint32_t node = volumeFaceNode(face, i);
    order[static_cast<std::size_t>(i)] =
        node == kNoVertex ? kAddedCentre : elementNodePosition(n, nodeCount, node);
  }
  return order;
}

// Order 3 and up: the element's flat faces through its nodes (high_order.hpp).
void MshMeshAssembler::addHighOrderSurface(int type, const std::uint32_t* n) {
  const int corners = mshSurfaceCorners(type);
  const auto first = static_cast<std::uint32_t>(faces_.size());
  for (const MshSubFace& face : mshHighOrderSurfaceFaces(type)) {
    if (face.corner[3] == kNoSubCorner) {
      addTriangle(n[face.corner[0]], n[face.corner[1]], n[face.corner[2]], face.edgeMask);
    } else {
      addQuad(n[face.corner[0]], n[face.corner[1]], n[face.corner[2]], n[face.corner[3]], face.edgeMask);
    }
  }
  secondOrderSurfaces_.push_back({mshFaceKey(n, corners),
                                  {n[0], n[1], n[2], corners == 4 ? n[3] : kNoVertex},
                                  first,
                                  static_cast<std::uint32_t>(faces_.size()) - first});
}

Mesh MshMeshAssembler::finish(MeshSourceInfo source, std::vector<PhysicalGroup> namedGroups) {
  for (int type = 1; type <= kMaxMshElementType; ++type) {
    const std::uint64_t count = countByType_[static_cast<std::size_t>(type)];
    if (count == 0) continue;
    source.elementsByType[type] = count;
    const MshElementRole role = mshElementType(type).role;
    if (role == MshElementRole::kUnrenderable) source.unrenderableByType[type] = count;
    if (role == MshElementRole::kVolume) source.volumeElements += count;
  }
  appendVolumeBoundary(source);

  // Keep the nodes that faces use, in file order, recentred on their bounding box as float. Every
  // pass runs on `threads_` threads in chunks fixed by the counts (util/parallel_for.hpp), so the
  // mesh is the same bytes for any thread count; only the renumbering and compaction are serial.
  const std::span<const Vec3d> coords =
      adoptedPoints_.empty() ? std::span<const Vec3d>(nodes.coords()) : adoptedPoints_;
  std::vector<std::uint8_t> usedNode(coords.size(), 0);
  parallelFor(faces_.size(), threads_, kFaceGrain, [&](std::size_t f) {
    const MeshFace& face = faces_[f];
    // Threads may mark one node together: they store the same byte.
    for (int c = 0; c < face.cornerCount(); ++c)
      std::atomic_ref<std::uint8_t>(usedNode[face.vertex[c]]).store(1, std::memory_order_relaxed);
  });
  const ChunkPlan nodeChunks(coords.size(), kNodeGrain);
  std::vector<Aabbd> chunkBox(nodeChunks.chunks);
  std::vector<std::uint32_t> chunkUsed(nodeChunks.chunks, 0);
  parallelChunks(nodeChunks, threads_, [&](std::size_t k, std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) {
      if (!usedNode[i]) continue;
      ++chunkUsed[k];
      chunkBox[k].extend(coords[i]);
    }
  });
  Aabbd box;
  std::uint32_t usedCount = 0;
  for (std::size_t k = 0; k < nodeChunks.chunks; ++k) {
    usedCount += chunkUsed[k];
    if (!chunkBox[k].empty()) box.extend(chunkBox[k]);
  }
  // Usually every node is used and indices stay as they are; otherwise faces are renumbered.
  const bool identity = usedCount == coords.size();
  std::vector<std::uint32_t> remap;  // file-order index -> mesh vertex; empty for the identity
  if (!identity) {
    remap.reserve(coords.size());
    adviseHugePages(remap);
    std::uint32_t next = 0;
    for (std::size_t i = 0; i < coords.size(); ++i) remap.push_back(usedNode[i] ? next++ : kNoVertex);
  }
  Mesh mesh;
  mesh.origin = box.empty() ? Vec3d{} : box.center();
  mesh.positions.resize(usedCount);
  adviseHugePages(mesh.positions);
  parallelFor(coords.size(), threads_, kNodeGrain, [&](std::size_t i) {
    if (identity || usedNode[i]) mesh.positions[identity ? i : remap[i]] = toFloat(coords[i] - mesh.origin);
  });
  if (volumeCapture_) volumeCapture_->finishCells(coords, mesh.origin);

  // Drop the faces that are degenerate as the renderer will see them (isDegenerateFace, face_geometry.hpp):
  // each chunk renumbers its faces and marks the degenerate ones, then one pass closes the gaps.
  const std::vector<Vec3>& positions = mesh.positions;
  const ChunkPlan faceChunks(faces_.size(), kFaceGrain);
  std::vector<std::uint8_t> degenerate(faces_.size(), 0);
  std::vector<std::size_t> chunkDropped(faceChunks.chunks, 0);
  parallelChunks(faceChunks, threads_, [&](std::size_t k, std::size_t begin, std::size_t end) {
    constexpr std::size_t kPrefetchDistance = 16;  // faces ahead: the position reads are random
    for (std::size_t f = begin; f < end; ++f) {
      if (f + kPrefetchDistance < end) {
        const MeshFace& ahead = faces_[f + kPrefetchDistance];
        for (int c = 0; c < 3; ++c)
          __builtin_prefetch(identity ? static_cast<const void*>(&positions[ahead.vertex[c]])
                                      : static_cast<const void*>(&remap[ahead.vertex[c]]));
      }
      MeshFace& face = faces_[f];
      if (!identity)
        for (int c = 0; c < face.cornerCount(); ++c) face.vertex[c] = remap[face.vertex[c]];
      if (isDegenerateFace(positions.data(), face)) degenerate[f] = 1, ++chunkDropped[k];
    }
  });
  std::size_t kept = faces_.size();
  for (const std::size_t dropped : chunkDropped) kept -= dropped;
  if (kept != faces_.size()) {
    std::size_t next = 0;
    for (std::size_t f = 0; f < faces_.size(); ++f) {
      if (degenerate[f]) continue;
      if (next != f) moveFace(next, f);
      ++next;
    }
  }
  source.degenerateFacesDropped = faces_.size() - kept;
  truncateFaces(kept);
  // What was read and is not drawn, said by every command that loads the mesh (info lists it too).
  for (const auto& [type, count] : source.unrenderableByType)
    source.warnings.push_back(formatInputWarning(
        SourceLocation{source.path}, fmt::format("{} {} (type {}) not drawn: lancer does not draw this type",
                                                 count, mshElementTypeName(type), type)));
  if (source.degenerateFacesDropped)
    source.warnings.push_back(formatInputWarning(
        SourceLocation{source.path},
        fmt::format("{} degenerate (zero-area) faces dropped", source.degenerateFacesDropped)));
  LANCER_DCHECK(facePhysical_.size(), ==, faces_.size());
  LANCER_DCHECK(faceEntity_.size(), ==, faces_.size());
  LANCER_DCHECK(faceEdgeMask_.size(), ==, faces_.size());
  if (trackSides_) LANCER_DCHECK(sides_.side.size(), ==, faces_.size());
  if (trackSides_) mesh.volumeSides = std::move(sides_);
  mesh.faces = std::move(faces_);
  mesh.facePhysicalTag = std::move(facePhysical_);
  mesh.faceEntityTag = std::move(faceEntity_);
  mesh.faceEdgeMask = std::move(faceEdgeMask_);

  // Named groups first, then the unnamed physical tags that surface and volume elements carry.
  std::set<std::pair<int, std::int32_t>> named;
  for (const PhysicalGroup& group : namedGroups) named.insert({group.dimension, group.tag});
  for (const auto& [dimension, tag] : physicalsSeen_) {
    if (!named.count({dimension, tag})) namedGroups.push_back({dimension, tag, ""});
  }
  std::sort(namedGroups.begin(), namedGroups.end(), [](const PhysicalGroup& a, const PhysicalGroup& b) {
    return a.dimension != b.dimension ? a.dimension < b.dimension : a.tag < b.tag;
  });
  mesh.physicalGroups = std::move(namedGroups);
  mesh.source = std::move(source);
  mesh.fields = std::move(nodeFields);
  for (MeshField& field : mesh.fields) {
    if (volumeCapture_) volumeCapture_->addNodeField(field, field.values);
    remapNodeValues(field.values, field.components, usedNode, usedCount, nodes.taggedCount(),
                    derivedSources_);
  }
  std::sort(elementAliases_.begin(), elementAliases_.end());
  // Corner order becomes slot order (cornerSlot, mesh.hpp): the orientation of shells turns faces
  // after this, and a slot follows its vertex wherever the winding puts it.
  // In place: a second array of 8 bytes a face was as many fresh pages to fault in and clear.
  std::vector<MshCornerNodes> cornerSlots = std::move(faceCornerNode_);
  faceCornerNode_ = std::vector<MshCornerNodes>();
  parallelFor(cornerSlots.size(), threads_, kFaceGrain, [&](std::size_t f) {
    const MeshFace& face = mesh.faces[f];
    const MshCornerNodes order = cornerSlots[f];
    MshCornerNodes& slots = cornerSlots[f];
    slots.fill(kNoElementNode);
    for (int c = 0; c < face.cornerCount(); ++c)
      slots[static_cast<std::size_t>(cornerSlot(face, c))] = order[static_cast<std::size_t>(c)];
  });
  MshCoveredElements covered;
  if (!faceCoveredElement_.empty()) {
    covered.element = std::move(faceCoveredElement_);
    covered.cornerNode.resize(faceCoveredCornerNode_.size());
    for (std::size_t f = 0; f < covered.element.size(); ++f) {
      if (covered.element[f] == kNoCoveredElement) continue;
      MshCornerNodes& slots = covered.cornerNode[f];
      slots.fill(kNoElementNode);
      for (int c = 0; c < mesh.faces[f].cornerCount(); ++c)
        slots[static_cast<std::size_t>(cornerSlot(mesh.faces[f], c))] =
            faceCoveredCornerNode_[f][static_cast<std::size_t>(c)];
    }
    faceCoveredCornerNode_ = std::vector<MshCornerNodes>();
  }
  mapElementFields(mesh, cornerSlots, covered);
  if (keepFieldMapping_) {
    // The reader's field sections are read after this, into the mesh's order: what it takes.
    auto mapping = std::make_shared<MshFieldMapping>();
    mapping->nodeCount = nodes.size();
    mapping->nodes = std::move(nodes);
    mapping->nodes.keepLookupOnly();
    mapping->usedNode = std::move(usedNode);
    mapping->usedCount = usedCount;
    mapping->derivedSources = std::move(derivedSources_);
    mapping->faceElement = std::move(faceElement_);
    mapping->faceCornerNode = std::move(cornerSlots);
    mapping->elementAliases = std::move(elementAliases_);
    mapping->covered = std::move(covered);
    mapping->volume = volumeCapture_;
    fieldMapping_ = std::move(mapping);
  }
  faceElement_ = std::vector<std::uint64_t>();
  return mesh;
}

void MshMeshAssembler::mapElementFields(Mesh& mesh, const std::vector<MshCornerNodes>& cornerSlots,
                                        const MshCoveredElements& covered) {
  for (ElementField& raw : elementFields) {
    if (volumeCapture_) volumeCapture_->addElementField(raw.field, raw.tags, raw.field.values);
    raw.field.values = mapElementValues(std::move(raw.tags), raw.field.values, raw.field.components,
                                        faceElement_, elementAliases_, covered);
    mesh.fields.push_back(std::move(raw.field));
  }
  elementFields.clear();
  for (ElementNodeField& raw : elementNodeFields) {
    if (volumeCapture_) volumeCapture_->addElementNodeField(raw.field, raw.records);
    raw.field.values = mapElementNodeValues(std::move(raw.records), raw.field.components, faceElement_,
                                            cornerSlots, elementAliases_, covered);
    mesh.fields.push_back(std::move(raw.field));
  }
  elementNodeFields.clear();
}

}  // namespace lancer
