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

#include "lancer/accel/kd/query.hpp"
#include "lancer/accel/kd_tree.hpp"
#include "lancer/accel/packet_frame.hpp"

namespace lancer {
namespace {

using namespace accel;
using namespace kd;

#ifdef LANCER_PACKETS_AVX2

// The packet's rays (accel/packet_frame.hpp) with what the kd walk adds: per axis the split-plane
// band's edges and which child is near, as in the single-ray walk, and the slack of its decisions.
struct KdPacketFrame : PacketFrame {
  __m256 nearEdge[3], farEdge[3];
  __m256 eps;
  std::uint32_t firstIsRight[3];
};

// Sets up the frame of the lanes `active`, keeping in `active` those whose rays meet the scene box,
// with each one's interval in the box: the single-ray walk's set-up (intersectAabb and the bands)
// lane by lane. False when the rays run different ways along some axis.
bool setUpFrame(const RayPacket& packet, std::uint32_t& active, const Aabb& bounds, float magnitude,
                KdPacketFrame& f, __m256& tEnter, __m256& tExit) {
  loadPacketRays(packet, active, f);
  // intersectAabb, lane by lane (NaN from 0 * inf leaves the span as it is).
  const float lower[3] = {bounds.lower.x, bounds.lower.y, bounds.lower.z};
  const float upper[3] = {bounds.upper.x, bounds.upper.y, bounds.upper.z};
  __m256 tIn = loadLaneBounds(packet.tMin, active), tOut = loadLaneBounds(packet.tMax, active);
  for (int a = 0; a < 3; ++a) {
    const __m256 t0 = _mm256_mul_ps(_mm256_sub_ps(_mm256_set1_ps(lower[a]), f.origin[a]), f.invDirection[a]);
    const __m256 t1 = _mm256_mul_ps(_mm256_sub_ps(_mm256_set1_ps(upper[a]), f.origin[a]), f.invDirection[a]);
    const __m256 swap = _mm256_cmp_ps(t0, t1, _CMP_GT_OQ);
    const __m256 near = _mm256_blendv_ps(t0, t1, swap), far = _mm256_blendv_ps(t1, t0, swap);
    tIn = _mm256_blendv_ps(tIn, near, _mm256_cmp_ps(near, tIn, _CMP_GT_OQ));
    tOut = _mm256_blendv_ps(tOut, far, _mm256_cmp_ps(far, tOut, _CMP_LT_OQ));
  }
  active &= laneMask(_mm256_cmp_ps(tIn, tOut, _CMP_LE_OQ));
  const __m256 zero = _mm256_setzero_ps();
  const __m256 band = _mm256_mul_ps(
      _mm256_set1_ps(kPlaneSlack),
      _mm256_max_ps(
          _mm256_set1_ps(magnitude),
          _mm256_max_ps(_mm256_max_ps(absolute(f.origin[0]), absolute(f.origin[1])), absolute(f.origin[2]))));
  for (int a = 0; a < 3; ++a) {
    const __m256 towardsMinus = _mm256_cmp_ps(f.invDirection[a], zero, _CMP_LT_OQ);
    const std::uint32_t right = laneMask(towardsMinus) & active;
    if (right != 0 && right != active) return false;
    f.firstIsRight[a] = right != 0 ? 1u : 0u;
    const __m256 signedBand =
        _mm256_blendv_ps(band, _mm256_xor_ps(band, _mm256_set1_ps(-0.0f)), towardsMinus);
    f.nearEdge[a] = _mm256_add_ps(f.origin[a], signedBand);
    f.farEdge[a] = _mm256_sub_ps(f.origin[a], signedBand);
  }
  f.eps = _mm256_mul_ps(_mm256_set1_ps(kSlack), _mm256_max_ps(absolute(tIn), absolute(tOut)));
  tEnter = tIn;
  tExit = tOut;
  return true;
}

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
bool walkLane(const KdNode* base, const KdNode* node, const KdPacketFrame& f, int lane, float tEnter,
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
std::uint32_t walkPacket(std::span<const KdNode> layout, const KdPacketFrame& f, std::uint32_t active,
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
  // time against its one ray (accel/hit_query.hpp), with the packet's mailbox kept as testLeaf keeps it. A
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

template <typename Isa, typename Filter>
std::uint32_t KdTree::closestHitsOn(const RayPacket& packet, std::uint32_t active, const Filter& keeps,
                                    std::span<Hit, kPacketSize> hits) const {
  active &= kAllLanes;
#ifdef LANCER_PACKETS_AVX2
  if (std::popcount(active) < 2) return closestHitsOneByOne(packet, active, keeps, hits);
  KdPacketFrame frame;
  PacketClosestHit<Filter> query{packet, frame, keeps, {}, {}, {}};
  query.start(active, slivers_);
  std::uint32_t inBox = active;
  __m256 tEnter, tExit;
  if (!setUpFrame(packet, inBox, bounds_, magnitude_, frame, tEnter, tExit)) {
    return closestHitsOneByOne(packet, active, keeps, hits);
  }
  if (inBox != 0) walkPacket(layout_, frame, inBox, tEnter, tExit, query);
  return query.answer(active, hits);
#else
  return closestHitsOneByOne(packet, active, keeps, hits);
#endif
}

template <typename Isa, typename Filter>
std::uint32_t KdTree::anyHitsOn(const RayPacket& packet, std::uint32_t active, const Filter& keeps) const {
  active &= kAllLanes;
#ifdef LANCER_PACKETS_AVX2
  if (std::popcount(active) < 2) return anyHitsOneByOne(packet, active, keeps);
  const std::uint32_t blocked = lanesBlockedBySlivers(packet, active, slivers_, keeps);
  std::uint32_t inBox = active & ~blocked;
  if (inBox == 0) return blocked;
  KdPacketFrame frame;
  __m256 tEnter, tExit;
  if (!setUpFrame(packet, inBox, bounds_, magnitude_, frame, tEnter, tExit)) {
    return blocked | anyHitsOneByOne(packet, active & ~blocked, keeps);
  }
  if (inBox == 0) return blocked;
  PacketAnyHit<Filter> query{packet, frame, keeps, {}};
  query.start(inBox);
  return blocked | walkPacket(layout_, frame, inBox, tEnter, tExit, query);
#else
  return anyHitsOneByOne(packet, active, keeps);
#endif
}

template std::uint32_t KdTree::closestHitsOn<LANCER_ISA_TAG>(const RayPacket&, std::uint32_t,
                                                             const KeepEveryHit&,
                                                             std::span<Hit, kPacketSize>) const;
template std::uint32_t KdTree::closestHitsOn<LANCER_ISA_TAG>(const RayPacket&, std::uint32_t,
                                                             const HitFilter&,
                                                             std::span<Hit, kPacketSize>) const;
template std::uint32_t KdTree::anyHitsOn<LANCER_ISA_TAG>(const RayPacket&, std::uint32_t,
                                                         const KeepEveryHit&) const;
template std::uint32_t KdTree::anyHitsOn<LANCER_ISA_TAG>(const RayPacket&, std::uint32_t,
                                                         const HitFilter&) const;

}  // namespace lancer
