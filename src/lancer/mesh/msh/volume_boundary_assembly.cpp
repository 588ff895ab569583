// The assembler's volume part: the volume elements' boundary (skin faces and interfaces) merged with
// the surface elements that show it, each face kept once, on the side it belongs to.
#include "lancer/mesh/msh/mesh_assembler.hpp"

#include "lancer/mesh/face_geometry.hpp"

#include <algorithm>

namespace lancer {

std::vector<MshMeshAssembler::SurfaceElementFaces> MshMeshAssembler::surfaceElementsByKey() const {
  std::vector<SurfaceElementFaces> elements = secondOrderSurfaces_;
  std::vector<std::uint8_t> split(faces_.size(), 0);
  for (const SurfaceElementFaces& element : secondOrderSurfaces_)
    std::fill_n(split.begin() + element.firstFace, element.faceCount, std::uint8_t{1});
  elements.reserve(elements.size() + faces_.size());
  for (std::size_t f = 0; f < faces_.size(); ++f) {
    if (split[f]) continue;
    const MeshFace& face = faces_[f];
    elements.push_back({mshFaceKey(face.vertex, face.cornerCount()),
                        {face.vertex[0], face.vertex[1], face.vertex[2], face.vertex[3]},
                        static_cast<std::uint32_t>(f),
                        1});
  }
  std::sort(elements.begin(), elements.end());
  return elements;
}

// Turns a surface element that shows a volume face to the volume face's winding (out of the volume).
void MshMeshAssembler::alignWinding(const SurfaceElementFaces& element, const MshVolumeFace& volumeFace) {
  const int corners = element.corner[3] == kNoVertex ? 3 : 4;
  int at = 0;
  while (at < corners && element.corner[at] != volumeFace.corner[0]) ++at;
  if (element.corner[(at + 1) % corners] == volumeFace.corner[1]) return;
  for (std::uint32_t f = element.firstFace; f < element.firstFace + element.faceCount; ++f) {
    reverseWinding(faces_[f], faceEdgeMask_[f]);
    if (trackElements_)  // in step with the corners, as reverseWinding turns them
      std::reverse(faceCornerNode_[f].begin() + 1, faceCornerNode_[f].begin() + faces_[f].cornerCount());
  }
}

void MshMeshAssembler::recordCoveredElement(const SurfaceElementFaces& element, std::uint32_t volumeFace) {
  if (faceCoveredElement_.empty()) {
    faceCoveredElement_.assign(faces_.size(), kNoCoveredElement);
    faceCoveredCornerNode_.assign(faces_.size(),
                                  {kNoElementNode, kNoElementNode, kNoElementNode, kNoElementNode});
  }
  const MshVolumeFace face = volumeElements_.face(volumeFace);
  const std::array<std::uint16_t, 9> order = volumeFaceNodeOrder(volumeFace, face);
  const std::uint64_t tag = volumeElements_.elementTagOfFace(volumeFace);
  for (std::uint32_t f = element.firstFace; f < element.firstFace + element.faceCount; ++f) {
    faceCoveredElement_[f] = tag;
    for (int c = 0; c < faces_[f].cornerCount(); ++c)
      faceCoveredCornerNode_[f][static_cast<std::size_t>(c)] =
          volumeFaceNodePosition(face, order, faces_[f].vertex[c]);
  }
}

MshMeshAssembler::MergedSurfaceElement MshMeshAssembler::mergedSurfaceElement(
    const SurfaceElementFaces& element) const {
  MergedSurfaceElement merged;
  merged.element = faceElement_[element.firstFace];
  for (std::uint32_t f = element.firstFace; f < element.firstFace + element.faceCount; ++f)
    for (int c = 0; c < faces_[f].cornerCount(); ++c) {
      const std::uint32_t node = faces_[f].vertex[c];
      if (std::find(merged.node.begin(), merged.node.begin() + merged.count, node) !=
          merged.node.begin() + merged.count)
        continue;
      merged.node[merged.count] = node;
      merged.position[merged.count++] = faceCornerNode_[f][static_cast<std::size_t>(c)];
    }
  return merged;
}

void MshMeshAssembler::showMergedSurfaceFirst(const MergedSurfaceElement& merged, std::size_t firstFace) {
  if (faceCoveredElement_.empty()) {
    faceCoveredElement_.assign(faces_.size(), kNoCoveredElement);
    faceCoveredCornerNode_.assign(faces_.size(),
                                  {kNoElementNode, kNoElementNode, kNoElementNode, kNoElementNode});
  }
  for (std::size_t f = firstFace; f < faces_.size(); ++f) {
    faceCoveredElement_[f] = faceElement_[f];
    faceCoveredCornerNode_[f] = faceCornerNode_[f];
    faceElement_[f] = merged.element;
    for (int c = 0; c < faces_[f].cornerCount(); ++c) {
      const auto at = std::find(merged.node.begin(), merged.node.begin() + merged.count, faces_[f].vertex[c]);
      faceCornerNode_[f][static_cast<std::size_t>(c)] =
          at != merged.node.begin() + merged.count
              ? merged.position[static_cast<std::size_t>(at - merged.node.begin())]
              : kAddedCentre;
    }
  }
}

void MshMeshAssembler::moveFace(std::size_t to, std::size_t from) {
  faces_[to] = faces_[from];
  facePhysical_[to] = facePhysical_[from];
  faceEntity_[to] = faceEntity_[from];
  faceEdgeMask_[to] = faceEdgeMask_[from];
  if (trackElements_) {
    faceElement_[to] = faceElement_[from];
    faceCornerNode_[to] = faceCornerNode_[from];
    if (!faceCoveredElement_.empty()) {
      faceCoveredElement_[to] = faceCoveredElement_[from];
      faceCoveredCornerNode_[to] = faceCoveredCornerNode_[from];
    }
  }
  if (trackSides_) {
    sides_.side[to] = sides_.side[from];
    sides_.outerPhysicalTag[to] = sides_.outerPhysicalTag[from];
    sides_.outerEntityTag[to] = sides_.outerEntityTag[from];
  }
}

void MshMeshAssembler::reserveMoreFaces(std::size_t count) {
  const std::size_t total = faces_.size() + count;
  faces_.reserve(total);
  facePhysical_.reserve(total);
  faceEntity_.reserve(total);
  faceEdgeMask_.reserve(total);
  if (trackElements_) {
    faceElement_.reserve(total);
    faceCornerNode_.reserve(total);
    if (!faceCoveredElement_.empty()) {
      faceCoveredElement_.reserve(total);
      faceCoveredCornerNode_.reserve(total);
    }
  }
  if (trackSides_) {
    sides_.side.reserve(total);
    sides_.outerPhysicalTag.reserve(total);
    sides_.outerEntityTag.reserve(total);
  }
}

void MshMeshAssembler::truncateFaces(std::size_t count) {
  faces_.resize(count);
  facePhysical_.resize(count);
  faceEntity_.resize(count);
  faceEdgeMask_.resize(count);
  if (trackElements_) {
    faceElement_.resize(count);
    faceCornerNode_.resize(count);
    if (!faceCoveredElement_.empty()) {
      faceCoveredElement_.resize(count);
      faceCoveredCornerNode_.resize(count);
    }
  }
  if (trackSides_) {
    sides_.side.resize(count);
    sides_.outerPhysicalTag.resize(count);
    sides_.outerEntityTag.resize(count);
  }
}

void MshMeshAssembler::removeFaces(const std::vector<std::uint8_t>& removed) {
  std::size_t kept = 0;
  for (std::size_t f = 0; f < faces_.size(); ++f)
    if (!removed[f]) moveFace(kept++, f);
  truncateFaces(kept);
}

void MshMeshAssembler::addVolumeFace(const MshVolumeFace& face) {
  if (face.mid[0] != kNoVertex && face.corner[3] == kNoVertex) {
    addSplitTriangle(face.corner, face.mid);
  } else if (face.mid[0] != kNoVertex) {
    const std::uint32_t centre =
        face.centre != kNoVertex ? face.centre : addDerivedCentre(face.corner, face.mid);
    addSplitQuad(face.corner, face.mid, centre);
  } else if (face.corner[3] == kNoVertex) {
    addTriangle(face.corner[0], face.corner[1], face.corner[2], 0b111);
  } else {
    addQuad(face.corner[0], face.corner[1], face.corner[2], face.corner[3], kAllEdges);
  }
}

// The volume elements' boundary: skin faces and interfaces (volume_skin.hpp). A surface element
// that shows a boundary face is that face, not a second one: on the skin it is kept in the volume's
// place when it is in a physical group or the volume is not (so a Physical Surface keeps its
// material), else the volume's face is kept (-save_all writes every surface, in no group); on an
// interface the volumes' face is kept, so that each side shows its own volume.
void MshMeshAssembler::appendVolumeBoundary(MeshSourceInfo& source) {
  if (volumeElements_.empty()) return;
  // A volume is its physical group, or its elementary entity when it has none.
  std::vector<std::uint64_t> volumeOfGroup(groups_.size());
  for (std::size_t g = 0; g < groups_.size(); ++g) {
    const auto [physical, entity] = groups_[g];
    volumeOfGroup[g] = physical != 0 ? std::uint64_t{static_cast<std::uint32_t>(physical)}
                                     : (std::uint64_t{1} << 32) | static_cast<std::uint32_t>(entity);
  }
  const bool severalVolumes = std::any_of(volumeGroups_.begin(), volumeGroups_.end(), [&](std::uint32_t g) {
    return volumeOfGroup[g] != volumeOfGroup[volumeGroups_.front()];
  });
  const std::vector<VolumeBoundaryFace> boundary =
      findVolumeBoundary(volumeElements_, nodes.size(), volumeOfGroup, severalVolumes, threads_);
  const bool anyInterface = std::any_of(boundary.begin(), boundary.end(), [](const VolumeBoundaryFace& face) {
    return face.outer != kNoVertex;
  });
  if (anyInterface) {
    trackSides_ = true;
    sides_.side.assign(faces_.size(), FaceSide::kSurface);
    sides_.outerPhysicalTag.assign(faces_.size(), 0);
    sides_.outerEntityTag.assign(faces_.size(), 0);
  }

  std::vector<std::uint8_t> addBoundaryFace(boundary.size(), 1);
  std::vector<std::uint8_t> removedSurface;  // sized at the first surface element merged away
  // When tracking: the surface elements merged into interfaces, whose own records the interface
  // faces show first (a view on the interface), the inner volume element's after them.
  std::vector<std::uint32_t> interfaceSurfaceOf;  // per boundary face; sized at the first one
  std::vector<MergedSurfaceElement> interfaceSurfaces;
  if (!faces_.empty()) {
    const std::vector<SurfaceElementFaces> surfaces = surfaceElementsByKey();
    for (std::size_t b = 0; b < boundary.size(); ++b) {
      const MshVolumeFace volumeFace = volumeElements_.face(boundary[b].face);
      const int corners = volumeFace.corner[3] == kNoVertex ? 3 : 4;
      SurfaceElementFaces probe{};
      probe.key = mshFaceKey(volumeFace.corner, corners);
      const auto [begin, end] = std::equal_range(surfaces.begin(), surfaces.end(), probe);
      if (begin == end) continue;
      const bool interface = boundary[b].outer != kNoVertex;
      const bool surfaceGrouped = std::any_of(
          begin, end, [&](const SurfaceElementFaces& e) { return facePhysical_[e.firstFace] != 0; });
      const bool volumeGrouped = groups_[volumeFace.group].first != 0;
      if (interface || (!surfaceGrouped && volumeGrouped)) {
        if (interface && trackElements_) {
          if (interfaceSurfaceOf.empty()) interfaceSurfaceOf.assign(boundary.size(), kNoMergedSurface);
          interfaceSurfaceOf[b] = static_cast<std::uint32_t>(interfaceSurfaces.size());
          interfaceSurfaces.push_back(mergedSurfaceElement(*begin));
        }
        if (removedSurface.empty()) removedSurface.assign(faces_.size(), 0);
        for (auto e = begin; e != end; ++e)
          std::fill_n(removedSurface.begin() + e->firstFace, e->faceCount, 1);
        source.interfaceSurfaceElementsMerged += interface ? static_cast<std::uint64_t>(end - begin) : 0;
        continue;
      }
      addBoundaryFace[b] = 0;
      ++source.skinFacesCoveredBySurfaces;
      if (trackElements_)
        for (auto e = begin; e != end; ++e) recordCoveredElement(*e, boundary[b].face);
      if (!anyInterface) continue;
      // Among interfaces, edges meet three faces and shells cannot be oriented by their edges: the
      // surface element takes its volume's winding instead.
      for (auto e = begin; e != end; ++e) {
        alignWinding(*e, volumeFace);
        std::fill_n(sides_.side.begin() + e->firstFace, e->faceCount, FaceSide::kSkin);
      }
    }
  }
  if (!removedSurface.empty()) removeFaces(removedSurface);

  // Room for the faces added below (split in four where second order), so that no array grows by copies.
  std::size_t added = 0;
  for (std::size_t b = 0; b < boundary.size(); ++b) added += addBoundaryFace[b];
  const bool secondOrder = std::any_of(  // the types whose faces addVolumeFace splits
      volumeElements_.runs().begin(), volumeElements_.runs().end(),
      [](const MshVolumeElements::Run& run) { return run.type == 11 || run.type == 12 || run.type == 17; });
  reserveMoreFaces(added * (secondOrder ? 4 : 1));
  for (std::size_t b = 0; b < boundary.size(); ++b) {
    if (!addBoundaryFace[b]) continue;
    const MshVolumeFace face = volumeElements_.face(boundary[b].face);
    std::array<std::uint16_t, 9> order{};
    if (trackElements_) {
      element_ = volumeElements_.elementTagOfFace(boundary[b].face);
      order = volumeFaceNodeOrder(boundary[b].face, face);
      volumeFace_ = &face;
      volumeFaceNodeOrder_ = &order;
    }
    physical_ = groups_[face.group].first;
    entity_ = groups_[face.group].second;
    side_ = boundary[b].outer != kNoVertex ? FaceSide::kInterface : FaceSide::kSkin;
    if (side_ == FaceSide::kInterface) {
      const MshVolumeFace outer = volumeElements_.face(boundary[b].outer);
      outerPhysical_ = groups_[outer.group].first;
      outerEntity_ = groups_[outer.group].second;
      ++source.interfaceFaces;
    } else {
      outerPhysical_ = outerEntity_ = 0;
    }
    ++source.skinFaces;
    const std::size_t firstFace = faces_.size();
    addVolumeFace(face);
    if (!interfaceSurfaceOf.empty() && interfaceSurfaceOf[b] != kNoMergedSurface)
      showMergedSurfaceFirst(interfaceSurfaces[interfaceSurfaceOf[b]], firstFace);
  }
  volumeFace_ = nullptr;
  volumeElements_.clear();
}

}  // namespace lancer
