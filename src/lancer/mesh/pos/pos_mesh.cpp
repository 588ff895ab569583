#include "lancer/mesh/pos/pos_mesh.hpp"

#include <algorithm>
#include <array>
#include <optional>

#include "lancer/mesh/msh/mesh_assembler.hpp"
#include "lancer/mesh/pos/point_index.hpp"
#include "lancer/mesh/pos/pos_fields.hpp"

namespace lancer {
namespace {

constexpr int kMaxNodes = 27;  // a second-order hexahedron
constexpr std::size_t kPrefetchAhead = 4;

// The distinct elements of views that list different elements: an element is its type and its set
// of nodes, whatever their order (nothing says two views list one element's nodes alike). An
// open-addressing table on a hash of the sorted nodes.
class ElementIndex {
 public:
  struct Found {
    std::uint32_t id;
    bool added;
  };

  // The element's number, a new one (added) when it was not there. nodes: `count` node numbers.
  Found insert(int type, const std::uint32_t* nodes, int count) {
    std::array<std::uint32_t, kMaxNodes> sorted;
    std::copy_n(nodes, count, sorted.begin());
    std::sort(sorted.begin(), sorted.begin() + count);
    std::uint64_t h = static_cast<std::uint64_t>(type) * 0x9E3779B97F4A7C15ull;
    for (int i = 0; i < count; ++i)
      h = (h ^ (h >> 29) ^ sorted[static_cast<std::size_t>(i)]) * 0xBF58476D1CE4E5B9ull;
    h ^= h >> 32;
    std::size_t slot = h & mask_;
    for (;; slot = (slot + 1) & mask_) {
      const std::uint32_t id = slots_[slot];
      if (id == kNone) break;
      if (hashes_[id] == h && types_[id] == type && sameNodes(id, sorted.data(), count)) return {id, false};
    }
    const auto id = static_cast<std::uint32_t>(types_.size());
    types_.push_back(static_cast<std::uint8_t>(type));
    hashes_.push_back(h);
    first_.push_back(nodes_.size());
    nodes_.insert(nodes_.end(), nodes, nodes + count);
    slots_[slot] = id;
    if (types_.size() * 2 > slots_.size()) rehash(slots_.size() * 2);
    return {id, true};
  }
  // The nodes of element `id` in the order it was added with.
  const std::uint32_t* nodes(std::uint32_t id) const { return nodes_.data() + first_[id]; }

  explicit ElementIndex(std::size_t expected) {
    rehash(std::bit_ceil(std::max<std::size_t>(expected * 2, 64)));
    types_.reserve(expected);
    hashes_.reserve(expected);
    first_.reserve(expected);
  }

 private:
  static constexpr std::uint32_t kNone = 0xFFFFFFFFu;

  bool sameNodes(std::uint32_t id, const std::uint32_t* sorted, int count) const {
    std::array<std::uint32_t, kMaxNodes> kept;
    std::copy_n(nodes(id), count, kept.begin());
    std::sort(kept.begin(), kept.begin() + count);
    return std::equal(kept.begin(), kept.begin() + count, sorted);
  }
  void rehash(std::size_t size) {
    slots_.assign(size, kNone);
    mask_ = size - 1;
    for (std::uint32_t id = 0; id < types_.size(); ++id) {
      std::size_t slot = hashes_[id] & mask_;
      while (slots_[slot] != kNone) slot = (slot + 1) & mask_;
      slots_[slot] = id;
    }
  }

  std::vector<std::uint32_t> slots_;
  std::size_t mask_ = 0;
  std::vector<std::uint8_t> types_;
  std::vector<std::uint64_t> hashes_;
  std::vector<std::size_t> first_;
  std::vector<std::uint32_t> nodes_;
};

// Where each of `nodes` is among `kept` (the same set in another order); false when the order is the same.
bool nodeOrder(const std::uint32_t* nodes, const std::uint32_t* kept, int count,
               std::vector<std::uint8_t>& order) {
  if (std::equal(nodes, nodes + count, kept)) return false;
  for (int j = 0; j < count; ++j)
    order.push_back(static_cast<std::uint8_t>(std::find(kept, kept + count, nodes[j]) - kept));
  return true;
}

}  // namespace

Mesh meshFromPos(const PosFile& pos, MeshSourceInfo source, int threads) {
  // A view whose elements are an earlier view's, in the same order at the same coordinates (the
  // views of one GetDP Print region, of one gmsh mesh), takes that view's tags; elements are
  // matched one by one (ElementIndex) only when some view lists other elements than the first.
  std::vector<std::size_t> sameAs(pos.views.size(), pos.views.size());
  bool matchElements = false;
  std::size_t elementCount = 0, nodeRefs = 0, faceEstimate = 0;
  for (std::size_t v = 0; v < pos.views.size(); ++v) {
    for (std::size_t earlier = 0; earlier < v && sameAs[v] == pos.views.size(); ++earlier)
      if (sameAs[earlier] == pos.views.size() && sameElements(pos.views[earlier], pos.views[v]))
        sameAs[v] = earlier;
    if (sameAs[v] != pos.views.size()) continue;
    matchElements = matchElements || v > 0;
    for (const PosElementBlock& block : pos.views[v].blocks) {
      elementCount += block.elementCount();
      nodeRefs += block.elementCount() * static_cast<std::size_t>(block.kind.nodes);
      if (block.kind.dimension == 2) faceEstimate += block.elementCount();
    }
  }
  MshMeshAssembler assembler;
  assembler.setThreads(threads);
  assembler.trackElements();
  assembler.keepFieldMapping();
  assembler.reserveFaces(faceEstimate);
  // A triangle mesh has about a sixth as many nodes as node references: the table grows if not.
  PointIndex<double> points(nodeRefs / 6);
  std::optional<ElementIndex> elements;
  if (matchElements) elements.emplace(elementCount);
  std::uint32_t nextElement = 0;
  std::vector<PosElementTags> tags(pos.views.size());
  std::vector<int> components(pos.views.size());
  for (std::size_t v = 0; v < pos.views.size(); ++v) {
    const PosView& view = pos.views[v];
    components[v] = drawnComponents(view, pos.file);
    PosElementTags& viewTags = tags[v];
    if (sameAs[v] != pos.views.size()) {
      viewTags = tags[sameAs[v]];
      continue;
    }
    viewTags.tag.reserve(view.elementCount());
    for (const PosElementBlock& block : view.blocks) {
      const int type = block.kind.gmshType;
      const int count = block.kind.nodes;
      const bool drawn = drawnBlock(block);
      if (drawn) assembler.setGroup(block.kind.dimension, 0, 1);
      std::array<std::uint32_t, kMaxNodes> node;
      for (std::size_t e = 0; e < block.elementCount(); ++e) {
        const double* xyz = block.coords.data() + e * 3 * static_cast<std::size_t>(count);
        // The points of an element a few ahead: a point met for the first time misses in the large
        // table, and one element's work is too short to hide that miss.
        if (e + kPrefetchAhead < block.elementCount())
          for (int j = 0; j < count; ++j) {
            const double* next = xyz + 3 * (kPrefetchAhead * count + j);
            points.prefetch({next[0], next[1], next[2]});
          }
        for (int j = 0; j < count; ++j)
          node[static_cast<std::size_t>(j)] = points.insert({xyz[3 * j], xyz[3 * j + 1], xyz[3 * j + 2]});
        const ElementIndex::Found found =
            elements ? elements->insert(type, node.data(), count) : ElementIndex::Found{nextElement++, true};
        const std::uint64_t tag = found.id + std::uint64_t{1};
        if (found.added) {
          drawn ? assembler.addElement(type, node.data(), tag) : assembler.countElement(type);
        } else if (drawn) {
          const auto start = static_cast<std::uint32_t>(viewTags.order.size());
          if (nodeOrder(node.data(), elements->nodes(found.id), count, viewTags.order)) {
            viewTags.orderAt.resize(view.elementCount(), PosElementTags::kSameOrder);
            viewTags.orderAt[viewTags.tag.size()] = start;
          }
        }
        viewTags.tag.push_back(drawn ? tag : 0);
      }
    }
  }
  // Node tags 1..N in the order met, as a .msh file numbers them; the assembler reads them now.
  source.nodeCount = points.size();
  std::vector<std::uint64_t>& nodeTags = assembler.nodes.tags();
  nodeTags.resize(points.size());
  for (std::size_t i = 0; i < nodeTags.size(); ++i) nodeTags[i] = i + 1;
  assembler.nodes.coords() = std::move(points.points());
  Mesh mesh = assembler.finish(std::move(source), {});
  const std::shared_ptr<MshFieldMapping> mapping = assembler.takeFieldMapping();
  for (std::size_t v = 0; v < pos.views.size(); ++v)
    if (components[v] != 0)
      addPosViewSteps(mesh, pos.views[v], components[v], tags[v], mapping->faceElement,
                      mapping->faceCornerNode, mapping->covered);
  return mesh;
}

}  // namespace lancer
