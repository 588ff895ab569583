// What the three kd-tree builders share (binned_build.cpp the default `kdtree-sah`, sah_build.cpp the
// exact `kdtree-sah-exact`, median_build.cpp `kdtree-median`): the gathered triangles they read, the
// temporary tree they write (in per-thread arenas), and the assembler that lays that tree out as the
// final KdTree. (The BVH, the default accelerator, has its own build in accel/bvh/.)
#pragma once

#include <array>
#include <cstdint>
#include <deque>
#include <memory>
#include <mutex>
#include <span>
#include <string>
#include <vector>

#include "lancer/accel/kd_tree.hpp"
#include "lancer/util/parallel_for.hpp"
#include "lancer/util/stopwatch.hpp"

namespace lancer {

// The triangles to build over, with their exact corners (the builders clip and bound these).
struct KdBuildInput {
  std::vector<PackedTriangle> triangles;  // tree triangles, index = build triangle id
  // Parallel to triangles, for the exact builder only (kdtree-sah-exact clips through spans of them);
  // the others read a triangle's corners from `triangles` (cornersOf): 36 bytes a triangle saved.
  std::vector<std::array<Vec3, 3>> corners;
  std::vector<PackedTriangle> slivers;  // kept out of the tree, see KdTree::slivers_
  Aabb bounds;                          // of the tree triangles
  std::uint64_t faceCount = 0;
  // Where `triangles` came from, so that the assembler can write the layout's triangles from the
  // mesh again once it has freed them: its peak then holds the layout and not a second copy of
  // every triangle (40 bytes a triangle). The spans must outlive the build (the scene's arrays do).
  std::span<const Vec3> positions;
  std::span<const MeshFace> faces;
  std::vector<std::uint8_t> sliver;         // per triangle in face order (a quad's two in turn)
  std::vector<std::size_t> chunkFirst;      // per chunk of gatherChunkPlan(): its first triangle
  std::vector<std::size_t> chunkFirstTree;  // ... and its first tree triangle
  std::size_t treeTriangles = 0;            // triangles.size(), kept once they are freed
};
// On up to `threads` threads (the result does not depend on how many).
ChunkPlan gatherChunkPlan(std::size_t faceCount);
KdBuildInput gatherTriangles(std::span<const Vec3> positions, std::span<const MeshFace> faces,
                             bool withCorners = false, int threads = 1);

inline std::array<Vec3, 3> cornersOf(const PackedTriangle& triangle) {
  return {triangle.v0, triangle.v1, triangle.v2};
}

// Deepest level the options allow for this many triangles.
int resolveMaxDepth(const KdBuildOptions& options, std::size_t triangleCount);
int resolveThreads(const KdBuildOptions& options);

struct BuildArena;

// A node of the temporary tree: inner (axis >= 0) with its two children, or a leaf (axis < 0) with
// its triangle ids, kept in its arena's id blocks. The tree has about one node a triangle, so the
// node's size counts in the build's peak memory: 32 bytes (the leaf's fields share the children's).
struct BuildNode {
  struct LeafIds {
    const std::uint32_t* ids;
    std::uint32_t count;
  };
  union {
    BuildNode* child[2] = {nullptr, nullptr};  // inner
    LeafIds leaf;                              // leaf (ids null when count is 0)
  };
  float split = 0;
  // Set by the assembler's planning walk: the node's word in the layout (kUnplaced for a node the
  // walk never reached, such as a subtree root copied into its parent's slot), and a leaf's list.
  std::uint32_t word = kUnplaced;
  std::uint32_t list = 0;
  std::int8_t axis = -1;
  static constexpr std::uint32_t kUnplaced = 0xFFFFFFFFu;

  std::span<const std::uint32_t> leafIds() const { return {leaf.ids, leaf.count}; }
};
static_assert(sizeof(BuildNode) == 32);

// One build thread's output; deque keeps node addresses stable while it grows.
struct BuildArena {
  std::deque<BuildNode> nodes;

  BuildNode* leaf(std::span<const std::uint32_t> triangles);
  BuildNode* inner(int axis, float split, BuildNode* left, BuildNode* right);
  // The same, filling a node allocated beforehand (in any arena): a builder that allocates a
  // cell's node when it enters the cell lays the nodes out in about the assembler's walk order.
  BuildNode* node() { return &nodes.emplace_back(); }
  void setLeaf(BuildNode& node, std::span<const std::uint32_t> triangles);

 private:
  // Leaves' triangle ids, each leaf's in one block; blocks never move (a growing vector would
  // hold the ids twice while it copies them, and up to twice their size after).
  const std::uint32_t* keepIds(std::span<const std::uint32_t> ids);
  std::vector<std::unique_ptr<std::uint32_t[]>> idBlocks_;
  std::uint32_t* blockFree_ = nullptr;
  std::size_t blockRoom_ = 0;
  std::size_t nextBlockIds_ = 1024;  // doubled up to kMaxBlockIds: small subtrees, small blocks
  static constexpr std::size_t kMaxBlockIds = std::size_t(1) << 16;
};

// Arenas for any number of threads; create() is the only call that needs the lock.
class BuildArenas {
 public:
  BuildArena& create() {
    std::lock_guard lock(mutex_);
    return arenas_.emplace_back();
  }
  // For the assembler, once the build is done.
  std::deque<BuildArena>& all() { return arenas_; }

 private:
  std::mutex mutex_;
  std::deque<BuildArena> arenas_;
};

// Lays the temporary tree out as one stream (KdTree::layout_): sibling-paired 8-byte nodes, each
// leaf's list and triangles written after the pair that holds it, and fills stats. A serial walk
// places every node, list and triangle (reading no triangle); the words are then written on
// options.threads threads, node by node of the arenas and triangle by triangle.
class KdTreeAssembler {
 public:
  // The steps every kd builder takes: the triangles gathered (with their corners for a builder that
  // clips through them), Builder(input, options, arenas).buildRoot() for the temporary tree, and its
  // layout, inside the timing (the user waits for all of it).
  template <typename Builder>
  static KdTree build(std::span<const Vec3> positions, std::span<const MeshFace> faces,
                      const KdBuildOptions& options, bool withCorners, std::string kind) {
    const Stopwatch stopwatch;
    KdBuildInput input = gatherTriangles(positions, faces, withCorners, options.threads);
    BuildArenas arenas;
    Builder builder(input, options, arenas);
    BuildNode* root = builder.buildRoot();
    KdTree tree = assemble(*root, arenas, std::move(input), options, std::move(kind), 0.0);
    tree.stats_.buildSeconds = stopwatch.seconds();
    return tree;
  }

  static KdTree assemble(BuildNode& root, BuildArenas& arenas, KdBuildInput&& input,
                         const KdBuildOptions& options, std::string kind, double buildSeconds);
};

}  // namespace lancer
