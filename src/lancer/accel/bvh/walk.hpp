// The BVH's single-ray walk from any node (bvh/traversal.cpp from the root; bvh/packet_traversal.cpp
// for a packet lane left alone in a subtree): a node's eight child boxes tested at once, the children
// met visited near to far (closest hit) with a fixed stack, those entered beyond the best hit so far
// skipped when popped.
#pragma once

#include <bit>
#include <cstdint>
#include <span>

#include "lancer/accel/bvh/box_test.hpp"
#include "lancer/accel/bvh/leaf_test.hpp"
#include "lancer/accel/bvh/node.hpp"
#include "lancer/util/isa.hpp"

// The copy of the kernels being compiled (util/isa.hpp).
namespace lancer::bvh {
inline namespace LANCER_ISA_NS {

struct StackEntry {
  std::uint32_t child;
  float tNear;
};

// Pushes the children of `mask` (other than the nearest, returned) so that the nearest pops first;
// any-hit queries take them in slot order.
template <bool kSorted>
std::uint32_t pushChildren(const BvhNode& node, std::uint32_t mask, const float* tNear, StackEntry* stack,
                           int& top) {
  if constexpr (!kSorted) {
    const int first = std::countr_zero(mask);
    for (mask &= mask - 1; mask != 0; mask &= mask - 1) {
      const int k = std::countr_zero(mask);
      stack[top++] = {node.child[k], tNear[k]};
    }
    return node.child[first];
  } else {
    // Insertion sort, far to near, straight onto the stack (at most eight entries).
    const int base = top;
    for (; mask != 0; mask &= mask - 1) {
      const int k = std::countr_zero(mask);
      const StackEntry entry{node.child[k], tNear[k]};
      int at = top++;
      while (at > base && stack[at - 1].tNear < entry.tNear) {
        stack[at] = stack[at - 1];
        --at;
      }
      stack[at] = entry;
    }
    return stack[--top].child;
  }
}

// Walks the subtree at `start` (a node, or a leaf's code) for one ray; Query::test/finish return true
// to stop (any hit), Query::bound is the current pruning distance (the closest hit so far, or tMax
// for any-hit); `eps` the slack of the pruning (kSlack times the ray's span in the scene box).
template <typename Query>
bool walkFrom(std::uint32_t start, std::span<const BvhNode> nodes, const std::uint64_t* leaves,
              const BoxRay& boxRay, float eps, const Ray& ray, float tMin, float tMax, Query& query) {
#ifdef LANCER_BVH_AVX2
  const BoxRay8 boxRay8(boxRay);
  const __m256 lowest = _mm256_set1_ps(tMin);
#endif
  StackEntry stack[BvhNode::kMaxDepth * (BvhNode::kWidth - 1) + 1];
  int top = 0;
  std::uint32_t child = start;
  while (true) {
    if (!BvhNode::isLeaf(child)) {
      const BvhNode& node = nodes[child];
      const float limit = query.bound(tMax) + eps;
      alignas(32) float tNear[BvhNode::kWidth];
#ifdef LANCER_BVH_AVX2
      __m256 enter;
      const std::uint32_t mask = hitChildren(node, boxRay8, lowest, _mm256_set1_ps(limit), enter);
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
        continue;
      }
    } else if (testLeaf(BvhLeaf(leaves + BvhNode::leafFirst(child), BvhNode::leafCount(child)), ray, tMin,
                        tMax, query)) {
      return true;
    }
    // The next child on the stack still entered before the bound.
    do {
      if (top == 0) return false;
      --top;
    } while (stack[top].tNear > query.bound(tMax) + eps);
    child = stack[top].child;
  }
}

}  // namespace LANCER_ISA_NS
}  // namespace lancer::bvh
