// Independent rays with several in flight: Bvh::kRaysInFlight single-ray walks (bvh/walk.hpp's, step
// for step) advanced in turn, one node or leaf each, the next node or leaf of each asked for before
// the others take their turn. An incoherent ray's walk is a chain of dependent cache misses; with
// several walks interleaved their misses overlap. Each ray's answer is its single walk's, to the bit.
#include <bit>
#include <cmath>
#include <optional>

#include "lancer/accel/bvh/bvh.hpp"
#include "lancer/accel/bvh/walk.hpp"

// The copy of the kernels being compiled (util/isa.hpp).
namespace lancer::bvh {
inline namespace LANCER_ISA_NS {

// One ray's walk from the root, resumable: step() does what one turn of walkFrom's loop does.
// (Members in the order the constructor fills them; the padding tidy reports is a few bytes beside
// the 4.5 KB stack.)
template <typename Filter>
struct RayWalk {  // NOLINT(clang-analyzer-optin.performance.Padding)
  const Ray& ray;
  float tMin, tMax, eps = 0;
  BoxRay boxRay;
#ifdef LANCER_BVH_AVX2
  BoxRay8 boxRay8;
#endif
  accel::ClosestHit<Filter> query;
  std::uint32_t child = 0;
  int top = 0;
  StackEntry stack[BvhNode::kMaxDepth * (BvhNode::kWidth - 1) + 1];

  // Tests the slivers; false when the ray misses the scene box (the walk is then over).
  RayWalk(const Ray& r, float t0, float t1, const Aabb& bounds, float magnitude, const Filter& keeps,
          std::span<const PackedTriangle> slivers, bool& walks)
      : ray(r),
        tMin(t0),
        tMax(t1),
        boxRay(r, magnitude),
#ifdef LANCER_BVH_AVX2
        boxRay8(boxRay),
#endif
        query{Hit{t1, Hit{}.face}, t1, keeps} {
    for (const PackedTriangle& tri : slivers) query.test(tri, ray, tMin, tMax);
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
          prefetchChildren(node, mask, nodes, leaves);
        } else {
          prefetchChildren(node, mask, nodes, leaves);
          child = pushChildren<true>(node, mask, tNear, stack, top);
        }
        return true;
      }
    } else {
      testLeaf(BvhLeaf(leaves + BvhNode::leafFirst(child), BvhNode::leafCount(child)), ray, tMin, tMax,
               query);
    }
    do {
      if (top == 0) return false;
      --top;
    } while (stack[top].tNear > query.bound(tMax) + eps);
    child = stack[top].child;
    return true;
  }
};

}  // namespace LANCER_ISA_NS
}  // namespace lancer::bvh

namespace lancer {

template <typename Isa, typename Filter>
std::size_t Bvh::closestHitsInFlightOn(std::span<const Ray> rays, float tMin, std::span<const float> tMax,
                                       const Filter& keeps, std::span<Hit> hits) const {
  std::optional<bvh::RayWalk<Filter>> walk[kRaysInFlight];
  std::size_t slot[kRaysInFlight] = {};
  std::size_t next = 0, hitCount = 0;
  int live = 0;
  auto finish = [&](int w) {
    const Hit& best = walk[w]->query.best;
    hits[slot[w]] = best.valid() ? best : Hit{};
    hitCount += best.valid() ? 1 : 0;
    walk[w].reset();
    --live;
  };
  // Starts the next ray in walk w (rays that miss the scene box finish at once).
  auto start = [&](int w) {
    while (next < rays.size()) {
      const std::size_t i = next++;
      bool walks = false;
      walk[w].emplace(rays[i], tMin, tMax[i], bounds_, magnitude_, keeps, slivers_, walks);
      slot[w] = i;
      ++live;
      if (walks) return;
      finish(w);
    }
  };
  for (int w = 0; w < kRaysInFlight; ++w) start(w);
  while (live > 0) {  // NOLINT(bugprone-infinite-loop): finish() and start() change `live`
    for (int w = 0; w < kRaysInFlight; ++w) {
      if (walk[w] && !walk[w]->step(nodes_, leaves_.data())) {
        finish(w);
        start(w);
      }
    }
  }
  return hitCount;
}

template std::size_t Bvh::closestHitsInFlightOn<LANCER_ISA_TAG>(std::span<const Ray>, float,
                                                                std::span<const float>, const KeepEveryHit&,
                                                                std::span<Hit>) const;
template std::size_t Bvh::closestHitsInFlightOn<LANCER_ISA_TAG>(std::span<const Ray>, float,
                                                                std::span<const float>, const HitFilter&,
                                                                std::span<Hit>) const;

}  // namespace lancer
