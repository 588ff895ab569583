// Geometry and rays made in code for the accelerator tests: triangle soups, grids whose vertices
// sit on the kd-tree's split planes, a tessellated sphere, degenerate and coplanar faces, and
// rays aimed at vertices, edges and split planes.
#pragma once

#include <bit>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "lancer/accel/kd_tree.hpp"
#include "lancer/math/ray.hpp"
#include "lancer/mesh/mesh.hpp"

namespace lancer::test {

// The same hit to the bit: face, t and barycentrics (what "equals brute force" means here).
inline bool sameBits(const Hit& a, const Hit& b) {
  return a.face == b.face && std::bit_cast<std::uint32_t>(a.t) == std::bit_cast<std::uint32_t>(b.t) &&
         std::bit_cast<std::uint32_t>(a.b1) == std::bit_cast<std::uint32_t>(b.b1) &&
         std::bit_cast<std::uint32_t>(a.b2) == std::bit_cast<std::uint32_t>(b.b2);
}

struct Soup {
  std::vector<Vec3> positions;
  std::vector<MeshFace> faces;

  std::uint32_t vertex(Vec3 p) {
    positions.push_back(p);
    return static_cast<std::uint32_t>(positions.size() - 1);
  }
  void triangle(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    faces.push_back({{a, b, c, kNoVertex}});
  }
  void quad(std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d) {
    faces.push_back({{a, b, c, d}});
  }
  void triangle(Vec3 a, Vec3 b, Vec3 c) { triangle(vertex(a), vertex(b), vertex(c)); }
};

inline Vec3 randomPoint(std::mt19937& rng, Vec3 lo, Vec3 hi) {
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  return {lo.x + u(rng) * (hi.x - lo.x), lo.y + u(rng) * (hi.y - lo.y), lo.z + u(rng) * (hi.z - lo.z)};
}

inline Vec3 randomDirection(std::mt19937& rng) {
  std::normal_distribution<float> n(0.0f, 1.0f);
  while (true) {
    const Vec3 d{n(rng), n(rng), n(rng)};
    if (dot(d, d) > 1e-6f) return normalize(d);
  }
}

// Triangles of every size in the unit cube, many of them straddling each other's planes.
inline Soup randomSoup(std::mt19937& rng, int count) {
  Soup soup;
  std::uniform_real_distribution<float> scale(0.002f, 0.4f);
  for (int i = 0; i < count; ++i) {
    const Vec3 c = randomPoint(rng, {0, 0, 0}, {1, 1, 1});
    const float s = i % 50 == 0 ? 1.0f : scale(rng) * scale(rng) * 3.0f;
    soup.triangle(c + randomDirection(rng) * s, c + randomDirection(rng) * s, c + randomDirection(rng) * s);
  }
  return soup;
}

// The six sides of the cube [0,n]^3 as n x n grids with integer corners: shared edges and
// vertices lie exactly on split planes. Quads on even sides, triangle pairs on odd ones.
inline Soup gridBox(int n) {
  Soup soup;
  for (int side = 0; side < 6; ++side) {
    const int axis = side / 2;
    const float level = side % 2 ? float(n) : 0.0f;
    const int u = (axis + 1) % 3, v = (axis + 2) % 3;
    std::vector<std::uint32_t> ids;
    for (int j = 0; j <= n; ++j) {
      for (int i = 0; i <= n; ++i) {
        Vec3 p;
        p[axis] = level;
        p[u] = float(i);
        p[v] = float(j);
        ids.push_back(soup.vertex(p));
      }
    }
    for (int j = 0; j < n; ++j) {
      for (int i = 0; i < n; ++i) {
        const std::uint32_t a = ids[j * (n + 1) + i], b = a + 1, c = b + (n + 1), d = a + (n + 1);
        if (side % 2 == 0) {
          soup.quad(a, b, c, d);
        } else {
          soup.triangle(a, b, c);
          soup.triangle(a, c, d);
        }
      }
    }
  }
  return soup;
}

// A UV sphere: triangle fans at the poles, quads elsewhere; shared vertices.
inline Soup sphere(int rings, int segments, Vec3 center = {0.5f, 0.5f, 0.5f}, float radius = 0.4f) {
  Soup soup;
  const float pi = 3.14159265358979f;
  const std::uint32_t north = soup.vertex(center + Vec3{0, 0, radius});
  std::vector<std::uint32_t> ring;
  for (int r = 1; r < rings; ++r) {
    const float theta = pi * float(r) / float(rings);
    for (int s = 0; s < segments; ++s) {
      const float phi = 2.0f * pi * float(s) / float(segments);
      ring.push_back(soup.vertex(
          center +
          Vec3{std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)} * radius));
    }
  }
  const std::uint32_t south = soup.vertex(center - Vec3{0, 0, radius});
  auto at = [&](int r, int s) { return ring[(r - 1) * segments + (s % segments)]; };
  for (int s = 0; s < segments; ++s) {
    soup.triangle(north, at(1, s), at(1, s + 1));
    soup.triangle(south, at(rings - 1, s + 1), at(rings - 1, s));
    for (int r = 1; r + 1 < rings; ++r) soup.quad(at(r, s), at(r + 1, s), at(r + 1, s + 1), at(r, s + 1));
  }
  return soup;
}

// Degenerate and coincident faces: zero-area triangles (collinear, repeated corner), slivers,
// axis-aligned triangles lying in one plane, exact duplicates (ties broken by face index) and a
// stack of overlapping coplanar triangles.
inline Soup adversarialSoup(std::mt19937& rng) {
  Soup soup;
  for (int i = 0; i < 40; ++i) {
    const Vec3 a = randomPoint(rng, {0, 0, 0}, {1, 1, 1});
    const Vec3 d = randomDirection(rng) * 0.3f;
    soup.triangle(a, a + d, a + d * 2.0f);                      // collinear
    soup.triangle(a, a, a + d);                                 // repeated corner
    soup.triangle(a, a + d, a + d * 0.5f + Vec3{1e-7f, 0, 0});  // sliver
  }
  for (int i = 0; i < 200; ++i) {
    // Axis-aligned triangles on a few planes shared with the grid coordinates 0.25, 0.5, 0.75.
    const int axis = i % 3;
    Vec3 a = randomPoint(rng, {0, 0, 0}, {1, 1, 1}), b = randomPoint(rng, {0, 0, 0}, {1, 1, 1}),
         c = randomPoint(rng, {0, 0, 0}, {1, 1, 1});
    a[axis] = b[axis] = c[axis] = 0.25f * float(1 + i % 3);
    soup.triangle(a, b, c);
    if (i % 10 == 0) soup.triangle(a, b, c);  // exact duplicate: same t, the lower face must win
  }
  for (int i = 0; i < 30; ++i) {
    // Overlapping coplanar triangles in the oblique plane x + y + z = 1.5.
    auto onPlane = [&] {
      Vec3 p = randomPoint(rng, {0.2f, 0.2f, 0}, {0.8f, 0.8f, 0});
      p.z = 1.5f - p.x - p.y;
      return p;
    };
    soup.triangle(onPlane(), onPlane(), onPlane());
  }
  return soup;
}

struct TestRay {
  Ray ray;
  float tMin = 0.0f;
  float tMax = std::numeric_limits<float>::infinity();
};

// adversarialSoup(seed 4) inside a 4x4x4 grid box scaled to a quarter, so the tree has split
// planes through the coincident faces.
inline Soup adversarialSoupInGrid() {
  std::mt19937 rng(4);
  Soup soup = adversarialSoup(rng);
  const Soup grid = gridBox(4);
  for (MeshFace f : grid.faces) {
    for (std::uint32_t& v : f.vertex) {
      if (v != kNoVertex) v += static_cast<std::uint32_t>(soup.positions.size());
    }
    soup.faces.push_back(f);
  }
  for (const Vec3& p : grid.positions) soup.positions.push_back(p * 0.25f);
  return soup;
}

inline Vec3 corner(const Soup& soup, std::uint32_t face, int c) {
  return soup.positions[soup.faces[face].vertex[c]];
}

// Random rays plus rays aimed at vertices, edge points, face centres and the tree's split planes,
// and axis-parallel rays whose origins lie in split planes.
inline std::vector<TestRay> adversarialRays(const Soup& soup, const KdTree& tree, std::mt19937& rng,
                                            int count) {
  std::vector<TestRay> rays;
  Aabb box;
  for (const Vec3& p : soup.positions) box.extend(p);
  const Vec3 pad = box.extent() * 0.5f + Vec3{0.1f, 0.1f, 0.1f};
  const Vec3 lo = box.lower - pad, hi = box.upper + pad;
  std::uniform_int_distribution<std::uint32_t> anyFace(0, static_cast<std::uint32_t>(soup.faces.size() - 1));
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  std::vector<float> splits[3];
  for (std::vector<std::uint32_t> stack{0}; !stack.empty();) {
    const KdNode node = tree.layout()[stack.back()];
    stack.pop_back();
    if (node.isLeaf()) continue;
    splits[node.axis()].push_back(node.split());
    stack.push_back(node.firstChild());
    stack.push_back(node.firstChild() + 1);
  }
  auto pickSplit = [&](int axis, float fallback) {
    if (splits[axis].empty()) return fallback;
    std::uniform_int_distribution<std::size_t> pick(0, splits[axis].size() - 1);
    return splits[axis][pick(rng)];
  };
  auto aimAt = [&](Vec3 target, int variant) {
    TestRay r;
    const Vec3 origin = randomPoint(rng, lo, hi);
    r.ray = Ray(origin, target - origin);  // hit near t = 1
    if (variant == 1) r.tMin = 1e-4f;
    if (variant == 2) r.tMax = 1.0f;  // the open end sits on the target
    rays.push_back(r);
  };
  for (int i = 0; rays.size() < static_cast<std::size_t>(count); ++i) {
    const std::uint32_t f = anyFace(rng);
    const int corners = soup.faces[f].cornerCount();
    const int c = static_cast<int>(rng() % corners);
    const Vec3 a = corner(soup, f, c), b = corner(soup, f, (c + 1) % corners);
    switch (i % 8) {
      case 0: {  // random
        TestRay r;
        r.ray = Ray(randomPoint(rng, lo, hi), randomDirection(rng));
        rays.push_back(r);
        break;
      }
      case 1:
        aimAt(a, i / 8 % 3);
        break;  // vertex
      case 2:
        aimAt(a + (b - a) * 0.5f, i / 8 % 3);
        break;  // edge midpoint
      case 3:
        aimAt(a + (b - a) * unit(rng), i / 8 % 3);
        break;   // edge point
      case 4: {  // split plane point
        Vec3 target = randomPoint(rng, box.lower, box.upper);
        const int axis = static_cast<int>(rng() % 3);
        target[axis] = pickSplit(axis, target[axis]);
        aimAt(target, i / 8 % 3);
        break;
      }
      case 5: {  // axis-parallel, origin in split planes (or on the vertex's coordinates)
        const int axis = static_cast<int>(rng() % 3);
        Vec3 origin = i % 16 < 8 ? a : randomPoint(rng, box.lower, box.upper);
        for (int k = 0; k < 3; ++k) {
          if (k != axis && rng() % 2) origin[k] = pickSplit(k, origin[k]);
        }
        origin[axis] = rng() % 2 ? lo[axis] : hi[axis];
        Vec3 dir;
        dir[axis] = origin[axis] == lo[axis] ? 1.0f : -1.0f;
        TestRay r;
        r.ray = Ray(origin, dir);
        rays.push_back(r);
        break;
      }
      case 6: {  // lying in a split plane, parallel to it
        const int axis = static_cast<int>(rng() % 3);
        Vec3 origin = randomPoint(rng, lo, hi);
        origin[axis] = pickSplit(axis, a[axis]);
        Vec3 dir = randomDirection(rng);
        dir[axis] = 0.0f;
        if (dot(dir, dir) == 0.0f) dir[(axis + 1) % 3] = 1.0f;
        TestRay r;
        r.ray = Ray(origin, dir);
        rays.push_back(r);
        break;
      }
      case 7: {  // from a point on a face (a secondary ray), tMin = 0 or a small offset
        const Vec3 p = a + (b - a) * unit(rng);
        TestRay r;
        r.ray = Ray(p, randomDirection(rng));
        r.tMin = i % 16 < 8 ? 0.0f : 1e-4f;
        rays.push_back(r);
        break;
      }
    }
  }
  return rays;
}

// Rays from near the centre of a closed mesh to each corner of each face and to the middle and a
// quarter of each edge, each from its own origin (the centre jittered by up to 5% of the box, fixed
// seed): the rays that slip through a test that is not watertight.
inline std::vector<Ray> raysAtCornersAndEdges(const std::vector<Vec3>& positions,
                                              const std::vector<MeshFace>& faces) {
  Aabb box;
  for (const Vec3& p : positions) box.extend(p);
  std::mt19937 rng(12345);
  std::uniform_real_distribution<float> jitter(-0.05f, 0.05f);
  std::vector<Ray> rays;
  for (const MeshFace& face : faces) {
    for (int c = 0; c < face.cornerCount(); ++c) {
      const Vec3 a = positions[face.vertex[c]];
      const Vec3 b = positions[face.vertex[(c + 1) % face.cornerCount()]];
      for (const float s : {0.0f, 0.5f, 0.25f}) {
        const Vec3 origin = box.center() + box.extent() * Vec3{jitter(rng), jitter(rng), jitter(rng)};
        rays.emplace_back(origin, a + (b - a) * s - origin);
      }
    }
  }
  return rays;
}

}  // namespace lancer::test
