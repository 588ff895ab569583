#include "lancer/mesh/msh/high_order.hpp"

#include <array>
#include <mutex>

#include "lancer/mesh/msh/element_types.hpp"

namespace lancer {
namespace {

constexpr int kMaxOrder = 10;

// Lattice point (i, j) of an element of order p -> local node index, filled in gmsh's order.
using Lattice = std::array<std::array<int, kMaxOrder + 1>, kMaxOrder + 1>;

// Triangle of order p whose lattice starts at (o, o): corners (0,0), (p,0), (0,p), edges, interior.
void fillTriangle(Lattice& at, int p, int o, int& next) {
  if (p < 0) return;
  if (p == 0) {
    at[o][o] = next++;
    return;
  }
  at[o][o] = next++;
  at[o + p][o] = next++;
  at[o][o + p] = next++;
  for (int k = 1; k < p; ++k) at[o + k][o] = next++;
  for (int k = 1; k < p; ++k) at[o + p - k][o + k] = next++;
  for (int k = 1; k < p; ++k) at[o][o + p - k] = next++;
  fillTriangle(at, p - 3, o + 1, next);
}

// Quadrangle of order p from (o, o): corners (0,0), (p,0), (p,p), (0,p), edges, interior.
void fillQuad(Lattice& at, int p, int o, int& next) {
  if (p < 0) return;
  if (p == 0) {
    at[o][o] = next++;
    return;
  }
  at[o][o] = next++;
  at[o + p][o] = next++;
  at[o + p][o + p] = next++;
  at[o][o + p] = next++;
  for (int k = 1; k < p; ++k) at[o + k][o] = next++;
  for (int k = 1; k < p; ++k) at[o + p][o + k] = next++;
  for (int k = 1; k < p; ++k) at[o + p - k][o + p] = next++;
  for (int k = 1; k < p; ++k) at[o][o + p - k] = next++;
  fillQuad(at, p - 2, o + 1, next);
}

std::uint16_t node(const Lattice& at, int i, int j) { return static_cast<std::uint16_t>(at[i][j]); }

std::vector<MshSubFace> splitTriangle(int p) {
  Lattice at{};
  int next = 0;
  fillTriangle(at, p, 0, next);
  std::vector<MshSubFace> faces;
  for (int j = 0; j < p; ++j) {
    for (int i = 0; i + j < p; ++i) {
      const auto mask =
          static_cast<std::uint8_t>((j == 0 ? 1 : 0) | (i + j + 1 == p ? 2 : 0) | (i == 0 ? 4 : 0));
      faces.push_back({{node(at, i, j), node(at, i + 1, j), node(at, i, j + 1), kNoSubCorner}, mask});
      if (i + j + 1 < p)
        faces.push_back({{node(at, i + 1, j), node(at, i + 1, j + 1), node(at, i, j + 1), kNoSubCorner}, 0});
    }
  }
  return faces;
}

std::vector<MshSubFace> splitQuad(int p) {
  Lattice at{};
  int next = 0;
  fillQuad(at, p, 0, next);
  std::vector<MshSubFace> faces;
  for (int j = 0; j < p; ++j) {
    for (int i = 0; i < p; ++i) {
      const auto mask = static_cast<std::uint8_t>((j == 0 ? 1 : 0) | (i + 1 == p ? 2 : 0) |
                                                  (j + 1 == p ? 4 : 0) | (i == 0 ? 8 : 0));
      faces.push_back(
          {{node(at, i, j), node(at, i + 1, j), node(at, i + 1, j + 1), node(at, i, j + 1)}, mask});
    }
  }
  return faces;
}

std::vector<MshSubFace> facesOf(int type) {
  const int order = mshCompleteSurfaceOrder(type);
  if (order && mshSurfaceCorners(type) == 3) return splitTriangle(order);
  if (order) return splitQuad(order);
  switch (mshSurfaceCorners(type)) {
    case 3:
      return {{{0, 1, 2, kNoSubCorner}, 0b111}};
    case 4:
      return {{{0, 1, 2, 3}, 0x0F}};
    default:
      return {};
  }
}

}  // namespace

const std::vector<MshSubFace>& mshHighOrderSurfaceFaces(int type) {
  static std::array<std::vector<MshSubFace>, kMaxMshElementType + 1> cache;
  static std::array<std::once_flag, kMaxMshElementType + 1> once;
  static const std::vector<MshSubFace> none;
  if (type < 1 || type > kMaxMshElementType) return none;
  const auto index = static_cast<std::size_t>(type);
  std::call_once(once[index], [&] { cache[index] = facesOf(type); });
  return cache[index];
}

}  // namespace lancer
