// Refit: the tree of one time step kept for the next, whose vertices moved (a deformed shape, same
// faces): the leaves' vertices are gathered again from the new positions and every box recomputed
// bottom up (children lie after their parents in the depth-first layout, so one backward pass
// suffices). Answers stay exact as long as no triangle turned into a sliver; the SAH cost of the
// kept tree says when a rebuild pays.
#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstring>
#include <limits>

#include "lancer/accel/bvh/bvh.hpp"
#include "lancer/util/parallel_for.hpp"

namespace lancer {

namespace {

// Corners of the triangle a face's half `half` is (packTriangles's order).
PackedTriangle triangleOf(std::span<const Vec3> positions, const MeshFace& face, std::uint32_t id, int half) {
  return {positions[face.vertex[0]], positions[face.vertex[1 + half]], positions[face.vertex[2 + half]], id};
}

bool validFace(const MeshFace& face, std::size_t vertexCount) {
  for (int k = 0; k < face.cornerCount(); ++k) {
    if (face.vertex[k] >= vertexCount) return false;
  }
  return true;
}

// Rewrites triangles[first, first + count) (a quad's halves neighbours, (0,1,2) first: a triangle
// of the same face as the one before it is the second half) from `positions`, extending `box` by
// them; false when a face is out of range or, with `noSlivers`, a triangle is now a sliver.
bool regather(PackedTriangle* triangles, std::size_t count, std::span<const Vec3> positions,
              std::span<const MeshFace> faces, bool noSlivers, Aabb& box) {
  std::uint32_t previous = 0xFFFFFFFFu;
  for (std::size_t i = 0; i < count; ++i) {
    const std::uint32_t id = triangles[i].face;
    const bool half = id == previous;
    previous = id;
    if (id >= faces.size() || !validFace(faces[id], positions.size()) || (half && !faces[id].isQuad()))
      return false;
    const PackedTriangle tri = triangleOf(positions, faces[id], id, half);
    if (noSlivers && isSliverTriangle(tri.v0, tri.v1, tri.v2)) return false;
    triangles[i] = tri;
    box.extend(tri.v0);
    box.extend(tri.v1);
    box.extend(tri.v2);
  }
  return true;
}

// Rewrites the vertices of the leaf at `words` (`count` triangles; a quad's halves neighbours, (0,1,2)
// first: a triangle of the same face as the one before it is the second half) from `positions`,
// giving its box; false when a face is out of range, its corners no longer match the leaf's shared
// vertices (other faces), or a triangle is now a sliver.
bool regatherLeaf(std::uint64_t* words, std::uint32_t count, std::span<const Vec3> positions,
                  std::span<const MeshFace> faces, Aabb& box) {
  const bvh::BvhLeaf leaf(words, count);
  const std::uint32_t vertexCount = leaf.vertexCount();
  std::uint32_t global[bvh::kMaxLeafVertices];
  std::fill(global, global + vertexCount, 0xFFFFFFFFu);
  std::uint32_t previous = 0xFFFFFFFFu;
  for (std::uint32_t i = 0; i < count; ++i) {
    const std::uint32_t id = leaf.face(i);
    const bool half = id == previous;
    previous = id;
    if (id >= faces.size() || !validFace(faces[id], positions.size()) || (half && !faces[id].isQuad()))
      return false;
    const MeshFace& face = faces[id];
    const std::uint32_t corner[3] = {face.vertex[0], face.vertex[1 + half], face.vertex[2 + half]};
    for (int c = 0; c < 3; ++c) {
      const std::uint32_t v = leaf.corner(i, c);
      if (v >= vertexCount || (global[v] != 0xFFFFFFFFu && global[v] != corner[c])) return false;
      global[v] = corner[c];
    }
  }
  // Rows x, y, z of the vertices, as the build wrote them (bvh/leaf.hpp).
  auto* rows = reinterpret_cast<unsigned char*>(words) + bvh::BvhLeaf::coordinateOffset(count);
  for (std::uint32_t v = 0; v < vertexCount; ++v) {
    if (global[v] == 0xFFFFFFFFu) return false;
    const Vec3& p = positions[global[v]];
    for (int a = 0; a < 3; ++a) {
      const float coordinate = p[a];
      std::memcpy(rows + 4 * (a * std::size_t(vertexCount) + v), &coordinate, 4);
    }
    box.extend(p);
  }
  for (std::uint32_t i = 0; i < count; ++i) {
    const PackedTriangle tri = leaf.triangle(i);
    if (isSliverTriangle(tri.v0, tri.v1, tri.v2)) return false;
  }
  return true;
}

}  // namespace

bool Bvh::refit(std::span<const Vec3> positions, std::span<const MeshFace> faces, int threads) {
  // Leaf by leaf on every thread: the triangles gathered again and the leaf's box from them while
  // they are at hand; then the inner children, backwards.
  std::atomic<bool> ok{true};
  parallelFor(nodes_.size(), threads, 256, [&](std::size_t n) {
    BvhNode& node = nodes_[n];
    for (int k = 0; k < BvhNode::kWidth; ++k) {
      const std::uint32_t child = node.child[k];
      if (child == BvhNode::kEmpty || !BvhNode::isLeaf(child)) continue;
      Aabb box;
      if (!regatherLeaf(leaves_.data() + BvhNode::leafFirst(child), BvhNode::leafCount(child), positions,
                        faces, box))
        ok = false;
      for (int a = 0; a < 3; ++a) {
        node.lower[a][k] = box.lower[a] + 0.0f;
        node.upper[a][k] = box.upper[a] + 0.0f;
      }
    }
  });
  Aabb sliverBox;
  if (!ok || !regather(slivers_.data(), slivers_.size(), positions, faces, false, sliverBox)) return false;
  for (std::size_t n = nodes_.size(); n-- > 0;) {
    BvhNode& node = nodes_[n];
    for (int k = 0; k < BvhNode::kWidth; ++k) {
      const std::uint32_t child = node.child[k];
      if (child == BvhNode::kEmpty || BvhNode::isLeaf(child)) continue;
      const BvhNode& below = nodes_[child];
      for (int a = 0; a < 3; ++a) {
        float lo = std::numeric_limits<float>::infinity(), hi = -lo;
        for (int c = 0; c < BvhNode::kWidth; ++c) {
          lo = std::min(lo, below.lower[a][c]);
          hi = std::max(hi, below.upper[a][c]);
        }
        node.lower[a][k] = lo;
        node.upper[a][k] = hi;
      }
    }
  }
  // The root's children hold the boxes of every leaf's triangles (the build's bounds: the slivers,
  // tested for every ray, are not in them).
  Aabb box;
  if (!nodes_.empty())
    for (int k = 0; k < BvhNode::kWidth; ++k)
      if (nodes_[0].child[k] != BvhNode::kEmpty) {
        box.extend(Vec3{nodes_[0].lower[0][k], nodes_[0].lower[1][k], nodes_[0].lower[2][k]});
        box.extend(Vec3{nodes_[0].upper[0][k], nodes_[0].upper[1][k], nodes_[0].upper[2][k]});
      }
  setBounds(box);
  stats_.sahCost = sahCost();
  return true;
}

double Bvh::sahCost() const {
  if (nodes_.empty()) return 0.0;
  auto area = [](const BvhNode& node, int k) {
    const float x = node.upper[0][k] - node.lower[0][k], y = node.upper[1][k] - node.lower[1][k],
                z = node.upper[2][k] - node.lower[2][k];
    return x < 0 ? 0.0 : 2.0 * (double(x) * y + double(y) * z + double(z) * x);
  };
  // Each node's area is the union of its children's boxes, which its parent holds.
  std::vector<double> nodeArea(nodes_.size(), 0.0);
  {
    Aabb root;
    const BvhNode& node = nodes_[0];
    for (int k = 0; k < BvhNode::kWidth; ++k) {
      if (node.child[k] == BvhNode::kEmpty) continue;
      root.extend(Vec3{node.lower[0][k], node.lower[1][k], node.lower[2][k]});
      root.extend(Vec3{node.upper[0][k], node.upper[1][k], node.upper[2][k]});
    }
    nodeArea[0] = root.empty() ? 0.0 : double(root.surfaceArea());
  }
  const double rootArea = nodeArea[0] > 0 ? nodeArea[0] : 1.0;
  if (nodeArea[0] <= 0) nodeArea[0] = 1.0;
  double cost = 0;
  for (std::size_t n = 0; n < nodes_.size(); ++n) {
    const BvhNode& node = nodes_[n];
    cost += traversalCost_ * nodeArea[n] / rootArea;
    for (int k = 0; k < BvhNode::kWidth; ++k) {
      const std::uint32_t child = node.child[k];
      if (child == BvhNode::kEmpty) continue;
      if (BvhNode::isLeaf(child)) {
        cost += intersectionCost_ * BvhNode::leafCount(child) * area(node, k) / rootArea;
      } else {
        nodeArea[child] = area(node, k);
      }
    }
  }
  return cost;
}

}  // namespace lancer
