#include "lancer/accel/kd/build.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <string>
#include <thread>

#include "lancer/util/check.hpp"
#include "lancer/util/huge_pages.hpp"
#include "lancer/util/parallel_for.hpp"
#include "lancer/util/thread_count.hpp"

namespace lancer {

namespace {

bool isSliver(const std::array<Vec3, 3>& c) { return isSliverTriangle(c[0], c[1], c[2]); }

// Calls visit(face, corners) for each triangle of faces [begin, end), in face order, a quad as
// (0,1,2) then (0,2,3) like packTriangles.
template <typename Visit>
void forEachTriangle(std::span<const Vec3> positions, std::span<const MeshFace> faces, std::size_t begin,
                     std::size_t end, Visit&& visit) {
  for (std::size_t f = begin; f < end; ++f) {
    const MeshFace& face = faces[f];
    const int halves = face.isQuad() ? 2 : 1;
    for (int half = 0; half < halves; ++half) {
      visit(f, std::array<Vec3, 3>{positions[face.vertex[0]], positions[face.vertex[1 + half]],
                                   positions[face.vertex[2 + half]]});
    }
  }
}

}  // namespace

// Fixed by the face count, so that the result is the same on any thread count.
ChunkPlan gatherChunkPlan(std::size_t faceCount) { return {faceCount, 1 << 14}; }

KdBuildInput gatherTriangles(std::span<const Vec3> positions, std::span<const MeshFace> faces,
                             bool withCorners, int threads) {
  KdBuildInput input;
  input.faceCount = faces.size();
  input.positions = positions;
  input.faces = faces;
  // Faces in chunks: a first pass finds the slivers, a second writes the triangles where the
  // counts before them put them, in face order.
  const ChunkPlan plan = gatherChunkPlan(faces.size());
  std::vector<std::size_t>& first = input.chunkFirst;
  std::vector<std::size_t>& kept = input.chunkFirstTree;
  std::vector<std::size_t> dropped(plan.chunks + 1, 0);
  first.assign(plan.chunks + 1, 0);
  kept.assign(plan.chunks + 1, 0);
  for (std::size_t c = 0; c < plan.chunks; ++c) {
    std::size_t count = 0;
    for (std::size_t f = plan.begin(c); f < plan.begin(c + 1); ++f) count += faces[f].isQuad() ? 2 : 1;
    first[c + 1] = first[c] + count;
  }
  // Build events keep a triangle id in 30 bits, nodes a child index in 30 bits.
  if (first.back() > KdNode::kMaxIndex / 4) {
    throw std::length_error("kd-tree: " + std::to_string(first.back()) + " triangles, at most " +
                            std::to_string(KdNode::kMaxIndex / 4) + " supported");
  }
  std::vector<std::uint8_t>& sliver = input.sliver;
  sliver.resize(first.back());
  parallelChunks(plan, threads, [&](std::size_t chunk, std::size_t begin, std::size_t end) {
    std::size_t next = first[chunk], slivers = 0;
    forEachTriangle(positions, faces, begin, end, [&](std::size_t, const std::array<Vec3, 3>& corners) {
      sliver[next] = isSliver(corners);
      slivers += sliver[next++];
    });
    dropped[chunk + 1] = slivers;
    kept[chunk + 1] = next - first[chunk] - slivers;
  });
  for (std::size_t c = 0; c < plan.chunks; ++c) {
    kept[c + 1] += kept[c];
    dropped[c + 1] += dropped[c];
  }
  // Every element is overwritten below (on huge pages: a fault per 2 MiB, not per 4 KiB).
  input.triangles = vectorOnHugePages<PackedTriangle>(kept.back());
  input.treeTriangles = kept.back();
  if (withCorners) input.corners.resize(kept.back());
  input.slivers.resize(dropped.back());
  std::vector<Aabb> chunkBounds(plan.chunks);
  parallelChunks(plan, threads, [&](std::size_t chunk, std::size_t begin, std::size_t end) {
    std::size_t next = first[chunk], tree = kept[chunk], out = dropped[chunk];
    Aabb bounds;
    forEachTriangle(positions, faces, begin, end, [&](std::size_t f, const std::array<Vec3, 3>& corners) {
      const PackedTriangle packed{corners[0], corners[1], corners[2], static_cast<std::uint32_t>(f)};
      if (sliver[next++]) {
        input.slivers[out++] = packed;
        return;
      }
      if (withCorners) input.corners[tree] = corners;
      input.triangles[tree++] = packed;
      for (const Vec3& c : corners) bounds.extend(c);
    });
    chunkBounds[chunk] = bounds;
  });
  // Chunk by chunk in order: the first of equal extremes (+0 or -0) wins, as in one pass.
  for (const Aabb& bounds : chunkBounds) input.bounds.extend(bounds);
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
  setLeaf(node, triangles);
  return &node;
}

void BuildArena::setLeaf(BuildNode& node, std::span<const std::uint32_t> triangles) {
  node.axis = -1;
  node.leaf = {keepIds(triangles), static_cast<std::uint32_t>(triangles.size())};
}

const std::uint32_t* BuildArena::keepIds(std::span<const std::uint32_t> ids) {
  if (ids.empty()) return nullptr;
  if (ids.size() > blockRoom_) {
    const std::size_t size = std::max(ids.size(), nextBlockIds_);
    nextBlockIds_ = std::min(2 * nextBlockIds_, kMaxBlockIds);
    idBlocks_.push_back(std::make_unique_for_overwrite<std::uint32_t[]>(size));
    blockFree_ = idBlocks_.back().get();
    blockRoom_ = size;
  }
  std::uint32_t* at = blockFree_;
  std::copy(ids.begin(), ids.end(), at);
  blockFree_ += ids.size();
  blockRoom_ -= ids.size();
  return at;
}

BuildNode* BuildArena::inner(int axis, float split, BuildNode* left, BuildNode* right) {
  BuildNode& node = nodes.emplace_back();
  node.axis = static_cast<std::int8_t>(axis);
  node.split = split;
  node.child[0] = left;
  node.child[1] = right;
  return &node;
}

namespace {

// The planning walk: depth first from the root, leaf children first (their lists and triangles
// land right after the pair), giving each node its word, each leaf of 2+ triangles its list and
// each triangle its words at the first leaf that holds it; and the stats. It only counts: the
// stream is allocated once at its exact size, then written by the passes below.
// (Grouping a pair with its children's pairs in 64-byte lines, so a ray descends two levels per
// cache miss, measured no faster on the 1M bench bracket, within noise, so it is not done.)
struct LayoutPlan {
  std::size_t size = 0;
  std::vector<std::uint32_t> triangleWord;  // build triangle id -> word offset, or kUnset
  // Whether a triangle is placed, 1 bit each: the walk's check stays in the cache, and its writes
  // of triangleWord (read only by the parallel passes) do not wait for memory.
  std::vector<std::uint64_t> placed;
  AccelStats stats;
  double rootArea = 0;
  float traversalCost = 0, intersectionCost = 0;

  static constexpr std::uint32_t kUnset = 0xFFFFFFFFu;

  std::uint32_t allocate(std::size_t count) {
    const std::size_t at = size;
    if (at + count > KdNode::kMaxIndex) {
      throw std::length_error("kd-tree: layout over " + std::to_string(KdNode::kMaxIndex) + " words");
    }
    size = at + count;
    return static_cast<std::uint32_t>(at);
  }

  // Child pairs start at even words, so a pair never straddles a 16-byte block (nor a cache line).
  std::uint32_t allocatePair() {
    if (size % 2) allocate(1);
    return allocate(2);
  }

  void placeTriangle(std::uint32_t triangle) {
    std::uint64_t& bits = placed[triangle >> 6];
    const std::uint64_t bit = std::uint64_t(1) << (triangle & 63);
    if (bits & bit) return;
    bits |= bit;
    triangleWord[triangle] = allocate(KdTree::kTriangleWords);
  }

  void placeLeaf(BuildNode& node) {
    const std::span<const std::uint32_t> tris = node.leafIds();
    if (tris.empty()) {
      ++stats.emptyLeaves;
    } else if (tris.size() == 1) {
      placeTriangle(tris[0]);
    } else {
      node.list = allocate((tris.size() + 1) / 2);
      for (const std::uint32_t triangle : tris) placeTriangle(triangle);
    }
  }

  void place(std::uint32_t index, BuildNode& node, const Aabb& box, std::uint64_t depth) {
    node.word = index;
    ++stats.nodes;
    const double area = rootArea > 0 ? double(box.surfaceArea()) / rootArea : 0.0;
    if (node.axis < 0) {
      ++stats.leaves;
      stats.depth = std::max(stats.depth, depth);
      stats.triangleReferences += node.leaf.count;
      stats.sahCost += intersectionCost * double(node.leaf.count) * area;
      placeLeaf(node);
      return;
    }
    stats.sahCost += traversalCost * area;
    const std::uint32_t children = allocatePair();
    Aabb childBox[2] = {box, box};
    childBox[0].upper[node.axis] = node.split;
    childBox[1].lower[node.axis] = node.split;
    for (int leafPass : {1, 0}) {
      for (int k = 0; k < 2; ++k) {
        if ((node.child[k]->axis < 0) == bool(leafPass))
          place(children + std::uint32_t(k), *node.child[k], childBox[k], depth + 1);
      }
    }
  }
};

// The words of one placed node (and a leaf's list).
void writeNode(const BuildNode& node, const std::vector<std::uint32_t>& triangleWord, KdNode* words) {
  if (node.axis >= 0) {
    words[node.word] = KdNode::inner(node.axis, node.split, node.child[0]->word);
    return;
  }
  const std::span<const std::uint32_t> tris = node.leafIds();
  if (tris.empty()) {
    words[node.word] = KdNode::leaf(0, 0);
  } else if (tris.size() == 1) {
    words[node.word] = KdNode::leaf(triangleWord[tris[0]], 1);
  } else {
    auto* list = reinterpret_cast<char*>(words + node.list);
    for (std::size_t i = 0; i < tris.size(); ++i) {
      const std::uint32_t offset = triangleWord[tris[i]];
      std::memcpy(list + i * sizeof(std::uint32_t), &offset, sizeof offset);
    }
    words[node.word] = KdNode::leaf(node.list, node.leaf.count);
  }
}

}  // namespace

KdTree KdTreeAssembler::assemble(BuildNode& root, BuildArenas& arenas, KdBuildInput&& input,
                                 const KdBuildOptions& options, std::string kind, double buildSeconds) {
  std::vector<std::array<Vec3, 3>>().swap(input.corners);  // only the builders clip them
  // The layout's triangles are written from the mesh again (see KdBuildInput::positions).
  std::vector<PackedTriangle>().swap(input.triangles);
  LayoutPlan plan;
  plan.rootArea = input.bounds.surfaceArea();
  plan.traversalCost = options.traversalCost;
  plan.intersectionCost = options.intersectionCost;
  plan.triangleWord = vectorOnHugePages<std::uint32_t>(input.treeTriangles, LayoutPlan::kUnset);
  plan.placed.assign((input.treeTriangles + 63) / 64, 0);
  // Root alone at 0, a pad at 1, then sibling pairs at even words.
  plan.allocate(2);
  plan.place(0, root, input.bounds, 0);

  // One allocation at the exact size, on huge pages; unwritten words (the pad, pads before pairs,
  // the second half of an odd list's last word) keep KdNode's default, an empty leaf.
  std::vector<KdNode> words = vectorOnHugePages<KdNode>(plan.size);
  KdNode* out = words.data();
  const int threads = resolveThreads(options);
  // Nodes, arena by arena in chunks (a node the walk did not reach is skipped), then triangles.
  struct Range {
    const std::deque<BuildNode>* nodes;
    std::size_t begin, end;
  };
  std::vector<Range> ranges;
  constexpr std::size_t kNodesPerRange = 1 << 14;
  for (const BuildArena& arena : arenas.all()) {
    for (std::size_t at = 0; at < arena.nodes.size(); at += kNodesPerRange)
      ranges.push_back({&arena.nodes, at, std::min(arena.nodes.size(), at + kNodesPerRange)});
  }
  parallelFor(ranges.size(), threads, 1, [&](std::size_t r) {
    const Range& range = ranges[r];
    for (std::size_t i = range.begin; i < range.end; ++i) {
      const BuildNode& node = (*range.nodes)[i];
      if (node.word != BuildNode::kUnplaced) writeNode(node, plan.triangleWord, out);
    }
  });
  // The triangles, gathered again as gatherTriangles did (same chunks, same order, same slivers).
  parallelChunks(
      gatherChunkPlan(input.faces.size()), threads,
      [&](std::size_t chunk, std::size_t begin, std::size_t end) {
        std::size_t next = input.chunkFirst[chunk], tree = input.chunkFirstTree[chunk];
        forEachTriangle(
            input.positions, input.faces, begin, end, [&](std::size_t f, const std::array<Vec3, 3>& corners) {
              if (input.sliver[next++]) return;
              const std::uint32_t at = plan.triangleWord[tree++];
              if (at == LayoutPlan::kUnset) return;
              const PackedTriangle packed{corners[0], corners[1], corners[2], static_cast<std::uint32_t>(f)};
              std::memcpy(static_cast<void*>(out + at), &packed, sizeof packed);
            });
      });
  std::vector<std::uint32_t>().swap(plan.triangleWord);
  std::vector<std::uint64_t>().swap(plan.placed);

  KdTree tree;
  tree.layout_ = std::move(words);
  tree.slivers_ = std::move(input.slivers);
  tree.bounds_ = paddedBounds(input.bounds);
  if (!input.bounds.empty())
    tree.magnitude_ = std::max(maxComponent(abs(input.bounds.lower)), maxComponent(abs(input.bounds.upper)));

  AccelStats& stats = tree.stats_;
  stats = plan.stats;
  stats.kind = std::move(kind);
  stats.faces = input.faceCount;
  stats.triangles = input.treeTriangles + tree.slivers_.size();
  const std::uint64_t filled = stats.leaves - stats.emptyLeaves;
  stats.meanTrianglesPerLeaf = filled ? double(stats.triangleReferences) / double(filled) : 0.0;
  stats.buildSeconds = buildSeconds;
  stats.bytes = tree.layout_.capacity() * sizeof(KdNode) + tree.slivers_.capacity() * sizeof(PackedTriangle);
  return tree;
}

}  // namespace lancer
