#include "lancer/mesh/pos/pos_on_mesh.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <atomic>

#include "lancer/math/aabb.hpp"
#include "lancer/mesh/pos/point_index.hpp"
#include "lancer/mesh/pos/pos_fields.hpp"
#include "lancer/util/parallel_for.hpp"

namespace lancer {
namespace {

constexpr std::size_t kFaceGrain = 16384;

// A view's drawn elements by their nodes: the nodes numbered by their position as the mesh keeps
// positions (float, relative to its origin), and per node the elements that hold it.
class ViewElementsByNode {
 public:
  ViewElementsByNode(const PosView& view, const Vec3d& origin) {
    elementStart_.push_back(0);
    std::size_t refs = 0;
    for (const PosElementBlock& block : view.blocks)
      if (drawnBlock(block)) refs += block.elementCount() * static_cast<std::size_t>(block.kind.nodes);
    nodes_ = PointIndex<float>(refs / 6);
    elementNode_.reserve(refs);
    isVolume_.reserve(view.elementCount());
    for (const PosElementBlock& block : view.blocks) {
      const std::size_t count = drawnBlock(block) ? static_cast<std::size_t>(block.kind.nodes) : 0;
      for (std::size_t e = 0; e < block.elementCount(); ++e) {
        isVolume_.push_back(block.kind.dimension == 3);
        const double* xyz = block.coords.data() + e * 3 * static_cast<std::size_t>(block.kind.nodes);
        for (std::size_t j = 0; j < count; ++j)
          elementNode_.push_back(
              nodes_.insert(toFloat(Vec3d{xyz[3 * j], xyz[3 * j + 1], xyz[3 * j + 2]} - origin)));
        elementStart_.push_back(elementNode_.size());
      }
    }
    // Per node, its (element, local node) pairs: counted, then placed.
    nodeStart_.assign(nodes_.size() + 1, 0);
    for (const std::uint32_t node : elementNode_) ++nodeStart_[node + 1];
    for (std::size_t n = 0; n < nodes_.size(); ++n) nodeStart_[n + 1] += nodeStart_[n];
    holders_.resize(elementNode_.size());
    std::vector<std::size_t> next(nodeStart_.begin(), nodeStart_.end() - 1);
    for (std::size_t e = 0; e + 1 < elementStart_.size(); ++e)
      for (std::size_t i = elementStart_[e]; i < elementStart_[e + 1]; ++i)
        holders_[next[elementNode_[i]]++] = {static_cast<std::uint32_t>(e),
                                             static_cast<std::uint16_t>(i - elementStart_[e])};
  }

  // The element whose values `face` takes, among those holding every corner of the face among
  // their nodes: a surface element (the face itself, a view on a boundary or an interface) before
  // any volume element; between the two volume elements of an interface face, the one behind it
  // (the face is wound out of its inner volume, whose values the .msh path gives it too); else the
  // first in the view. Returns its number (from 1) and where each corner's slot (cornerSlot) is
  // among its nodes; 0 when no element holds the face.
  std::uint64_t match(const Mesh& mesh, const MeshFace& face, bool interface, MshCornerNodes& slots) const {
    std::uint32_t node[4];
    for (int c = 0; c < face.cornerCount(); ++c) {
      node[c] = nodes_.find(mesh.positions[face.vertex[c]]);
      if (node[c] == PointIndex<float>::kNone) return 0;
    }
    std::uint32_t chosen = kNoElement;
    std::uint16_t chosenLocal[4] = {};
    for (std::size_t h = nodeStart_[node[0]]; h < nodeStart_[node[0] + 1]; ++h) {
      const Holder holder = holders_[h];
      const std::uint32_t* first = elementNode_.data() + elementStart_[holder.element];
      const std::uint32_t* last = elementNode_.data() + elementStart_[holder.element + 1];
      std::uint16_t local[4] = {holder.local, 0, 0, 0};
      bool holdsAll = true;
      for (int c = 1; c < face.cornerCount() && holdsAll; ++c) {
        const std::uint32_t* at = std::find(first, last, node[c]);
        holdsAll = at != last;
        local[c] = static_cast<std::uint16_t>(at - first);
      }
      if (!holdsAll) continue;
      const bool surface = !isVolume_[holder.element];
      if (surface || chosen == kNoElement || (interface && behind(mesh, face, holder.element))) {
        chosen = holder.element;
        std::copy_n(local, 4, chosenLocal);
      }
      if (surface) break;
    }
    if (chosen == kNoElement) return 0;
    slots.fill(kNoElementNode);
    for (int c = 0; c < face.cornerCount(); ++c)
      slots[static_cast<std::size_t>(cornerSlot(face, c))] = chosenLocal[c];
    return chosen + std::uint64_t{1};
  }

 private:
  struct Holder {
    std::uint32_t element;
    std::uint16_t local;
  };
  static constexpr std::uint32_t kNoElement = 0xFFFFFFFFu;

  // Whether the element's centroid lies behind the face (against the normal its winding gives).
  bool behind(const Mesh& mesh, const MeshFace& face, std::uint32_t element) const {
    Vec3 centroid{};
    for (std::size_t i = elementStart_[element]; i < elementStart_[element + 1]; ++i)
      centroid += nodes_.points()[elementNode_[i]];
    centroid = centroid / static_cast<float>(elementStart_[element + 1] - elementStart_[element]);
    const Vec3& a = mesh.positions[face.vertex[0]];
    const Vec3 normal = cross(mesh.positions[face.vertex[1]] - a, mesh.positions[face.vertex[2]] - a);
    return dot(centroid - a, normal) < 0;
  }

  PointIndex<float> nodes_;
  std::vector<std::uint32_t> elementNode_;  // per element (every block's, in order), its nodes
  std::vector<std::size_t> elementStart_;
  std::vector<std::size_t> nodeStart_;
  std::vector<Holder> holders_;
  std::vector<std::uint8_t> isVolume_;  // per element: a volume element (else a surface element)
};

std::string describeBox(const Aabbd& box) {
  return fmt::format("[{:.6g}, {:.6g}, {:.6g}] .. [{:.6g}, {:.6g}, {:.6g}]", box.lower.x, box.lower.y,
                     box.lower.z, box.upper.x, box.upper.y, box.upper.z);
}

[[noreturn]] void failNoFaceMatched(const Mesh& mesh, const PosView& view, const std::string& file) {
  Aabbd viewBox, meshBox;
  std::size_t elements = 0;
  for (const PosElementBlock& block : view.blocks) {
    if (!drawnBlock(block)) continue;
    elements += block.elementCount();
    for (std::size_t i = 0; i + 2 < block.coords.size(); i += 3)
      viewBox.extend(Vec3d{block.coords[i], block.coords[i + 1], block.coords[i + 2]});
  }
  for (const MeshFace& face : mesh.faces)
    for (int c = 0; c < face.cornerCount(); ++c) meshBox.extend(mesh.worldPosition(face.vertex[c]));
  throw InputError(
      SourceLocation{file, view.line},
      fmt::format("view \"{}\" matches no face of {}: none of its {} elements has the corners of a face of "
                  "that mesh among its nodes (the view spans {}, the mesh {}); give the mesh the view was "
                  "computed on (the .msh the solver read), or draw the view on its own elements: "
                  "lancer render {}",
                  view.name, mesh.source.path, elements, describeBox(viewBox), describeBox(meshBox), file));
}

}  // namespace

void addPosViews(Mesh& mesh, const PosFile& pos) {
  std::vector<std::uint64_t> faceElement;
  std::vector<MshCornerNodes> faceCornerNode;
  const PosView* matched = nullptr;  // the view whose elements faceElement names
  for (const PosView& view : pos.views) {
    const int components = drawnComponents(view, pos.file);
    if (components == 0) {
      if (view.elementCount() > 0)
        mesh.source.warnings.push_back(formatInputWarning(
            SourceLocation{pos.file, view.line},
            fmt::format("view \"{}\" holds only points and lines, which lancer does not draw; skipped",
                        view.name)));
      continue;
    }
    if (!matched || !sameElements(*matched, view)) {
      const ViewElementsByNode elements(view, mesh.origin);
      faceElement.assign(mesh.faces.size(), 0);
      faceCornerNode.assign(mesh.faces.size(), MshCornerNodes{});
      std::atomic<std::size_t> covered{0};
      parallelChunks(
          ChunkPlan(mesh.faces.size(), kFaceGrain), 0, [&](std::size_t, std::size_t begin, std::size_t end) {
            std::size_t count = 0;
            for (std::size_t f = begin; f < end; ++f) {
              faceElement[f] =
                  elements.match(mesh, mesh.faces[f], mesh.volumeSides.isInterface(f), faceCornerNode[f]);
              count += faceElement[f] != 0;
            }
            covered += count;
          });
      if (covered == 0) failNoFaceMatched(mesh, view, pos.file);
      matched = &view;
    }
    PosElementTags tags;
    tags.tag.reserve(view.elementCount());
    for (const PosElementBlock& block : view.blocks)
      for (std::size_t e = 0; e < block.elementCount(); ++e)
        tags.tag.push_back(drawnBlock(block) ? tags.tag.size() + 1 : 0);
    addPosViewSteps(mesh, view, components, tags, faceElement, faceCornerNode);
  }
}

}  // namespace lancer
