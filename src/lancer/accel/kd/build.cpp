#include "lancer/accel/kd/build.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <string>
#include <thread>

#include "lancer/util/check.hpp"
#include "lancer/util/thread_count.hpp"

namespace lancer {

namespace {

// A triangle whose corners are collinear to within this sine of the corner angle: its
// determinant (the sum of the edge functions) is rounding noise, so a computed hit may lie anywhere
// on the ray.
constexpr double kSliverSine = 1e-4;

bool isSliver(const std::array<Vec3, 3>& c) {
  const Vec3d e1 = toDouble(c[1]) - toDouble(c[0]);
  const Vec3d e2 = toDouble(c[2]) - toDouble(c[0]);
  const Vec3d n = cross(e1, e2);
  return dot(n, n) <= kSliverSine * kSliverSine * dot(e1, e1) * dot(e2, e2);
}

}  // namespace

KdBuildInput gatherTriangles(std::span<const Vec3> positions, std::span<const MeshFace> faces,
                             bool withCorners) {
  KdBuildInput input;
  input.faceCount = faces.size();
  std::vector<PackedTriangle> packed = packTriangles(positions, faces);
  // Build events keep a triangle id in 30 bits, nodes a child index in 30 bits.
  if (packed.size() > KdNode::kMaxIndex / 4) {
    throw std::length_error("kd-tree: " + std::to_string(packed.size()) + " triangles, at most " +
                            std::to_string(KdNode::kMaxIndex / 4) + " supported");
  }
  input.triangles.reserve(packed.size());
  if (withCorners) input.corners.reserve(packed.size());
  std::size_t next = 0;
  for (const MeshFace& face : faces) {
    // Same corner order as packTriangles: (0,1,2) and, for a quad, (0,2,3).
    const int count = face.isQuad() ? 2 : 1;
    for (int half = 0; half < count; ++half, ++next) {
      const std::array<Vec3, 3> corners = {positions[face.vertex[0]], positions[face.vertex[1 + half]],
                                           positions[face.vertex[2 + half]]};
      if (isSliver(corners)) {
        input.slivers.push_back(packed[next]);
        continue;
      }
      input.triangles.push_back(packed[next]);
      if (withCorners) input.corners.push_back(corners);
      for (const Vec3& c : corners) input.bounds.extend(c);
    }
  }
  return input;
}

int resolveMaxDepth(const KdBuildOptions& options, std::size_t triangleCount) {
  int depth = options.maxDepth;
  if (depth <= 0) {
    depth =
        static_cast<int>(std::lround(8.0 + 1.3 * std::log2(double(std::max<std::size_t>(triangleCount, 1)))));
  }
  return std::clamp(depth, 0, KdTree::kMaxDepth);
}

int resolveThreads(const KdBuildOptions& options) { return resolveThreadCount(options.threads); }

BuildNode* BuildArena::leaf(std::span<const std::uint32_t> triangles) {
  BuildNode& node = nodes.emplace_back();
  node.arena = this;
  node.first = static_cast<std::uint32_t>(leafTriangles.size());
  node.count = static_cast<std::uint32_t>(triangles.size());
  leafTriangles.insert(leafTriangles.end(), triangles.begin(), triangles.end());
  return &node;
}

BuildNode* BuildArena::inner(int axis, float split, BuildNode* left, BuildNode* right) {
  BuildNode& node = nodes.emplace_back();
  node.axis = axis;
  node.split = split;
  node.child[0] = left;
  node.child[1] = right;
  return &node;
}

namespace {

struct Layout {
  // Counting pass: the same walk allocating nothing, only adding up the words, so that the stream
  // is allocated once at its exact size (reserving a bound and shrinking after kept both copies
  // alive at the build's memory peak: 72 + 60 bytes per triangle).
  bool counting = false;
  std::size_t counted = 0;
  std::vector<KdNode> words;                // the tree's layout_ stream
  std::vector<std::uint32_t> triangleWord;  // build triangle id -> word offset, or kUnset
  const std::vector<PackedTriangle>* triangles = nullptr;
  AccelStats stats;
  double rootArea = 0;
  float traversalCost = 0, intersectionCost = 0;

  static constexpr std::uint32_t kUnset = 0xFFFFFFFFu;

  std::size_t size() const { return counting ? counted : words.size(); }

  std::uint32_t allocate(std::size_t count) {
    const std::size_t at = size();
    if (at + count > KdNode::kMaxIndex) {
      throw std::length_error("kd-tree: layout over " + std::to_string(KdNode::kMaxIndex) + " words");
    }
    if (counting)
      counted = at + count;
    else
      words.resize(at + count);
    return static_cast<std::uint32_t>(at);
  }

  void set(std::uint32_t index, KdNode node) {
    if (!counting) words[index] = node;
  }

  // Child pairs start at even words, so a pair never straddles a 16-byte block (nor a cache line).
  std::uint32_t allocatePair() {
    if (size() % 2) allocate(1);
    return allocate(2);
  }

  // The triangle's offset, writing it at the end of the stream the first time a leaf uses it.
  std::uint32_t placeTriangle(std::uint32_t triangle) {
    if (triangleWord[triangle] == kUnset) {
      const std::uint32_t at = allocate(KdTree::kTriangleWords);
      if (!counting)
        std::memcpy(static_cast<void*>(words.data() + at), &(*triangles)[triangle], sizeof(PackedTriangle));
      triangleWord[triangle] = at;
    }
    return triangleWord[triangle];
  }

  void placeLeaf(std::uint32_t index, const BuildNode& node) {
    const std::uint32_t* tris = node.arena->leafTriangles.data() + node.first;
    if (node.count == 0) {
      ++stats.emptyLeaves;
      set(index, KdNode::leaf(0, 0));
    } else if (node.count == 1) {
      const std::uint32_t offset = placeTriangle(tris[0]);
      set(index, KdNode::leaf(offset, 1));
    } else {
      const std::uint32_t list = allocate((node.count + 1) / 2);
      for (std::uint32_t i = 0; i < node.count; ++i) {
        const std::uint32_t offset = placeTriangle(tris[i]);  // may grow `words`: index afresh
        if (!counting)
          std::memcpy(reinterpret_cast<char*>(words.data() + list) + i * sizeof(std::uint32_t), &offset,
                      sizeof offset);
      }
      set(index, KdNode::leaf(list, node.count));
    }
  }

  void place(std::uint32_t index, const BuildNode& node, const Aabb& box, std::uint64_t depth) {
    ++stats.nodes;
    const double area = rootArea > 0 ? double(box.surfaceArea()) / rootArea : 0.0;
    if (node.axis < 0) {
      ++stats.leaves;
      stats.depth = std::max(stats.depth, depth);
      stats.triangleReferences += node.count;
      stats.sahCost += intersectionCost * double(node.count) * area;
      placeLeaf(index, node);
      return;
    }
    stats.sahCost += traversalCost * area;
    // Depth-first, leaf children first: their lists and triangles land right after the pair.
    // (Grouping a pair with its children's pairs in 64-byte lines, so a ray descends two levels per
    // cache miss, measured no faster on the 1M bracket, within noise, so it is not done.)
    const std::uint32_t children = allocatePair();
    set(index, KdNode::inner(node.axis, node.split, children));
    Aabb childBox[2] = {box, box};
    childBox[0].upper[node.axis] = node.split;
    childBox[1].lower[node.axis] = node.split;
    for (int leafPass : {1, 0}) {
      for (int k = 0; k < 2; ++k) {
        if ((node.child[k]->axis < 0) == bool(leafPass))
          place(children + k, *node.child[k], childBox[k], depth + 1);
      }
    }
  }
};

// Pads the scene box so that rays clipped to it keep hits that rounding puts on its faces.
Aabb paddedBounds(const Aabb& box) {
  if (box.empty()) return box;
  const float pad = 1e-5f * maxComponent(box.extent()) + 1e-30f;
  Aabb padded = box;
  for (int axis = 0; axis < 3; ++axis) {
    padded.lower[axis] -= pad + 1e-6f * std::abs(box.lower[axis]);
    padded.upper[axis] += pad + 1e-6f * std::abs(box.upper[axis]);
  }
  return padded;
}

}  // namespace

KdTree KdTreeAssembler::assemble(const BuildNode& root, KdBuildInput&& input, const KdBuildOptions& options,
                                 std::string kind, double buildSeconds) {
  std::vector<std::array<Vec3, 3>>().swap(input.corners);  // only the builders clip them
  Layout layout;
  layout.triangles = &input.triangles;
  layout.rootArea = input.bounds.surfaceArea();
  layout.traversalCost = options.traversalCost;
  layout.intersectionCost = options.intersectionCost;
  for (const bool counting : {true, false}) {
    layout.counting = counting;
    layout.stats = {};
    layout.triangleWord.assign(input.triangles.size(), Layout::kUnset);
    if (!counting) layout.words.reserve(layout.counted);  // the exact size: one allocation
    // Root alone at 0, a pad at 1, then sibling pairs at even words.
    layout.allocate(2);
    layout.set(1, KdNode::leaf(0, 0));
    layout.place(0, root, input.bounds, 0);
  }
  LANCER_DCHECK(layout.words.size(), ==, layout.counted);
  std::vector<std::uint32_t>().swap(layout.triangleWord);

  KdTree tree;
  tree.layout_ = std::move(layout.words);
  tree.slivers_ = std::move(input.slivers);
  tree.bounds_ = paddedBounds(input.bounds);
  if (!input.bounds.empty())
    tree.magnitude_ = std::max(maxComponent(abs(input.bounds.lower)), maxComponent(abs(input.bounds.upper)));

  AccelStats& stats = tree.stats_;
  stats = layout.stats;
  stats.kind = std::move(kind);
  stats.faces = input.faceCount;
  stats.triangles = input.triangles.size() + tree.slivers_.size();
  const std::uint64_t filled = stats.leaves - stats.emptyLeaves;
  stats.meanTrianglesPerLeaf = filled ? double(stats.triangleReferences) / double(filled) : 0.0;
  stats.buildSeconds = buildSeconds;
  stats.bytes = tree.layout_.capacity() * sizeof(KdNode) + tree.slivers_.capacity() * sizeof(PackedTriangle);
  return tree;
}

}  // namespace lancer
