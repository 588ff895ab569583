// The parts of the BVH build (bvh/build.cpp): face references, ranges of them with their bounds, the
// binned SAH split of a range (its bins also give both sides' bounds) and its partition.
#pragma once

#include <algorithm>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include "lancer/accel/bvh/bvh.hpp"
#include "lancer/math/aabb.hpp"

namespace lancer::bvh {

// One face as the build sees it: its box and how many triangles it holds (a quad two).
struct PrimRef {
  float lo[3];
  std::uint32_t face;
  float hi[3];
  std::uint32_t triangles;
};
static_assert(sizeof(PrimRef) == 32);

struct Box {
  float lo[3] = {std::numeric_limits<float>::infinity(), std::numeric_limits<float>::infinity(),
                 std::numeric_limits<float>::infinity()};
  float hi[3] = {-std::numeric_limits<float>::infinity(), -std::numeric_limits<float>::infinity(),
                 -std::numeric_limits<float>::infinity()};

  void extend(const float* lower, const float* upper) {
    for (int a = 0; a < 3; ++a) {
      lo[a] = std::min(lo[a], lower[a]);
      hi[a] = std::max(hi[a], upper[a]);
    }
  }
  void extend(const Box& b) { extend(b.lo, b.hi); }
  bool empty() const { return lo[0] > hi[0]; }
  float area() const {
    if (empty()) return 0.0f;
    const float x = hi[0] - lo[0], y = hi[1] - lo[1], z = hi[2] - lo[2];
    return 2.0f * (x * y + y * z + z * x);
  }
  Aabb aabb() const {
    Aabb box;
    if (!empty()) box = {{lo[0], lo[1], lo[2]}, {hi[0], hi[1], hi[2]}};
    return box;
  }
};

// Binary splits deeper than this take the middle reference (a balanced tree below), so that the
// traversal's fixed stack always suffices however the centroids fall: below it, middle splits over
// the clusters (at most 2^28, one a face at the face limit) and then inside a cluster (at most
// kMaxClusterReferences) halve what is left.
constexpr std::uint32_t kMaxBinnedDepth = 43;
constexpr std::uint32_t kMaxClusterReferences = 512;
static_assert(kMaxBinnedDepth + 28 + 9 <= BvhNode::kMaxDepth);

enum class SplitKind : std::uint8_t { Leaf, Binned, Median };

// How a range is split: at a bin boundary of its centroids along an axis, at its middle reference
// (centroids too close to bin), or not at all.
struct Split {
  SplitKind kind = SplitKind::Leaf;
  int axis = 0;
  int bins = 0;  // of the range's grid (fewer for small ranges)
  int bin = 0;   // the left side holds bins [0, bin)
  // The grid along `axis` (Grid's origin, scale and last bin there), so that the partition bins a
  // reference on that axis alone, in the same float operations.
  float origin = 0, scale = 0, lastBin = 0;
  float cost = 0;
  // A binned split's sides, read from the bins: their boxes and triangles.
  Box left, right;
  std::uint32_t leftTriangles = 0;
};

// References [begin, end) with the union of their boxes, of their centroids (as lo + hi, the
// centroid doubled) and the sum of their triangles.
struct Range {
  std::uint32_t begin = 0, end = 0;
  std::uint32_t triangles = 0;
  std::uint32_t depth = 0;          // of the binary split that made it
  std::uint32_t firstTriangle = 0;  // of its first reference, in leaf order
  Box bounds, centroids;
  Split split;

  std::size_t count() const { return end - begin; }
};

Range rangeOf(const PrimRef* refs, std::uint32_t begin, std::uint32_t end);

// Whether a range may end in a leaf: a range of faces may (its SAH decides), a range of clusters
// (bvh/build.cpp's top) only when it holds one.
enum class LeafRule : std::uint8_t { BySah, SingleReference };

// The binned SAH choice for `range`.
Split chooseSplit(const PrimRef* refs, const Range& range, const BvhBuildOptions& options, LeafRule rule);

// Splits `range` as its split says (references reordered in place), giving both sides' bounds and
// where their triangles start.
void partition(PrimRef* refs, const Range& range, Range& left, Range& right);

struct GatheredFaces {
  std::vector<PrimRef> refs;            // faces of the tree, in face order
  std::vector<PackedTriangle> slivers;  // faces with a sliver half, as triangles in face order
};
GatheredFaces gatherFaces(std::span<const Vec3> positions, std::span<const MeshFace> faces, int threads);

// What gatherFaces does for one face: whether it has a sliver half (isSliverTriangle; tested for every
// ray, outside the tree), its reference, its triangles (one, or a quad's two) into `out`.
bool isSliverFace(std::span<const Vec3> positions, const MeshFace& face);
PrimRef faceReference(std::span<const Vec3> positions, const MeshFace& face, std::uint32_t id);
void gatherSlivers(std::span<const Vec3> positions, const MeshFace& face, std::uint32_t id,
                   PackedTriangle* out);

}  // namespace lancer::bvh
