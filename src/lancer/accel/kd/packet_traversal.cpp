// Packet traversal of the kd-tree (Wald, Slusallek, Benthin & Wagner 2001, "Interactive Rendering
// with Coherent Ray Tracing"; Wald's thesis 2004, section 7.2): eight rays that run the same way
// along each axis walk the tree together, one SIMD lane each, with a mask of the lanes still
// active in the current subtree. Every lane makes exactly the decisions the single-ray walk
// (traversal.cpp) makes for it: the same cells, entered with the same intervals, pruned by the same
// bound, and the same triangle tests in the same order (the packet only skips the cells that no
// lane needs). So each lane's answer is the single ray's, to the bit. Rays that run different ways
// along some axis (different near children) are traced one by one.
#include <algorithm>
#include <bit>
#include <cmath>
#include <type_traits>

#include "lancer/accel/kd/packet_frame.hpp"
#include "lancer/accel/kd/query.hpp"
#include "lancer/accel/kd_tree.hpp"

namespace lancer {
namespace {

using namespace kd;

// The single-ray queries, lane by lane: the portable build, and packets whose rays diverge.
template <typename Filter>
std::uint32_t closestHitsOneByOne(const KdTree& tree, const RayPacket& packet, std::uint32_t active,
                                  const Filter& keeps, std::span<Hit, kPacketSize> hits) {
  std::uint32_t hitLanes = 0;
  for (std::uint32_t lanes = active; lanes != 0; lanes &= lanes - 1) {
    const int i = std::countr_zero(lanes);
    bool hit;
    if constexpr (std::is_same_v<Filter, HitFilter>) {
      hit = tree.intersect(packet.ray[i], packet.tMin[i], packet.tMax[i], keeps, hits[i]);
    } else {
      hit = tree.intersect(packet.ray[i], packet.tMin[i], packet.tMax[i], hits[i]);
    }
    hitLanes |= hit ? 1u << i : 0u;
  }
  return hitLanes;
}

template <typename Filter>
std::uint32_t anyHitsOneByOne(const KdTree& tree, const RayPacket& packet, std::uint32_t active,
                              const Filter& keeps) {
  std::uint32_t hitLanes = 0;
  for (std::uint32_t lanes = active; lanes != 0; lanes &= lanes - 1) {
    const int i = std::countr_zero(lanes);
    bool hit;
    if constexpr (std::is_same_v<Filter, HitFilter>) {
      hit = tree.occluded(packet.ray[i], packet.tMin[i], packet.tMax[i], keeps);
    } else {
      hit = tree.occluded(packet.ray[i], packet.tMin[i], packet.tMax[i]);
    }
    hitLanes |= hit ? 1u << i : 0u;
  }
  return hitLanes;
}

#ifdef LANCER_PACKETS_AVX2

// A cell the packet visits later: `lanes` enter it, and those of `direct` (which the single-ray
// walk would have gone to at once, without a look at its bound) are not pruned when it is popped.
struct alignas(32) PacketStackEntry {
  __m256 tEnter, tExit;
  std::uint32_t node, lanes, direct;
};

inline float laneOf(__m256 v, int lane) {
  alignas(32) float values[kPacketSize];
  _mm256_store_ps(values, v);
  return values[lane];
}

// The rest of a subtree for the one lane left in it: the single-ray walk's steps (traversal.cpp),
// in scalar, from `node` with the lane's interval; testLeaf(leaf, lanes) tests a leaf's triangles.
// Returns whether the lane is done (any-hit: blocked).
template <typename Query, typename TestLeaf>
bool walkLane(const KdNode* base, const KdNode* node, const PacketFrame& f, int lane, float tEnter,
              float tExit, const Query& query, TestLeaf& testLeaf) {
  float nearEdge[3], farEdge[3], invDirection[3];
  for (int a = 0; a < 3; ++a) {
    nearEdge[a] = laneOf(f.nearEdge[a], lane);
    farEdge[a] = laneOf(f.farEdge[a], lane);
    invDirection[a] = laneOf(f.invDirection[a], lane);
  }
  const float eps = laneOf(f.eps, lane);
  const std::uint32_t bit = 1u << lane;
  struct Entry {
    std::uint32_t node;
    float tEnter, tExit;
  } stack[KdTree::kMaxDepth + 2];
  int top = 0;
  while (true) {
    while (!node->isLeaf()) {
      const int axis = node->axis();
      const float split = node->split();
      const float tNear = (split - nearEdge[axis]) * invDirection[axis];
      const float tFar = (split - farEdge[axis]) * invDirection[axis];
      const KdNode* first = base + node->firstChild() + f.firstIsRight[axis];
      const KdNode* second = base + node->firstChild() + (f.firstIsRight[axis] ^ 1u);
      if (tNear > tExit + eps) {
        node = first;
      } else if (tFar < tEnter - eps) {
        node = second;
      } else {
        stack[top++] = {static_cast<std::uint32_t>(second - base), tNear > tEnter ? tNear : tEnter, tExit};
        if (!second->isLeaf()) __builtin_prefetch(base + second->firstChild());
        node = first;
        tExit = tFar < tExit ? tFar : tExit;
      }
    }
    if (testLeaf(node, bit) != 0) return true;
    do {
      if (top == 0) return false;
      --top;
      node = base + stack[top].node;
      tEnter = stack[top].tEnter;
      tExit = stack[top].tExit;
    } while (tEnter > query.laneBound(lane) + eps);
  }
}

// Walks the tree with the lanes `active`; Query::test(tri, lanes) tests a triangle on some lanes
// and returns those that are done (any-hit: blocked), Query::bound() is each lane's pruning
// distance. A lane left alone in a subtree finishes it on its own (walkLane). Returns the lanes
// that are done.
template <typename Query>
std::uint32_t walkPacket(std::span<const KdNode> layout, const PacketFrame& f, std::uint32_t active,
                         __m256 tEnter, __m256 tExit, Query& query) {
  PacketStackEntry stack[KdTree::kMaxDepth + 2];
  struct MailboxSlot {
    std::uint32_t triangle = 0xFFFFFFFFu, lanes = 0;
  } mailbox[kMailboxSize];
  int top = 0;
  std::uint32_t done = 0;
  std::uint32_t lanes = active;
  const KdNode* base = layout.data();
  const KdNode* node = base;
  // Tests a leaf's triangles on `lanes`; returns the lanes that are done.
  auto testLeaf = [&](const KdNode* leaf, std::uint32_t testLanes) {
    const std::uint32_t count = leaf->triangleCount();
    const std::uint32_t* index =
        count == 1 ? &leaf->payload : reinterpret_cast<const std::uint32_t*>(base + leaf->payload);
    for (std::uint32_t i = 0; i < count; ++i) {
      const char* tri = reinterpret_cast<const char*>(base + index[i]);
      __builtin_prefetch(tri);
      __builtin_prefetch(tri + sizeof(PackedTriangle) - 1);
    }
    std::uint32_t finishedLanes = 0;
    for (std::uint32_t i = 0; i < count && testLanes != 0; ++i) {
      const std::uint32_t triangle = index[i];
      // One mailbox for the packet, remembering which lanes tested each triangle.
      MailboxSlot& slot = mailbox[triangle & (kMailboxSize - 1)];
      std::uint32_t untested = testLanes;
      if (slot.triangle == triangle) {
        untested &= ~slot.lanes;
        slot.lanes |= testLanes;
      } else {
        slot = {triangle, testLanes};
      }
      if (untested == 0) continue;
      const std::uint32_t finished =
          query.test(*reinterpret_cast<const PackedTriangle*>(base + triangle), untested);
      finishedLanes |= finished;
      testLanes &= ~finished;
    }
    return finishedLanes;
  };
  // The same for a lane left alone in a subtree (walkLane): the triangles of a larger leaf eight at a
  // time against its one ray (kd/query.hpp), with the packet's mailbox kept as testLeaf keeps it. A
  // triangle marked tested whose test an any-hit lane then skips, being blocked, is never tested again
  // by that lane anyway; an evicted slot only makes another lane test a triangle again, which gives
  // the same answer (as in the single-ray walk).
  auto testLeafAlone = [&](const KdNode* leaf, std::uint32_t bit) {
#ifdef LANCER_LEAF_AVX2
    const std::uint32_t count = leaf->triangleCount();
    if (count < kMinSimdLeaf) return testLeaf(leaf, bit);
    const int lane = std::countr_zero(bit);
    const std::uint32_t* index = reinterpret_cast<const std::uint32_t*>(base + leaf->payload);
    for (std::uint32_t i = 0; i < count; ++i) {
      const char* tri = reinterpret_cast<const char*>(base + index[i]);
      __builtin_prefetch(tri);
      __builtin_prefetch(tri + sizeof(PackedTriangle) - 1);
    }
    std::uint32_t pending[8];
    for (std::uint32_t i = 0; i < count;) {
      std::uint32_t n = 0;
      for (; i < count && n < 8; ++i) {
        const std::uint32_t triangle = index[i];
        MailboxSlot& slot = mailbox[triangle & (kMailboxSize - 1)];
        if (slot.triangle == triangle) {
          if ((slot.lanes & bit) != 0) continue;
          slot.lanes |= bit;
        } else {
          slot = {triangle, bit};
        }
        pending[n++] = triangle;
      }
      if (n == 0) break;
      LeafCorners corners;
      for (std::uint32_t passed = sameSignTriangles(base, pending, n, query.packet.ray[lane], corners);
           passed != 0; passed &= passed - 1) {
        const int k = std::countr_zero(passed);
        if (query.finishAlone(*reinterpret_cast<const PackedTriangle*>(base + pending[k]), lane, corners, k))
          return bit;
      }
    }
    return 0u;
#else
    return testLeaf(leaf, bit);
#endif
  };
  while (true) {
    bool alone = false;
    while (!node->isLeaf()) {
      if ((lanes & (lanes - 1)) == 0) {
        alone = true;
        break;
      }
      const int axis = node->axis();
      const __m256 split = _mm256_set1_ps(node->split());
      const __m256 tNear = _mm256_mul_ps(_mm256_sub_ps(split, f.nearEdge[axis]), f.invDirection[axis]);
      const __m256 tFar = _mm256_mul_ps(_mm256_sub_ps(split, f.farEdge[axis]), f.invDirection[axis]);
      // The single-ray walk's three cases per lane: only the first child (tNear beyond the cell),
      // only the second (tFar before it), or both, the second from tNear on and the first up to tFar.
      const std::uint32_t beyond =
          laneMask(_mm256_cmp_ps(tNear, _mm256_add_ps(tExit, f.eps), _CMP_GT_OQ)) & lanes;
      const std::uint32_t before =
          laneMask(_mm256_cmp_ps(tFar, _mm256_sub_ps(tEnter, f.eps), _CMP_LT_OQ)) & lanes & ~beyond;
      const std::uint32_t firstLanes = lanes & ~before, secondLanes = lanes & ~beyond;
      const std::uint32_t firstIsRight = f.firstIsRight[axis];
      const KdNode* first = base + node->firstChild() + firstIsRight;
      const KdNode* second = base + node->firstChild() + (firstIsRight ^ 1u);
      const __m256 secondEnter = _mm256_blendv_ps(tEnter, tNear, _mm256_cmp_ps(tNear, tEnter, _CMP_GT_OQ));
      const __m256 firstExit = _mm256_blendv_ps(tExit, tFar, _mm256_cmp_ps(tFar, tExit, _CMP_LT_OQ));
      if (secondLanes == 0) {
        node = first;
      } else if (firstLanes == 0) {
        node = second;
        tEnter = secondEnter;
        lanes = secondLanes;
        continue;
      } else {
        stack[top++] = {secondEnter, tExit, static_cast<std::uint32_t>(second - base), secondLanes, before};
        if (!second->isLeaf()) __builtin_prefetch(base + second->firstChild());
        node = first;
      }
      // Lanes that only go to the first child keep their exit: tFar is beyond it (see traversal.cpp).
      tExit = firstExit;
      lanes = firstLanes;
    }
    std::uint32_t finished;
    if (alone) {
      const int lane = std::countr_zero(lanes);
      finished =
          walkLane(base, node, f, lane, laneOf(tEnter, lane), laneOf(tExit, lane), query, testLeafAlone)
              ? lanes
              : 0u;
    } else {
      finished = testLeaf(node, lanes);
    }
    if (finished != 0) {
      done |= finished;
      if ((active & ~done) == 0) return done;
    }
    do {
      if (top == 0) return done;
      --top;
      node = base + stack[top].node;
      tEnter = stack[top].tEnter;
      tExit = stack[top].tExit;
      // Cells further than a lane's best hit (plus slack) cannot hold a closer or tied hit.
      const std::uint32_t pruned =
          laneMask(_mm256_cmp_ps(tEnter, _mm256_add_ps(query.bound(), f.eps), _CMP_GT_OQ)) &
          ~stack[top].direct;
      lanes = stack[top].lanes & ~done & ~pruned;
    } while (lanes == 0);
  }
}

#endif  // LANCER_PACKETS_AVX2

}  // namespace

template <typename Filter>
std::uint32_t KdTree::closestHits(const RayPacket& packet, std::uint32_t active, const Filter& keeps,
                                  std::span<Hit, kPacketSize> hits) const {
  active &= kAllLanes;
#ifdef LANCER_PACKETS_AVX2
  if (std::popcount(active) < 2) return closestHitsOneByOne(*this, packet, active, keeps, hits);
  PacketFrame frame;
  PacketClosestHit<Filter> query{packet, frame, keeps, {}, {}, {}};
  for (std::uint32_t lanes = active; lanes != 0; lanes &= lanes - 1) {
    const int i = std::countr_zero(lanes);
    query.best[i] = Hit{packet.tMax[i], Hit{}.face};
    query.upper[i] = packet.tMax[i];
    for (const PackedTriangle& tri : slivers_) {
      takeIfCloser(testTriangle(tri, packet.ray[i], packet.tMin[i], query.upper[i]), tri.face, packet.ray[i],
                   packet.tMax[i], keeps, query.best[i], query.upper[i]);
    }
    query.bestT[i] = query.best[i].t;
  }
  std::uint32_t inBox = active;
  __m256 tEnter, tExit;
  if (!setUpFrame(packet, inBox, bounds_, magnitude_, frame, tEnter, tExit)) {
    return closestHitsOneByOne(*this, packet, active, keeps, hits);
  }
  if (inBox != 0) walkPacket(layout_, frame, inBox, tEnter, tExit, query);
  std::uint32_t hitLanes = 0;
  for (std::uint32_t lanes = active; lanes != 0; lanes &= lanes - 1) {
    const int i = std::countr_zero(lanes);
    if (!query.best[i].valid()) continue;
    hits[i] = query.best[i];
    hitLanes |= 1u << i;
  }
  return hitLanes;
#else
  return closestHitsOneByOne(*this, packet, active, keeps, hits);
#endif
}

template <typename Filter>
std::uint32_t KdTree::anyHits(const RayPacket& packet, std::uint32_t active, const Filter& keeps) const {
  active &= kAllLanes;
#ifdef LANCER_PACKETS_AVX2
  if (std::popcount(active) < 2) return anyHitsOneByOne(*this, packet, active, keeps);
  std::uint32_t blocked = 0;
  for (std::uint32_t lanes = active; lanes != 0 && !slivers_.empty(); lanes &= lanes - 1) {
    const int i = std::countr_zero(lanes);
    for (const PackedTriangle& tri : slivers_) {
      const float t = intersectTriangle(tri, packet.ray[i], packet.tMin[i], packet.tMax[i]);
      if (t >= 0.0f && keeps(packet.ray[i], tri.face, t)) {
        blocked |= 1u << i;
        break;
      }
    }
  }
  std::uint32_t inBox = active & ~blocked;
  if (inBox == 0) return blocked;
  PacketFrame frame;
  __m256 tEnter, tExit;
  if (!setUpFrame(packet, inBox, bounds_, magnitude_, frame, tEnter, tExit)) {
    return blocked | anyHitsOneByOne(*this, packet, active & ~blocked, keeps);
  }
  if (inBox == 0) return blocked;
  PacketAnyHit<Filter> query{packet, frame, keeps, {}};
  for (int i = 0; i < kPacketSize; ++i) query.tMax[i] = (inBox >> i & 1u) != 0 ? packet.tMax[i] : 0.0f;
  return blocked | walkPacket(layout_, frame, inBox, tEnter, tExit, query);
#else
  return anyHitsOneByOne(*this, packet, active, keeps);
#endif
}

std::uint32_t KdTree::intersect(const RayPacket& packet, std::uint32_t active,
                                std::span<Hit, kPacketSize> hits) const {
  return closestHits(packet, active, KeepEveryHit{}, hits);
}

std::uint32_t KdTree::occluded(const RayPacket& packet, std::uint32_t active) const {
  return anyHits(packet, active, KeepEveryHit{});
}

std::uint32_t KdTree::intersect(const RayPacket& packet, std::uint32_t active, const HitFilter& filter,
                                std::span<Hit, kPacketSize> hits) const {
  return closestHits(packet, active, filter, hits);
}

std::uint32_t KdTree::occluded(const RayPacket& packet, std::uint32_t active, const HitFilter& filter) const {
  return anyHits(packet, active, filter);
}

}  // namespace lancer
