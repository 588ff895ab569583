// The BVH's node: the boxes of up to eight children, quantized to eight bits a plane against the
// node's own box (Embree's compressed BVH8, Ylitie, Karras & Laine 2017), and what each child is:
// another node or a leaf. Two cache lines a node where full floats took four: the walk of incoherent
// rays waits on memory, and fewer lines a node is fewer misses.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include "lancer/math/aabb.hpp"

namespace lancer {

struct alignas(64) BvhNode {
  static constexpr int kWidth = 8;
  // A child's plane on axis a is origin[a] + q * scale[a] (q its byte), computed in float exactly so
  // (a multiply, then an add) by the build and by every box test. The build picks each byte so that
  // the plane lies on or outside the child's true box: the test's box holds the true one, so it meets
  // every ray the true box meets and enters no later (subtraction and multiplication round
  // monotonically), and no hit is lost.
  float origin[3] = {0, 0, 0};
  float scale[3] = {0, 0, 0};
  std::uint8_t lower[3][kWidth] = {};
  std::uint8_t upper[3][kWidth] = {};
  // Child: the index of a node, or kLeaf | (count - 1) << kCountShift | first triangle. Children fill
  // lanes 0 .. used - 1; the lanes past them are kEmpty, and their (meaningless) boxes are masked off.
  std::uint32_t child[kWidth] = {kEmpty, kEmpty, kEmpty, kEmpty, kEmpty, kEmpty, kEmpty, kEmpty};
  std::uint32_t used = 0;

  static constexpr std::uint32_t kLeaf = 0x80000000u;
  static constexpr int kCountShift = 28;
  static constexpr std::uint32_t kMaxLeafTriangles = 8;
  static constexpr std::uint32_t kMaxFirst = (1u << kCountShift) - 1;
  static constexpr std::uint32_t kEmpty = 0xFFFFFFFFu;
  // Deepest node (the build keeps to it), so a walk's stack of kMaxDepth * 7 + 1 always suffices.
  static constexpr int kMaxDepth = 80;

  static std::uint32_t leaf(std::uint32_t first, std::uint32_t count) {
    return kLeaf | (count - 1) << kCountShift | first;
  }
  static bool isLeaf(std::uint32_t c) { return (c & kLeaf) != 0; }
  static std::uint32_t leafFirst(std::uint32_t c) { return c & kMaxFirst; }
  static std::uint32_t leafCount(std::uint32_t c) { return ((c >> kCountShift) & 7u) + 1; }

  static float plane(float origin, float scale, std::uint32_t q) { return origin + float(q) * scale; }
  float lowerPlane(int axis, int k) const { return plane(origin[axis], scale[axis], lower[axis][k]); }
  float upperPlane(int axis, int k) const { return plane(origin[axis], scale[axis], upper[axis][k]); }
  // Child k's box as the box tests see it (holding the box it was given).
  Aabb box(int k) const {
    return {{lowerPlane(0, k), lowerPlane(1, k), lowerPlane(2, k)},
            {upperPlane(0, k), upperPlane(1, k), upperPlane(2, k)}};
  }
  std::uint32_t usedMask() const { return (1u << used) - 1; }

  void clear() { *this = BvhNode{}; }

  // The boxes of children 0 .. count - 1 (finite, not empty), quantized; the children's codes are
  // left kEmpty for the caller to set. The one place a node's boxes are written.
  void setBoxes(const Aabb* boxes, int count) {
    clear();
    used = static_cast<std::uint32_t>(count);
    for (int a = 0; a < 3; ++a) {
      float lo = std::numeric_limits<float>::infinity(), hi = -lo;
      for (int k = 0; k < count; ++k) {
        lo = std::min(lo, boxes[k].lower[a]);
        hi = std::max(hi, boxes[k].upper[a]);
      }
      // The smallest step whose 255th plane reaches the top (an exact origin: byte 0 is lo itself).
      float step = static_cast<float>((double(hi) - double(lo)) / 255.0);
      while (plane(lo, step, 255) < hi) step = std::nextafter(step, std::numeric_limits<float>::infinity());
      origin[a] = lo;
      scale[a] = step;
      for (int k = 0; k < count; ++k) {
        lower[a][k] = quantize(lo, step, boxes[k].lower[a], false);
        upper[a][k] = quantize(lo, step, boxes[k].upper[a], true);
      }
    }
  }

 private:
  // The byte whose plane is the nearest at or below `value` (at or above it when `up`).
  static std::uint8_t quantize(float origin, float scale, float value, bool up) {
    if (!(scale > 0)) return 0;  // a flat node: every plane is the origin
    const double guess = (double(value) - double(origin)) / double(scale);
    auto q = static_cast<int>(std::clamp(up ? std::ceil(guess) : std::floor(guess), 0.0, 255.0));
    if (up) {
      while (q < 255 && plane(origin, scale, q) < value) ++q;
      while (q > 0 && plane(origin, scale, q - 1) >= value) --q;
    } else {
      while (q > 0 && plane(origin, scale, q) > value) --q;
      while (q < 255 && plane(origin, scale, q + 1) <= value) ++q;
    }
    return static_cast<std::uint8_t>(q);
  }
};
static_assert(sizeof(BvhNode) == 128);

}  // namespace lancer
