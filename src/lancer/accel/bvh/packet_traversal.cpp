// Packet traversal of the BVH: the active lanes of a packet walk the tree once together, each child
// box tested for all eight lanes in one AVX2 step (the lanes that meet it go down with it), each
// leaf triangle tested against the lanes that reached it in one step (accel/packet_frame.hpp's shared
// packet test). A lane's answer does not depend on the order it meets leaves in (the closest hit is
// the least (t, face) however found, a quad's halves are tested in order in one leaf), so every lane
// gets the single ray's answer, to the bit. Unlike the kd-tree's packets, the rays need not run
// the same way along each axis.
#include <algorithm>
#include <bit>
#include <cmath>
#include <type_traits>

#include "lancer/accel/bvh/bvh.hpp"
#include "lancer/accel/bvh/walk.hpp"
#include "lancer/accel/packet_frame.hpp"

namespace lancer {
namespace {

using namespace bvh;
using namespace accel;

#ifdef LANCER_PACKETS_AVX2

// The packet's view for the box tests: per axis each lane's origin moved by its band to the lower
// and the upper side (box.lower - lowEdge and box.upper - highEdge, times the inverse direction,
// are where the lane meets the grown box's planes, whichever way it runs), its interval's start,
// and the slack of its pruning.
struct PacketBoxes {
  __m256 lowEdge[3], highEdge[3];
  __m256 tMin, eps;
  alignas(32) float laneEps[kPacketSize];  // eps, lane by lane (a lane left alone walks on its own)
};

// Sets up the lanes of `active` that meet the scene box (kept in `active`).
void setUpBoxes(const RayPacket& packet, std::uint32_t& active, const Aabb& bounds, float magnitude,
                PacketBoxes& boxes) {
  alignas(32) float low[3][kPacketSize] = {}, high[3][kPacketSize] = {}, tMin[kPacketSize] = {},
                    eps[kPacketSize] = {};
  for (std::uint32_t lanes = active; lanes != 0; lanes &= lanes - 1) {
    const int i = std::countr_zero(lanes);
    const Ray& ray = packet.ray[i];
    float tEnter, tExit;
    if (!intersectAabb(bounds, ray, packet.tMin[i], packet.tMax[i], tEnter, tExit)) {
      active &= ~(1u << i);
      continue;
    }
    eps[i] = kSlack * std::max(std::abs(tEnter), std::abs(tExit));
    tMin[i] = packet.tMin[i];
    const float band = kPlaneSlack * std::max(magnitude, maxComponent(abs(ray.origin)));
    const float origin[3] = {ray.origin.x, ray.origin.y, ray.origin.z};
    for (int a = 0; a < 3; ++a) {
      low[a][i] = origin[a] + band;
      high[a][i] = origin[a] - band;
    }
  }
  for (int a = 0; a < 3; ++a) {
    boxes.lowEdge[a] = _mm256_load_ps(low[a]);
    boxes.highEdge[a] = _mm256_load_ps(high[a]);
  }
  boxes.tMin = _mm256_load_ps(tMin);
  boxes.eps = _mm256_load_ps(eps);
  std::copy(eps, eps + kPacketSize, boxes.laneEps);
}

struct alignas(32) PacketStackEntry {
  __m256 tNear;
  std::uint32_t child, lanes;
  float key;  // the order of the children pushed together
};

// Walks the tree with the lanes `active`; Query::test(tri, lanes) tests a triangle on some lanes and
// returns those that are done (any-hit: blocked), Query::bound() is each lane's pruning distance.
// A lane left alone in a subtree finishes it on the single-ray walk (bvh/walk.hpp): one box test
// for one ray instead of eight lanes for one, as the kd-tree's packets do; alone(child, lane) says
// whether the lane is done. Returns the lanes that are done.
template <typename Query, typename Alone>
std::uint32_t walkPacket(std::span<const BvhNode> nodes, const std::uint64_t* leaves, const PacketFrame& f,
                         const PacketBoxes& boxes, std::uint32_t active, Query& query, const Alone& alone) {
  PacketStackEntry stack[BvhNode::kMaxDepth * (BvhNode::kWidth - 1) + 1];
  int top = 0;
  std::uint32_t done = 0, lanes = active, child = 0;
  while (true) {
    if ((lanes & (lanes - 1)) == 0) {
      if (alone(child, std::countr_zero(lanes))) {
        done |= lanes;
        if ((active & ~done) == 0) return done;
      }
    } else if (!BvhNode::isLeaf(child)) {
      const BvhNode& node = nodes[child];
      const __m256 limit = _mm256_add_ps(query.bound(), boxes.eps);
      alignas(32) float tNear[BvhNode::kWidth][kPacketSize];
      __m256 enterOf[BvhNode::kWidth];
      std::uint32_t childLanes[BvhNode::kWidth];
      std::uint32_t hitMask = 0;
      for (int k = 0; k < BvhNode::kWidth && node.child[k] != BvhNode::kEmpty; ++k) {
        __m256 enter = boxes.tMin, exit = limit;
        for (int a = 0; a < 3; ++a) {
          const __m256 t0 = _mm256_mul_ps(_mm256_sub_ps(_mm256_set1_ps(node.lower[a][k]), boxes.lowEdge[a]),
                                          f.invDirection[a]);
          const __m256 t1 = _mm256_mul_ps(_mm256_sub_ps(_mm256_set1_ps(node.upper[a][k]), boxes.highEdge[a]),
                                          f.invDirection[a]);
          enter = _mm256_max_ps(_mm256_min_ps(t0, t1), enter);
          exit = _mm256_min_ps(_mm256_max_ps(t0, t1), exit);
        }
        childLanes[k] = laneMask(_mm256_cmp_ps(enter, exit, _CMP_LE_OQ)) & lanes;
        if (childLanes[k] == 0) continue;
        hitMask |= 1u << k;
        enterOf[k] = enter;
        _mm256_store_ps(tNear[k], enter);
      }
      if (hitMask != 0) {
        if ((hitMask & (hitMask - 1)) == 0) {
          const int k = std::countr_zero(hitMask);
          child = node.child[k];
          lanes = childLanes[k];
          continue;
        }
        // Far to near onto the stack, by where the first lane that meets each child enters it.
        const int base = top;
        for (std::uint32_t m = hitMask; m != 0; m &= m - 1) {
          const int k = std::countr_zero(m);
          const float key = tNear[k][std::countr_zero(childLanes[k])];
          int at = top++;
          while (at > base && stack[at - 1].key < key) {
            stack[at] = stack[at - 1];
            --at;
          }
          stack[at] = {enterOf[k], node.child[k], childLanes[k], key};
        }
        --top;
        child = stack[top].child;
        lanes = stack[top].lanes;
        continue;
      }
    } else {
      const BvhLeaf leaf(leaves + BvhNode::leafFirst(child), BvhNode::leafCount(child));
      std::uint32_t testLanes = lanes;
      for (std::uint32_t i = 0, count = leaf.count(); i < count && testLanes != 0; ++i) {
        const std::uint32_t finished = query.test(leaf.triangle(i), testLanes);
        done |= finished;
        testLanes &= ~finished;
      }
      if ((active & ~done) == 0) return done;
    }
    // The next entry with lanes not done that entered it before their bound.
    while (true) {
      if (top == 0) return done;
      --top;
      const __m256 limit = _mm256_add_ps(query.bound(), boxes.eps);
      lanes = stack[top].lanes & ~done & laneMask(_mm256_cmp_ps(stack[top].tNear, limit, _CMP_LE_OQ));
      if (lanes != 0) break;
    }
    child = stack[top].child;
  }
}

#endif  // LANCER_PACKETS_AVX2

}  // namespace

template <typename Isa, typename Filter>
std::uint32_t Bvh::closestHitsOn(const RayPacket& packet, std::uint32_t active, const Filter& keeps,
                                 std::span<Hit, kPacketSize> hits) const {
  active &= kAllLanes;
#ifdef LANCER_PACKETS_AVX2
  if (std::popcount(active) < 2) return closestHitsOneByOne(packet, active, keeps, hits);
  PacketFrame frame;
  loadPacketRays(packet, active, frame);
  PacketClosestHit<Filter> query{packet, frame, keeps, {}, {}, {}};
  query.start(active, slivers_);
  std::uint32_t inBox = active;
  PacketBoxes boxes;
  setUpBoxes(packet, inBox, bounds_, magnitude_, boxes);
  auto alone = [&](std::uint32_t start, int i) {
    ClosestHit<Filter> single{query.best[i], query.upper[i], keeps};
    walkFrom(start, nodes_, leaves_.data(), BoxRay(packet.ray[i], magnitude_), boxes.laneEps[i],
             packet.ray[i], packet.tMin[i], packet.tMax[i], single);
    query.best[i] = single.best;
    query.upper[i] = single.upper;
    query.bestT[i] = single.best.t;
    return false;
  };
  if (inBox != 0) walkPacket(nodes_, leaves_.data(), frame, boxes, inBox, query, alone);
  return query.answer(active, hits);
#else
  return closestHitsOneByOne(packet, active, keeps, hits);
#endif
}

template <typename Isa, typename Filter>
std::uint32_t Bvh::anyHitsOn(const RayPacket& packet, std::uint32_t active, const Filter& keeps) const {
  active &= kAllLanes;
#ifdef LANCER_PACKETS_AVX2
  if (std::popcount(active) < 2) return anyHitsOneByOne(packet, active, keeps);
  const std::uint32_t blocked = lanesBlockedBySlivers(packet, active, slivers_, keeps);
  std::uint32_t inBox = active & ~blocked;
  PacketBoxes boxes;
  setUpBoxes(packet, inBox, bounds_, magnitude_, boxes);
  if (inBox == 0) return blocked;
  PacketFrame frame;
  loadPacketRays(packet, inBox, frame);
  PacketAnyHit<Filter> query{packet, frame, keeps, {}};
  query.start(inBox);
  auto alone = [&](std::uint32_t start, int i) {
    AnyHit<Filter> single{keeps};
    return walkFrom(start, nodes_, leaves_.data(), BoxRay(packet.ray[i], magnitude_), boxes.laneEps[i],
                    packet.ray[i], packet.tMin[i], packet.tMax[i], single);
  };
  return blocked | walkPacket(nodes_, leaves_.data(), frame, boxes, inBox, query, alone);
#else
  return anyHitsOneByOne(packet, active, keeps);
#endif
}

template std::uint32_t Bvh::closestHitsOn<LANCER_ISA_TAG>(const RayPacket&, std::uint32_t,
                                                          const KeepEveryHit&,
                                                          std::span<Hit, kPacketSize>) const;
template std::uint32_t Bvh::closestHitsOn<LANCER_ISA_TAG>(const RayPacket&, std::uint32_t, const HitFilter&,
                                                          std::span<Hit, kPacketSize>) const;
template std::uint32_t Bvh::anyHitsOn<LANCER_ISA_TAG>(const RayPacket&, std::uint32_t,
                                                      const KeepEveryHit&) const;
template std::uint32_t Bvh::anyHitsOn<LANCER_ISA_TAG>(const RayPacket&, std::uint32_t,
                                                      const HitFilter&) const;

}  // namespace lancer
