// Single-ray BVH traversal: a node's eight child boxes tested at once, the children met visited near
// to far (closest hit) with a fixed stack, those entered beyond the best hit so far skipped when
// popped. Exactness as the kd-tree's (kd/traversal.cpp): boxes are grown by a band against rounding
// and pruned only when clearly beyond the best hit, so a hit tied with the best (a ray through a shared
// edge) still reaches the lower-face tie rule; a quad's halves are tested in order in one leaf.
#include <bit>
#include <cmath>

#include "lancer/accel/bvh/bvh.hpp"
#include "lancer/accel/bvh/walk.hpp"

namespace lancer {
namespace {

using namespace bvh;
using namespace accel;

// The whole tree for one ray: its span in the scene box sets the slack of the pruning.
template <typename Query>
bool walk(std::span<const BvhNode> nodes, const std::uint64_t* leaves, const Aabb& bounds, float magnitude,
          const Ray& ray, float tMin, float tMax, Query& query) {
  float tEnter, tExit;
  if (!intersectAabb(bounds, ray, tMin, tMax, tEnter, tExit)) return false;
  const float eps = kSlack * std::max(std::abs(tEnter), std::abs(tExit));
  return walkFrom(0, nodes, leaves, BoxRay(ray, magnitude), eps, ray, tMin, tMax, query);
}

}  // namespace

template <typename Isa, typename Filter>
bool Bvh::closestHitOn(const Ray& ray, float tMin, float tMax, const Filter& keeps, Hit& hit) const {
  ClosestHit<Filter> query{Hit{tMax, Hit{}.face}, tMax, keeps};
  for (const PackedTriangle& tri : slivers_) query.test(tri, ray, tMin, tMax);
  walk(nodes_, leaves_.data(), bounds_, magnitude_, ray, tMin, tMax, query);
  if (!query.best.valid()) return false;
  hit = query.best;
  return true;
}

template <typename Isa, typename Filter>
bool Bvh::anyHitOn(const Ray& ray, float tMin, float tMax, const Filter& keeps) const {
  AnyHit<Filter> query{keeps};
  for (const PackedTriangle& tri : slivers_) {
    if (query.test(tri, ray, tMin, tMax)) return true;
  }
  return walk(nodes_, leaves_.data(), bounds_, magnitude_, ray, tMin, tMax, query);
}

template bool Bvh::closestHitOn<LANCER_ISA_TAG>(const Ray&, float, float, const KeepEveryHit&, Hit&) const;
template bool Bvh::closestHitOn<LANCER_ISA_TAG>(const Ray&, float, float, const HitFilter&, Hit&) const;
template bool Bvh::anyHitOn<LANCER_ISA_TAG>(const Ray&, float, float, const KeepEveryHit&) const;
template bool Bvh::anyHitOn<LANCER_ISA_TAG>(const Ray&, float, float, const HitFilter&) const;

}  // namespace lancer
