// Front-to-back kd-tree traversal with a fixed stack (pbrt-v3 section 4.4.4, Havran's thesis
// appendix C). Exactness: triangle hits are accepted wherever they lie, not just inside the current
// cell, a ray within a thin band of a split plane visits both sides, and cells are pruned only when
// clearly beyond the best hit, so a hit on or near a split plane (a ray through a shared edge lying
// in the plane) reaches the same tie-break as the brute-force loop.
#include <algorithm>
#include <bit>
#include <cmath>
#include <iterator>
#include <limits>

#include "lancer/accel/kd/query.hpp"
#include "lancer/accel/kd_tree.hpp"

namespace lancer {

#ifdef LANCER_KD_COUNTERS
#if defined(LANCER_ISA_X86_64_V3)
extern thread_local KdTraversalCounters kdCounters;  // the baseline copy's (this file is built twice)
#else
thread_local KdTraversalCounters kdCounters;
KdTraversalCounters& kdTraversalCounters() { return kdCounters; }
#endif
#define LANCER_KD_COUNT(field) ++kdCounters.field
#else
#define LANCER_KD_COUNT(field) ((void)0)
#endif

namespace {

using namespace accel;
using namespace kd;

struct StackEntry {
  std::uint32_t node;
  float tEnter, tExit;
};

// Walks the tree; Query::test returns true to stop (any hit). Query::bound is the current pruning
// distance: the closest hit so far, or tMax for any-hit.
template <typename Query>
bool walk(std::span<const KdNode> layout, const Aabb& bounds, float magnitude, const Ray& ray, float tMin,
          float tMax, Query& query) {
  float tEnter, tExit;
  if (!intersectAabb(bounds, ray, tMin, tMax, tEnter, tExit)) return false;
  const float eps = kSlack * std::max(std::abs(tEnter), std::abs(tExit));
  // Indexable copies: Vec3's operator[] is a select chain, too slow for the inner loop.
  const float origin[3] = {ray.origin.x, ray.origin.y, ray.origin.z};
  const float invDirection[3] = {ray.invDirection.x, ray.invDirection.y, ray.invDirection.z};
  // Half-width of the band around each split plane that counts as on both sides (kPlaneSlack),
  // signed along the ray so that the ray is inside the band for t in [tNear, tFar] below.
  const float band = kPlaneSlack * std::max(magnitude, maxComponent(abs(ray.origin)));
  // Per axis, once per ray: where the band's near and far edges sit relative to the origin, and
  // which child the ray meets first (the right one when it runs towards -axis).
  float nearEdge[3], farEdge[3];
  std::uint32_t firstIsRight[3];
  for (int a = 0; a < 3; ++a) {
    const float signedBand = invDirection[a] < 0.0f ? -band : band;
    nearEdge[a] = origin[a] + signedBand;
    farEdge[a] = origin[a] - signedBand;
    firstIsRight[a] = invDirection[a] < 0.0f ? 1u : 0u;
  }
  StackEntry stack[KdTree::kMaxDepth + 2];  // one push per level at most
  std::uint32_t mailbox[kMailboxSize];
  std::fill(std::begin(mailbox), std::end(mailbox), 0xFFFFFFFFu);
  int top = 0;
  const KdNode* base = layout.data();
  const KdNode* node = base;
  while (true) {
    while (!node->isLeaf()) {
      LANCER_KD_COUNT(innerNodes);
      const int axis = node->axis();
      const float split = node->split();
      // The ray enters the band around the plane at tNear and leaves it at tFar: the first child
      // (the side it starts on) holds t < tFar, the second t > tNear. A ray inside the band and
      // parallel to the plane gets infinite or NaN values, which fail every test below and so
      // visit both children over the whole span.
      const float tNear = (split - nearEdge[axis]) * invDirection[axis];
      const float tFar = (split - farEdge[axis]) * invDirection[axis];
      const KdNode* first = base + node->firstChild() + firstIsRight[axis];
      const KdNode* second = base + node->firstChild() + (firstIsRight[axis] ^ 1u);
      if (tNear > tExit + eps) {
        node = first;
      } else if (tFar < tEnter - eps) {
        node = second;
      } else if (second->bits == KdNode::kLeafTag) {
        // Both sides, but the far one is an empty leaf (a third of the leaves the SAH trees of
        // examples/glass_and_mirror.toml show a ray): nothing to visit there, nothing to push.
        node = first;
        tExit = tFar < tExit ? tFar : tExit;
      } else if (first->bits == KdNode::kLeafTag) {
        // The near side is empty: straight to the far one, pruned as a pop would prune it (no test
        // in between can have moved the bound); a pruned one goes to the empty leaf, which pops.
        const float secondEnter = tNear > tEnter ? tNear : tEnter;
        if (secondEnter > query.bound(tMax) + eps) {
          node = first;
        } else {
          node = second;
          tEnter = secondEnter;
        }
      } else {
        stack[top++] = {static_cast<std::uint32_t>(second - base), tNear > tEnter ? tNear : tEnter, tExit};
        // The far child's children lie far away in memory (depth-first layout): start their fetch
        // now, so the miss overlaps the near subtree's work instead of stalling the pop.
        if (!second->isLeaf()) __builtin_prefetch(base + second->firstChild());
        node = first;
        tExit = tFar < tExit ? tFar : tExit;
      }
    }
    const std::uint32_t count = node->triangleCount();
    LANCER_KD_COUNT(leaves);
    // Word offsets of the leaf's triangles: in the node itself for one, else a list in the layout.
    const std::uint32_t* index =
        count == 1 ? &node->payload : reinterpret_cast<const std::uint32_t*>(base + node->payload);
    // Fetch all of the leaf's triangles at once (independent misses overlap) before testing them.
    for (std::uint32_t i = 0; i < count; ++i) {
      const char* tri = reinterpret_cast<const char*>(base + index[i]);
      __builtin_prefetch(tri);
      __builtin_prefetch(tri + sizeof(PackedTriangle) - 1);
    }
#ifdef LANCER_LEAF_AVX2
    if (count >= kMinSimdLeaf) {
      // The mailbox's decisions first, in order (they depend only on the indices), then the
      // triangles left eight at a time; the passing ones are finished in the same order as the
      // scalar loop, each with the bound the ones before it left, so the answer is the same.
      std::uint32_t pending[8];
      for (std::uint32_t i = 0; i < count;) {
        std::uint32_t n = 0;
        for (; i < count && n < 8; ++i) {
          const std::uint32_t triangle = index[i];
          std::uint32_t& slot = mailbox[triangle & (kMailboxSize - 1)];
          if (slot == triangle) continue;
          slot = triangle;
          pending[n++] = triangle;
          LANCER_KD_COUNT(triangleTests);
        }
        if (n == 0) break;
        if (n < kMinSimdLeaf) {  // what the mailbox left is too few to be worth the transpose
          for (std::uint32_t k = 0; k < n; ++k) {
            if (query.test(*reinterpret_cast<const PackedTriangle*>(base + pending[k]), ray, tMin, tMax))
              return true;
          }
          continue;
        }
        LeafCorners c;
        for (std::uint32_t passed = sameSignTriangles(base, pending, n, ray, c); passed != 0;
             passed &= passed - 1) {
          const int lane = std::countr_zero(passed);
          if (query.finish(reinterpret_cast<const PackedTriangle*>(base + pending[lane])->face, ray, tMin,
                           tMax, c.ax[lane], c.ay[lane], c.az[lane], c.bx[lane], c.by[lane], c.bz[lane],
                           c.cx[lane], c.cy[lane], c.cz[lane]))
            return true;
        }
      }
    } else
#endif
    {
      for (std::uint32_t i = 0; i < count; ++i) {
        const std::uint32_t triangle = index[i];
        // Mailbox (Amanatides & Woo 1987; Havran's thesis 5.2): a triangle split into several leaves
        // is tested once per ray. Skipping a repeat is exact: the same test gives the same answer,
        // and the accepted bound has only shrunk since.
        std::uint32_t& slot = mailbox[triangle & (kMailboxSize - 1)];
        if (slot == triangle) continue;
        slot = triangle;
        LANCER_KD_COUNT(triangleTests);
        if (query.test(*reinterpret_cast<const PackedTriangle*>(base + triangle), ray, tMin, tMax))
          return true;
      }
    }
    // Cells further than the best hit (plus slack) cannot hold a closer or tied hit.
    do {
      if (top == 0) return false;
      --top;
      node = base + stack[top].node;
      tEnter = stack[top].tEnter;
      tExit = stack[top].tExit;
    } while (tEnter > query.bound(tMax) + eps);
  }
}

}  // namespace

template <typename Isa, typename Filter>
bool KdTree::closestHitOn(const Ray& ray, float tMin, float tMax, const Filter& keeps, Hit& hit) const {
  LANCER_KD_COUNT(rays);
  ClosestHit<Filter> query{Hit{tMax, Hit{}.face}, tMax, keeps};
  for (const PackedTriangle& tri : slivers_) query.test(tri, ray, tMin, tMax);
  walk(layout_, bounds_, magnitude_, ray, tMin, tMax, query);
  if (!query.best.valid()) return false;
  hit = query.best;
  return true;
}

template <typename Isa, typename Filter>
bool KdTree::anyHitOn(const Ray& ray, float tMin, float tMax, const Filter& keeps) const {
  LANCER_KD_COUNT(rays);
  AnyHit<Filter> query{keeps};
  for (const PackedTriangle& tri : slivers_) {
    if (query.test(tri, ray, tMin, tMax)) return true;
  }
  return walk(layout_, bounds_, magnitude_, ray, tMin, tMax, query);
}

template bool KdTree::closestHitOn<LANCER_ISA_TAG>(const Ray&, float, float, const KeepEveryHit&, Hit&) const;
template bool KdTree::closestHitOn<LANCER_ISA_TAG>(const Ray&, float, float, const HitFilter&, Hit&) const;
template bool KdTree::anyHitOn<LANCER_ISA_TAG>(const Ray&, float, float, const KeepEveryHit&) const;
template bool KdTree::anyHitOn<LANCER_ISA_TAG>(const Ray&, float, float, const HitFilter&) const;

}  // namespace lancer
