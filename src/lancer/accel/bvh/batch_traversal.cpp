// Independent rays with several in flight: Bvh::kRaysInFlight single-ray walks (bvh/walk.hpp's, step
// for step) advanced in turn, one node or leaf each, the next node or leaf of each asked for before
// the others take their turn. An incoherent ray's walk is a chain of dependent cache misses; with
// several walks interleaved their misses overlap. Each ray's answer is its single walk's, to the bit.
// Asking only for the step a walk takes next measured as fast as asking for every child its node test
// met (bench/RESULTS.md, "Rays in flight: the next step asked for, any-hit spans, and the path
// tracer") with a fraction of the prefetches.
#include <bit>
#include <cmath>
#include <optional>

#include <xmmintrin.h>

#include "lancer/accel/bvh/bvh.hpp"
#include "lancer/accel/bvh/walk.hpp"

// The copy of the kernels being compiled (util/isa.hpp).
namespace lancer::bvh {
inline namespace LANCER_ISA_NS {

// One ray's walk from the root, resumable: step() does what one turn of walkFrom's loop does.
// Query: ClosestHit (children near to far) or AnyHit (slot order, over at the first hit kept).
// (Members in the order the constructor fills them; the padding tidy reports is a few bytes beside
// the 4.5 KB stack.)
template <typename Query>
struct RayWalk {  // NOLINT(clang-analyzer-optin.performance.Padding)
  const Ray& ray;
  float tMin, tMax, eps = 0;
  BoxRay boxRay;
#ifdef LANCER_BVH_AVX2
  BoxRay8 boxRay8;
#endif
  Query query;
  bool found = false;  // any hit: a kept hit ended the walk
  std::uint32_t child = 0;
  int top = 0;
  StackEntry stack[BvhNode::kMaxDepth * (BvhNode::kWidth - 1) + 1];

  // Tests the slivers; `walks` false when the walk is already over (the ray misses the scene box,
  // or an any-hit query met a sliver).
  RayWalk(const Ray& r, float t0, float t1, const Aabb& bounds, float magnitude, const Query& q,
          std::span<const PackedTriangle> slivers, bool& walks)
      : ray(r),
        tMin(t0),
        tMax(t1),
        boxRay(r, magnitude),
#ifdef LANCER_BVH_AVX2
        boxRay8(boxRay),
#endif
        query(q) {
    walks = false;
    for (const PackedTriangle& tri : slivers) {
      if (query.test(tri, ray, tMin, tMax)) {
        found = true;
        return;
      }
    }
    float tEnter, tExit;
    walks = intersectAabb(bounds, ray, tMin, tMax, tEnter, tExit);
    if (walks) eps = accel::kSlack * std::max(std::abs(tEnter), std::abs(tExit));
  }

  // One node or leaf; false when the walk is over.
  bool step(std::span<const BvhNode> nodes, const std::uint64_t* leaves) {
    if (!BvhNode::isLeaf(child)) {
      const BvhNode& node = nodes[child];
      const float limit = query.bound(tMax) + eps;
      alignas(32) float tNear[BvhNode::kWidth];
#ifdef LANCER_BVH_AVX2
      __m256 enter;
      const std::uint32_t mask =
          hitChildren(node, boxRay8, _mm256_set1_ps(tMin), _mm256_set1_ps(limit), enter);
      _mm256_store_ps(tNear, enter);
#else
      const std::uint32_t mask = hitChildrenScalar(node, boxRay, tMin, limit, tNear);
#endif
      if (mask != 0) {
        if ((mask & (mask - 1)) == 0) {
          child = node.child[std::countr_zero(mask)];
        } else {
          child = pushChildren<!Query::kAnyHit>(node, mask, tNear, stack, top);
        }
        prefetchNext(nodes, leaves);
        return true;
      }
    } else if (testLeaf(BvhLeaf(leaves + BvhNode::leafFirst(child), BvhNode::leafCount(child)), ray, tMin,
                        tMax, query)) {
      found = true;
      return false;
    }
    do {
      if (top == 0) return false;
      --top;
    } while (stack[top].tNear > query.bound(tMax) + eps);
    child = stack[top].child;
    prefetchNext(nodes, leaves);
    return true;
  }

  // Asks for the lines of the node or leaf this walk visits at its next turn, while the other walks
  // take theirs.
  void prefetchNext(std::span<const BvhNode> nodes, const std::uint64_t* leaves) const {
    if (BvhNode::isLeaf(child)) {
      const char* at = reinterpret_cast<const char*>(leaves + BvhNode::leafFirst(child));
      const int lines = 1 + int(BvhNode::leafCount(child) * 26 / 64);  // about 25 bytes a triangle
      for (int line = 0; line < lines; ++line) _mm_prefetch(at + 64 * line, _MM_HINT_T0);
    } else {
      const char* at = reinterpret_cast<const char*>(nodes.data() + child);
      for (int line = 0; line < int((sizeof(BvhNode) + 63) / 64); ++line)
        _mm_prefetch(at + 64 * line, _MM_HINT_T0);
    }
  }
};

// Walks rays[i] for i in [0, rays.size()) with kInFlight of them at once; walk(i) builds ray i's
// RayWalk into the slot given (returning whether it walks), done(i, walk) takes its answer.
template <typename Query, int kInFlight, typename Start, typename Done>
void walkInFlight(std::size_t count, std::span<const BvhNode> nodes, const std::uint64_t* leaves,
                  const Start& startWalk, const Done& done) {
  std::optional<RayWalk<Query>> walk[kInFlight];
  std::size_t slot[kInFlight] = {};
  std::size_t next = 0;
  int live = 0;
  // Starts the next ray in walk w (rays whose walk is over at once are answered at once).
  auto start = [&](int w) {
    while (next < count) {
      const std::size_t i = next++;
      if (startWalk(i, walk[w])) {
        slot[w] = i;
        ++live;
        return;
      }
      done(i, *walk[w]);
      walk[w].reset();
    }
  };
  for (int w = 0; w < kInFlight; ++w) start(w);
  while (live > 0) {  // NOLINT(bugprone-infinite-loop): start() changes `live`
    for (int w = 0; w < kInFlight; ++w) {
      if (walk[w] && !walk[w]->step(nodes, leaves)) {
        done(slot[w], *walk[w]);
        walk[w].reset();
        --live;
        start(w);
      }
    }
  }
}

}  // namespace LANCER_ISA_NS
}  // namespace lancer::bvh

namespace lancer {

template <typename Isa, typename Filter>
std::size_t Bvh::closestHitsInFlightOn(std::span<const Ray> rays, float tMin, std::span<const float> tMax,
                                       const Filter& keeps, std::span<Hit> hits) const {
  using Query = accel::ClosestHit<Filter>;
  std::size_t hitCount = 0;
  bvh::walkInFlight<Query, kRaysInFlight>(
      rays.size(), nodes_, leaves_.data(),
      [&](std::size_t i, std::optional<bvh::RayWalk<Query>>& walk) {
        bool walks = false;
        walk.emplace(rays[i], tMin, tMax[i], bounds_, magnitude_,
                     Query{Hit{tMax[i], Hit{}.face}, tMax[i], keeps}, slivers_, walks);
        return walks;
      },
      [&](std::size_t i, const bvh::RayWalk<Query>& walk) {
        const Hit& best = walk.query.best;
        hits[i] = best.valid() ? best : Hit{};
        hitCount += best.valid() ? 1 : 0;
      });
  return hitCount;
}

template <typename Isa, typename Filter>
std::size_t Bvh::anyHitsInFlightOn(std::span<const Ray> rays, float tMin, std::span<const float> tMax,
                                   const Filter& keeps, std::span<std::uint8_t> blocked) const {
  using Query = accel::AnyHit<Filter>;
  std::size_t blockedCount = 0;
  bvh::walkInFlight<Query, kRaysInFlight>(
      rays.size(), nodes_, leaves_.data(),
      [&](std::size_t i, std::optional<bvh::RayWalk<Query>>& walk) {
        bool walks = false;
        walk.emplace(rays[i], tMin, tMax[i], bounds_, magnitude_, Query{keeps}, slivers_, walks);
        return walks;
      },
      [&](std::size_t i, const bvh::RayWalk<Query>& walk) {
        blocked[i] = walk.found ? 1 : 0;
        blockedCount += walk.found ? 1 : 0;
      });
  return blockedCount;
}

template std::size_t Bvh::closestHitsInFlightOn<LANCER_ISA_TAG>(std::span<const Ray>, float,
                                                                std::span<const float>, const KeepEveryHit&,
                                                                std::span<Hit>) const;
template std::size_t Bvh::closestHitsInFlightOn<LANCER_ISA_TAG>(std::span<const Ray>, float,
                                                                std::span<const float>, const HitFilter&,
                                                                std::span<Hit>) const;

template std::size_t Bvh::anyHitsInFlightOn<LANCER_ISA_TAG>(std::span<const Ray>, float,
                                                            std::span<const float>, const KeepEveryHit&,
                                                            std::span<std::uint8_t>) const;
template std::size_t Bvh::anyHitsInFlightOn<LANCER_ISA_TAG>(std::span<const Ray>, float,
                                                            std::span<const float>, const HitFilter&,
                                                            std::span<std::uint8_t>) const;

}  // namespace lancer
