// Builds a Mesh from the nodes and elements a .msh parser reads: splits second-order faces, turns
// volume elements into their skin and the interfaces between volumes, drops degenerate faces, keeps only the
// nodes faces use and recentres them on the bounding-box centre as float. Independent of the MSH version.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <set>
#include <span>
#include <utility>
#include <vector>

#include "lancer/mesh/mesh.hpp"
#include "lancer/mesh/msh/element_types.hpp"
#include "lancer/mesh/msh/field_mapping.hpp"
#include "lancer/mesh/msh/node_table.hpp"
#include "lancer/mesh/msh/volume_capture.hpp"
#include "lancer/mesh/msh/volume_skin.hpp"

namespace lancer {

// Where `node` is among the nodes of a volume face's element, `order` giving the element positions of
// the face's nodes; kAddedCentre when it is none of them.
std::uint16_t volumeFaceNodePosition(const MshVolumeFace& face, const std::array<std::uint16_t, 9>& order,
                                     std::uint32_t node);

class MshMeshAssembler {
 public:
  MshNodeTable nodes;
  // $NodeData steps with values in node-table order; finish() maps them onto the mesh's vertices.
  std::vector<MeshField> nodeFields;
  // $ElementData steps: values per record and the records' element tags; finish() gives every face
  // made from an element (split second-order faces, volume-skin faces) its element's value.
  struct ElementField {
    MeshField field;
    std::vector<std::uint64_t> tags;
  };
  std::vector<ElementField> elementFields;
  // Element-node data steps (ElementNodeData): each element's records; finish() gives every face
  // corner its element's value at that node.
  struct ElementNodeField {
    MeshField field;
    ElementNodeRecords records;
  };
  std::vector<ElementNodeField> elementNodeFields;
  // Set before the elements are read when the file has $ElementData or $ElementNodeData (reader.cpp
  // says when): faces then remember their element's tag and where each of their corners is among
  // the element's nodes (16 bytes per face, only for such files).
  void trackElements() {
    trackElements_ = true;
    volumeElements_.keepTags();
  }
  bool tracksElements() const { return trackElements_; }
  // An MSH 2 copy of an element (one per further physical group) that was skipped: $ElementData
  // values given for the copy go to the kept element.
  void aliasElement(std::uint64_t copy, std::uint64_t kept) {
    if (trackElements_) elementAliases_.emplace_back(copy, kept);
  }

  // Set before the elements are read: volume elements and the fields' values inside them are kept
  // too (mesh/volume/volume_mesh.hpp), for slices, isosurfaces, field lines and probes.
  void keepVolume() { volumeCapture_ = std::make_shared<MshVolumeCapture>(); }
  // After finish(): the volume, when it was asked for and the field sections are read (else null).
  std::shared_ptr<MshVolumeCapture> volumeCapture() const { return volumeCapture_; }
  // Threads for finish()'s passes (0: every core); the mesh does not depend on it.
  void setThreads(int threads) { threads_ = threads; }
  int threads() const { return threads_; }
  // Room for `count` faces (and their elements, when trackElements() came first).
  void reserveFaces(std::size_t count);
  // Room for `elements` volume elements of `elementNodes` nodes in all (from the block headers).
  void reserveVolumeElements(std::uint64_t elements, std::uint64_t elementNodes) {
    volumeElements_.reserve(elements, elementNodes);
  }
  // `count` volume elements of one type (mshVolumeShape knows it) in the current group, when no
  // volume is kept: returns where their node indices go (count x the type's node count, filled by
  // the caller) and, when tracking, their tags' place (else null).
  std::uint32_t* addVolumeElements(int type, std::uint64_t count, std::uint64_t** tags) {
    countByType_[static_cast<std::size_t>(type)] += count;
    if (volumeGroups_.empty() || volumeGroups_.back() != group_) volumeGroups_.push_back(group_);
    return volumeElements_.appendNodes(type, group_, count, tags);
  }
  bool keepsVolume() const { return volumeCapture_ != nullptr; }
  // Whether addTriangles() may take a block of 3-node triangles: when no element or side is tracked,
  // a triangle needs nothing but its corners and its group.
  bool takesTriangleBlocks() const { return !trackElements_ && !trackSides_; }
  // `count` 3-node triangles of the current group, as addElement(2, ...) would add them one by one:
  // returns where their corners go (filled by the caller, from any thread); their other per-face
  // arrays are filled here. Only where takesTriangleBlocks().
  MeshFace* addTriangles(std::size_t count) {
    countByType_[2] += count;
    const std::size_t first = faces_.size();
    faces_.resize(first + count);
    facePhysical_.resize(first + count, physical_);
    faceEntity_.resize(first + count, entity_);
    faceEdgeMask_.resize(first + count, 0b111);
    return faces_.data() + first;
  }
  // The physical and elementary tags of the elements that follow; dimension is the elements'.
  void setGroup(int dimension, std::int32_t physical, std::int32_t entity) {
    if (physical == physical_ && entity == entity_ && dimension == dimension_) return;
    changeGroup(dimension, physical, entity);
  }
  // nodeIndex: the element's nodes as indices into `nodes`, mshElementType(type).nodeCount of them.
  void addElement(int type, const std::uint32_t* nodeIndex, std::uint64_t tag = 0) {
    ++countByType_[static_cast<std::size_t>(type)];
    element_ = tag;
    if (trackElements_) {
      elementNodes_ = nodeIndex;
      if (type != elementType_) elementType_ = type, elementNodeCount_ = mshElementType(type).nodeCount;
    }
    switch (type) {
      case 2:
        addTriangle(nodeIndex[0], nodeIndex[1], nodeIndex[2], 0b111);
        break;
      case 3:
        addQuad(nodeIndex[0], nodeIndex[1], nodeIndex[2], nodeIndex[3], kAllEdges);
        break;
      default:
        addOtherElement(type, nodeIndex);
        break;
    }
  }
  // A surface mesh a caller made itself (lancer.Mesh from arrays: triangles and quads, corners
  // checked, one physical and entity tag per face), taken whole instead of nodes and elements; the
  // points are read in place (no copy), so they must outlive finish().
  void adoptSurfaceMesh(std::span<const Vec3d> points, std::vector<MeshFace> faces,
                        std::vector<std::int32_t> physical, std::vector<std::int32_t> entity);
  // Counts an element that is not read node by node (the caller skipped its nodes).
  void countElement(int type) { ++countByType_[static_cast<std::size_t>(type)]; }

  // partitions: number of mesh partitions the file declares (0 when not partitioned).
  Mesh finish(MeshSourceInfo source, std::vector<PhysicalGroup> namedGroups);
  // Asked before finish(): it then hands its node lookup and face elements to takeFieldMapping(),
  // for the reader's field sections, instead of freeing them.
  void keepFieldMapping() { keepFieldMapping_ = true; }
  std::shared_ptr<MshFieldMapping> takeFieldMapping() { return std::move(fieldMapping_); }

 private:
  void addTriangle(std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint8_t edgeMask) {
    faces_.push_back(MeshFace{{a, b, c, kNoVertex}});
    recordFace(edgeMask);
  }
  void addQuad(std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d, std::uint8_t edgeMask) {
    faces_.push_back(MeshFace{{a, b, c, d}});
    recordFace(edgeMask);
  }
  // The per-face arrays of the face just pushed.
  void recordFace(std::uint8_t edgeMask) {
    if (trackElements_) {
      faceElement_.push_back(element_);
      recordCornerNodes();
      if (!faceCoveredElement_.empty()) {
        faceCoveredElement_.push_back(kNoCoveredElement);
        faceCoveredCornerNode_.push_back({kNoElementNode, kNoElementNode, kNoElementNode, kNoElementNode});
      }
    }
    facePhysical_.push_back(physical_);
    faceEntity_.push_back(entity_);
    faceEdgeMask_.push_back(edgeMask);
    if (trackSides_) {
      sides_.side.push_back(side_);
      sides_.outerPhysicalTag.push_back(outerPhysical_);
      sides_.outerEntityTag.push_back(outerEntity_);
    }
  }
  // Where the corners of the face just pushed are among its element's nodes (faceCornerNode_).
  void recordCornerNodes();
  void addOtherElement(int type, const std::uint32_t* nodeIndex);
  void addVolumeElement(int type, const std::uint32_t* nodeIndex);
  void addHighOrderSurface(int type, const std::uint32_t* nodeIndex);
  Vec3d serendipityCentre(const std::uint32_t* corner, const std::uint32_t* mid) const;
  // A new node at the serendipity centre of an 8-node quad, remembering its sources for node data.
  std::uint32_t addDerivedCentre(const std::uint32_t* corner, const std::uint32_t* mid);
  void addSplitTriangle(const std::uint32_t* corner, const std::uint32_t* mid);
  void addSplitQuad(const std::uint32_t* corner, const std::uint32_t* mid, std::uint32_t centre);
  void changeGroup(int dimension, std::int32_t physical, std::int32_t entity);
  // A surface element as faces_[firstFace .. firstFace + faceCount) (four for a split second-order
  // element), with its corners in the file's order, for matching it with volume faces.
  struct SurfaceElementFaces {
    MshFaceKey key;
    std::uint32_t corner[4];
    std::uint32_t firstFace;
    std::uint32_t faceCount;
    bool operator<(const SurfaceElementFaces& other) const { return key < other.key; }
  };
  std::vector<SurfaceElementFaces> surfaceElementsByKey() const;
  void alignWinding(const SurfaceElementFaces& element, const MshVolumeFace& volumeFace);
  // The faces of a surface element that covers volume face `volumeFace` remember its element.
  void recordCoveredElement(const SurfaceElementFaces& element, std::uint32_t volumeFace);
  // A surface element merged into an interface (when tracking): its tag, and where each of its
  // faces' nodes is among its nodes (up to 9: a 9-node quad's), for the interface faces made after.
  struct MergedSurfaceElement {
    std::uint64_t element = 0;
    std::array<std::uint32_t, 9> node{};
    std::array<std::uint16_t, 9> position{};
    int count = 0;
  };
  static constexpr std::uint32_t kNoMergedSurface = 0xFFFFFFFFu;
  MergedSurfaceElement mergedSurfaceElement(const SurfaceElementFaces& element) const;
  // The interface faces from firstFace on show the merged surface element's records first, and
  // their volume element's (now the covered one) where it has none.
  void showMergedSurfaceFirst(const MergedSurfaceElement& merged, std::size_t firstFace);
  void moveFace(std::size_t to, std::size_t from);  // every per-face array
  void truncateFaces(std::size_t count);
  void reserveMoreFaces(std::size_t count);  // room for `count` more faces in every per-face array
  void removeFaces(const std::vector<std::uint8_t>& removed);
  void addVolumeFace(const MshVolumeFace& face);
  // Where each node of a volume face (MshVolumeFace's order) is among its element's nodes.
  std::array<std::uint16_t, 9> volumeFaceNodeOrder(std::uint32_t volumeFace, const MshVolumeFace& face) const;
  void appendVolumeBoundary(MeshSourceInfo& source);
  void mapElementFields(Mesh& mesh, const std::vector<MshCornerNodes>& cornerSlots,
                        const MshCoveredElements& covered);

  std::vector<MeshFace> faces_;
  std::vector<std::int32_t> facePhysical_;
  std::vector<std::int32_t> faceEntity_;
  std::vector<std::uint8_t> faceEdgeMask_;
  MshVolumeElements volumeElements_;  // their faces are the volume faces, numbered as there
  std::vector<std::array<std::uint32_t, 8>> derivedSources_;  // corners and mids of each derived centre
  bool trackElements_ = false;
  std::shared_ptr<MshVolumeCapture> volumeCapture_;                      // set by keepVolume()
  std::uint64_t element_ = 0;                                            // tag of the element being added
  std::vector<std::uint64_t> faceElement_;                               // per face, when tracking
  std::vector<std::pair<std::uint64_t, std::uint64_t>> elementAliases_;  // (copy, kept), when tracking
  // When tracking: per face, the position of each corner among its element's nodes (the order of
  // $ElementNodeData values; kAddedCentre for a centre lancer adds). While faces are added, the
  // nodes of the element at hand: elementNodes_ for a surface element, else volumeFaceNodeOrder_.
  std::vector<MshCornerNodes> faceCornerNode_;
  // When tracking and a surface element covers a volume's skin face, per face: the volume element
  // under it and where the face's corners are among that element's nodes (MshCoveredElements, in
  // corner order until finish()); empty otherwise, 16 bytes a face then.
  std::vector<std::uint64_t> faceCoveredElement_;
  std::vector<MshCornerNodes> faceCoveredCornerNode_;
  const std::uint32_t* elementNodes_ = nullptr;
  int elementType_ = 0;  // of elementNodeCount_
  int elementNodeCount_ = 0;
  const MshVolumeFace* volumeFace_ = nullptr;
  const std::array<std::uint16_t, 9>* volumeFaceNodeOrder_ = nullptr;
  std::vector<SurfaceElementFaces> secondOrderSurfaces_;  // split surface elements, for the skin
  FaceVolumeSides sides_;  // filled from the volume boundary on, and only when it has interfaces
  bool trackSides_ = false;
  FaceSide side_ = FaceSide::kSurface;
  std::int32_t outerPhysical_ = 0;
  std::int32_t outerEntity_ = 0;
  std::vector<std::pair<std::int32_t, std::int32_t>> groups_;  // (physical, entity) of volume faces
  std::vector<std::uint32_t> volumeGroups_;  // the groups of volume elements (each run of one, once)
  std::set<std::pair<int, std::int32_t>> physicalsSeen_;  // (dimension, physical tag)
  std::array<std::uint64_t, kMaxMshElementType + 1> countByType_{};
  int threads_ = 0;
  bool keepFieldMapping_ = false;
  std::shared_ptr<MshFieldMapping> fieldMapping_;
  std::span<const Vec3d> adoptedPoints_;  // adoptSurfaceMesh's points; else nodes.coords()
  int dimension_ = -1;
  std::int32_t physical_ = 0;
  std::int32_t entity_ = 0;
  std::uint32_t group_ = 0;
};

}  // namespace lancer
