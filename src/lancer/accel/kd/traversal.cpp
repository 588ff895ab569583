// Front-to-back kd-tree traversal with a fixed stack (pbrt-v3 section 4.4.4, Havran's thesis
// appendix C). Exactness: triangle hits are accepted wherever they lie, not just inside the current
// cell, a ray within a thin band of a split plane visits both sides, and cells are pruned only when
// clearly beyond the best hit, so a hit on or near a split plane (a ray through a shared edge lying
// in the plane) reaches the same tie-break as the brute-force loop.
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <limits>

#include "lancer/accel/kd/query.hpp"
#include "lancer/accel/kd_tree.hpp"

#if defined(__AVX2__) && defined(__FMA__)
#include <immintrin.h>
#define LANCER_LEAF_AVX2 1
#endif

namespace lancer {

#ifdef LANCER_KD_COUNTERS
thread_local KdTraversalCounters kdCounters;
KdTraversalCounters& kdTraversalCounters() { return kdCounters; }
#define LANCER_KD_COUNT(field) ++kdCounters.field
#else
#define LANCER_KD_COUNT(field) ((void)0)
#endif

namespace {

using namespace kd;

struct StackEntry {
  std::uint32_t node;
  float tEnter, tExit;
};

#ifdef LANCER_LEAF_AVX2

// Leaves this size or larger have their triangles tested eight at a time against the ray; below it
// loading and transposing them costs more than the scalar tests they replace.
constexpr std::uint32_t kMinSimdLeaf = 3;

// The sheared corners of up to eight triangles in the ray's frame, triangle i in lane i, exactly as
// testTriangle computes them (the same operations on the same floats, no contraction), for
// finishing the test of the lanes whose edge functions agree in sign.
struct LeafCorners {
  alignas(32) float ax[8], ay[8], az[8], bx[8], by[8], bz[8], cx[8], cy[8], cz[8];
};

// a b - c d as triangle_detail::differenceOfProducts computes it (Kahan's algorithm with FMA).
inline __m256 differenceOfProducts8(__m256 a, __m256 b, __m256 c, __m256 d) {
  const __m256 cd = _mm256_mul_ps(c, d);
  const __m256 cdError = _mm256_fnmadd_ps(c, d, cd);
  return _mm256_add_ps(_mm256_fmsub_ps(a, b, cd), cdError);
}

// The float half of testTriangle for `count` (1..8) triangles at the layout's word offsets
// `offsets`, against one ray: the lanes whose ray line meets the triangle.
inline std::uint32_t sameSignTriangles(const KdNode* base, const std::uint32_t* offsets, std::uint32_t count,
                                       const Ray& ray, LeafCorners& out) {
  static_assert(offsetof(PackedTriangle, v0) == 0 && offsetof(PackedTriangle, v2) == 6 * sizeof(float) &&
                sizeof(Vec3) == 3 * sizeof(float));
  // The triangles' first eight floats (v0, v1, v2.x, v2.y) as the rows of an 8x8 matrix, transposed
  // to one register per coordinate (unpack, shuffle, then swap halves); gathers measured slower.
  const float* tri[8];
  for (std::uint32_t i = 0; i < 8; ++i)
    tri[i] = reinterpret_cast<const float*>(base + offsets[i < count ? i : 0]);
  __m256 row[8];
  for (int i = 0; i < 8; ++i) row[i] = _mm256_loadu_ps(tri[i]);
  __m256 coordinate[9];
  for (int half = 0; half < 2; ++half) {
    const __m256* r = row + 4 * half;
    const __m256 lo01 = _mm256_unpacklo_ps(r[0], r[1]), hi01 = _mm256_unpackhi_ps(r[0], r[1]);
    const __m256 lo23 = _mm256_unpacklo_ps(r[2], r[3]), hi23 = _mm256_unpackhi_ps(r[2], r[3]);
    // Coordinates k and k + 4 of triangles 4 half .. 4 half + 3.
    __m256* q = row + 4 * half;
    q[0] = _mm256_shuffle_ps(lo01, lo23, _MM_SHUFFLE(1, 0, 1, 0));
    q[1] = _mm256_shuffle_ps(lo01, lo23, _MM_SHUFFLE(3, 2, 3, 2));
    q[2] = _mm256_shuffle_ps(hi01, hi23, _MM_SHUFFLE(1, 0, 1, 0));
    q[3] = _mm256_shuffle_ps(hi01, hi23, _MM_SHUFFLE(3, 2, 3, 2));
  }
  for (int k = 0; k < 4; ++k) {
    coordinate[k] = _mm256_permute2f128_ps(row[k], row[4 + k], 0x20);
    coordinate[4 + k] = _mm256_permute2f128_ps(row[k], row[4 + k], 0x31);
  }
  coordinate[8] =
      _mm256_set_ps(tri[7][8], tri[6][8], tri[5][8], tri[4][8], tri[3][8], tri[2][8], tri[1][8], tri[0][8]);
  const float origin[3] = {ray.origin.x, ray.origin.y, ray.origin.z};
  // Corner c's coordinate along `axis`, minus the origin's (testTriangle's da, db, dc).
  auto corner = [&](int c, int axis) {
    return _mm256_sub_ps(coordinate[3 * c + axis], _mm256_set1_ps(origin[axis]));
  };
  const __m256 shearX = _mm256_set1_ps(ray.shearX), shearY = _mm256_set1_ps(ray.shearY);
  const __m256 az = corner(0, ray.kz), bz = corner(1, ray.kz), cz = corner(2, ray.kz);
  const __m256 ax = _mm256_fnmadd_ps(shearX, az, corner(0, ray.kx));
  const __m256 ay = _mm256_fnmadd_ps(shearY, az, corner(0, ray.ky));
  const __m256 bx = _mm256_fnmadd_ps(shearX, bz, corner(1, ray.kx));
  const __m256 by = _mm256_fnmadd_ps(shearY, bz, corner(1, ray.ky));
  const __m256 cx = _mm256_fnmadd_ps(shearX, cz, corner(2, ray.kx));
  const __m256 cy = _mm256_fnmadd_ps(shearY, cz, corner(2, ray.ky));
  const __m256 u = differenceOfProducts8(cx, by, cy, bx);
  const __m256 v = differenceOfProducts8(ax, cy, ay, cx);
  const __m256 w = differenceOfProducts8(bx, ay, by, ax);
  const __m256 zero = _mm256_setzero_ps();
  const __m256 allNonNegative =
      _mm256_and_ps(_mm256_and_ps(_mm256_cmp_ps(u, zero, _CMP_GE_OQ), _mm256_cmp_ps(v, zero, _CMP_GE_OQ)),
                    _mm256_cmp_ps(w, zero, _CMP_GE_OQ));
  const __m256 allNonPositive =
      _mm256_and_ps(_mm256_and_ps(_mm256_cmp_ps(u, zero, _CMP_LE_OQ), _mm256_cmp_ps(v, zero, _CMP_LE_OQ)),
                    _mm256_cmp_ps(w, zero, _CMP_LE_OQ));
  const std::uint32_t passed =
      static_cast<std::uint32_t>(_mm256_movemask_ps(_mm256_or_ps(allNonNegative, allNonPositive))) &
      ((1u << count) - 1u);
  if (passed != 0) {
    _mm256_store_ps(out.ax, ax);
    _mm256_store_ps(out.ay, ay);
    _mm256_store_ps(out.az, az);
    _mm256_store_ps(out.bx, bx);
    _mm256_store_ps(out.by, by);
    _mm256_store_ps(out.bz, bz);
    _mm256_store_ps(out.cx, cx);
    _mm256_store_ps(out.cy, cy);
    _mm256_store_ps(out.cz, cz);
  }
  return passed;
}

#endif  // LANCER_LEAF_AVX2

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
        LeafCorners c;
        for (std::uint32_t passed = sameSignTriangles(base, pending, n, ray, c); passed != 0;
             passed &= passed - 1) {
          const int lane = std::countr_zero(passed);
          if (query.finish(*reinterpret_cast<const PackedTriangle*>(base + pending[lane]), ray, tMin, tMax,
                           c.ax[lane], c.ay[lane], c.az[lane], c.bx[lane], c.by[lane], c.bz[lane], c.cx[lane],
                           c.cy[lane], c.cz[lane]))
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

template <typename Filter>
bool KdTree::closestHit(const Ray& ray, float tMin, float tMax, const Filter& keeps, Hit& hit) const {
  LANCER_KD_COUNT(rays);
  ClosestHit<Filter> query{Hit{tMax, Hit{}.face}, tMax, keeps};
  for (const PackedTriangle& tri : slivers_) query.test(tri, ray, tMin, tMax);
  walk(layout_, bounds_, magnitude_, ray, tMin, tMax, query);
  if (!query.best.valid()) return false;
  hit = query.best;
  return true;
}

template <typename Filter>
bool KdTree::anyHit(const Ray& ray, float tMin, float tMax, const Filter& keeps) const {
  LANCER_KD_COUNT(rays);
  AnyHit<Filter> query{keeps};
  for (const PackedTriangle& tri : slivers_) {
    if (query.test(tri, ray, tMin, tMax)) return true;
  }
  return walk(layout_, bounds_, magnitude_, ray, tMin, tMax, query);
}

bool KdTree::intersect(const Ray& ray, float tMin, float tMax, Hit& hit) const {
  return closestHit(ray, tMin, tMax, KeepEveryHit{}, hit);
}

bool KdTree::occluded(const Ray& ray, float tMin, float tMax) const {
  return anyHit(ray, tMin, tMax, KeepEveryHit{});
}

bool KdTree::intersect(const Ray& ray, float tMin, float tMax, const HitFilter& filter, Hit& hit) const {
  return closestHit(ray, tMin, tMax, filter, hit);
}

bool KdTree::occluded(const Ray& ray, float tMin, float tMax, const HitFilter& filter) const {
  return anyHit(ray, tMin, tMax, filter);
}

}  // namespace lancer
