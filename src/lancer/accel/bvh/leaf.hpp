// A BVH leaf as stored: its triangles' distinct vertices once each (neighbouring triangles share
// most of theirs), each triangle three one-byte indices into them and its face. A leaf of 5.5
// triangles takes about 25 bytes a triangle where three corners each took 40, and its coordinates lie
// as three rows (x, y, z) that the AVX2 leaf test turns into a lane per triangle with one permute per
// corner, no transpose. The floats are the positions' own, so every test gives the same bits as on
// pre-gathered triangles.
//
// Bytes of a leaf (8-byte aligned, at the leaf code's first word of the tree's leaf array):
//   u32 vertexCount; u32 face[count]; u8 corner[3][count] (corner c of triangle i at c * count + i);
//   padding to 4 bytes; float x[vertexCount], y[vertexCount], z[vertexCount]; padding to 8 bytes.
// A quad's two halves are neighbours, (0,1,2) first, as on the faces.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>

#ifdef __SSE2__
#include <emmintrin.h>
#endif

#include "lancer/accel/triangle_intersect.hpp"

namespace lancer::bvh {

// Distinct vertices of a leaf of at most eight triangles (three corners each).
constexpr std::uint32_t kMaxLeafVertices = 24;
// Words the leaf array holds past its last leaf, so that the AVX2 test may read a row of eight
// floats or eight corner bytes from anywhere in a leaf.
constexpr std::size_t kLeafTailWords = 4;

class BvhLeaf {
 public:
  BvhLeaf(const std::uint64_t* words, std::uint32_t count)
      : data_(reinterpret_cast<const unsigned char*>(words)), count_(count) {}

  static constexpr std::size_t cornerOffset(std::uint32_t count) { return 4 + 4 * std::size_t(count); }
  static constexpr std::size_t coordinateOffset(std::uint32_t count) {
    return (cornerOffset(count) + 3 * std::size_t(count) + 3) & ~std::size_t(3);
  }
  // 8-byte words of a leaf.
  static constexpr std::size_t words(std::uint32_t count, std::uint32_t vertexCount) {
    return (coordinateOffset(count) + 12 * std::size_t(vertexCount) + 7) / 8;
  }

  std::uint32_t count() const { return count_; }
  std::uint32_t vertexCount() const { return load<std::uint32_t>(0); }
  std::uint32_t face(std::uint32_t i) const { return load<std::uint32_t>(4 + 4 * std::size_t(i)); }
  // The local vertex of corner c (0..2) of triangle i.
  std::uint32_t corner(std::uint32_t i, int c) const { return corners()[c * count_ + i]; }
  const unsigned char* corners() const { return data_ + cornerOffset(count_); }
  // Row `axis` of the vertices' coordinates.
  const float* row(int axis) const {
    return reinterpret_cast<const float*>(data_ + coordinateOffset(count_)) + axis * vertexCount();
  }
  Vec3 vertex(std::uint32_t v) const {
    const std::size_t at = coordinateOffset(count_) + 4 * std::size_t(v);
    const std::size_t stride = 4 * std::size_t(vertexCount());
    return {load<float>(at), load<float>(at + stride), load<float>(at + 2 * stride)};
  }
  PackedTriangle triangle(std::uint32_t i) const {
    return {vertex(corner(i, 0)), vertex(corner(i, 1)), vertex(corner(i, 2)), face(i)};
  }

 private:
  template <typename T>
  T load(std::size_t offset) const {
    T value;
    std::memcpy(&value, data_ + offset, sizeof(T));
    return value;
  }

  const unsigned char* data_;
  std::uint32_t count_;
};

// Writes a leaf of `count` triangles into `out` (BvhLeaf::words(count, vertexCount) words, zeroed):
// triangle i's face `face[i]`, corner c's coordinates `position[3 * i + c]` and local vertex
// `local[3 * i + c]` (numberLeafVertices).
inline void writeLeaf(std::uint64_t* out, std::uint32_t count, const std::uint32_t* face,
                      const Vec3* position, std::uint32_t vertexCount, const std::uint8_t* local) {
  auto* data = reinterpret_cast<unsigned char*>(out);
  std::memcpy(data, &vertexCount, 4);
  std::memcpy(data + 4, face, 4 * std::size_t(count));
  unsigned char* corners = data + BvhLeaf::cornerOffset(count);
  for (std::uint32_t i = 0; i < count; ++i) {
    for (int c = 0; c < 3; ++c) corners[c * count + i] = local[3 * i + c];
  }
  unsigned char* rows = data + BvhLeaf::coordinateOffset(count);
  for (std::uint32_t k = 0; k < 3 * count; ++k) {
    const std::size_t v = local[k];
    for (int a = 0; a < 3; ++a) {
      const float coordinate = position[k][a];
      std::memcpy(rows + 4 * (a * std::size_t(vertexCount) + v), &coordinate, 4);
    }
  }
}

// The local index of each corner: vertices numbered in order of first appearance among the corners
// `vertexOf[0 .. 3 count)`. Returns how many there are. Each corner is looked for among the
// vertices seen so far four at a time (SSE2), the first match taken: the numbering of a search one
// by one.
inline std::uint32_t numberLeafVertices(const std::uint32_t* vertexOf, std::uint32_t corners,
                                        std::uint8_t* local) {
#ifdef __SSE2__
  alignas(16) std::uint32_t seen[kMaxLeafVertices] = {};
  std::uint32_t vertexCount = 0;
  for (std::uint32_t k = 0; k < corners; ++k) {
    const __m128i key = _mm_set1_epi32(static_cast<int>(vertexOf[k]));
    std::uint32_t v = vertexCount;
    for (std::uint32_t at = 0; at < vertexCount; at += 4) {
      // Lanes past vertexCount hold stale or unset values: only matches below it count.
      const auto bits = static_cast<std::uint32_t>(_mm_movemask_ps(_mm_castsi128_ps(
          _mm_cmpeq_epi32(_mm_load_si128(reinterpret_cast<const __m128i*>(seen + at)), key))));
      if (bits != 0) {
        const std::uint32_t found = at + static_cast<std::uint32_t>(__builtin_ctz(bits));
        if (found < vertexCount) v = found;
        break;
      }
    }
    if (v == vertexCount) seen[vertexCount++] = vertexOf[k];
    local[k] = static_cast<std::uint8_t>(v);
  }
  return vertexCount;
#else
  std::uint32_t seen[kMaxLeafVertices];
  std::uint32_t vertexCount = 0;
  for (std::uint32_t k = 0; k < corners; ++k) {
    std::uint32_t v = 0;
    while (v < vertexCount && seen[v] != vertexOf[k]) ++v;
    if (v == vertexCount) seen[vertexCount++] = vertexOf[k];
    local[k] = static_cast<std::uint8_t>(v);
  }
  return vertexCount;
#endif
}

}  // namespace lancer::bvh
