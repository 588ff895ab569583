#include "lancer/render/surface_point.hpp"

#include <cmath>

#include "lancer/render/ray_offset.hpp"
#include "lancer/render/shading.hpp"

namespace lancer {
namespace {

struct Vec2 {
  float x, y;
};
Vec2 operator-(Vec2 a, Vec2 b) { return {a.x - b.x, a.y - b.y}; }
Vec2 operator+(Vec2 a, Vec2 b) { return {a.x + b.x, a.y + b.y}; }
float cross2(Vec2 a, Vec2 b) { return a.x * b.y - a.y * b.x; }

// Barycentric weights of p in triangle (a, b, c) (p is on its plane).
void barycentric(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& p, float w[3]) {
  const Vec3 e1 = b - a, e2 = c - a, h = p - a;
  const float d11 = dot(e1, e1), d12 = dot(e1, e2), d22 = dot(e2, e2);
  const float dh1 = dot(h, e1), dh2 = dot(h, e2);
  const float det = d11 * d22 - d12 * d12;
  if (!(std::abs(det) > 0.0f)) {
    w[0] = 1;
    w[1] = w[2] = 0;
    return;
  }
  const float v = std::clamp((d22 * dh1 - d12 * dh2) / det, 0.0f, 1.0f);
  const float u = std::clamp((d11 * dh2 - d12 * dh1) / det, 0.0f, 1.0f - v);
  w[0] = 1.0f - u - v;
  w[1] = v;
  w[2] = u;
}

// Inverse of the bilinear map q(u,v) = a + u e + v f + u v g in 2D (Quilez, "inverse bilinear
// interpolation"); returns false when p is outside the quad.
bool inverseBilinear(Vec2 p, Vec2 a, Vec2 b, Vec2 c, Vec2 d, float& u, float& v) {
  const Vec2 e = b - a, f = d - a, g = (a - b) + (c - d), h = p - a;
  const float k2 = cross2(g, f);
  const float k1 = cross2(e, f) + cross2(h, g);
  const float k0 = cross2(h, e);
  auto solveU = [&](float vv) {
    const Vec2 denominator = e + Vec2{g.x * vv, g.y * vv};
    return std::abs(denominator.x) > std::abs(denominator.y) ? (h.x - f.x * vv) / denominator.x
                                                             : (h.y - f.y * vv) / denominator.y;
  };
  constexpr float kTolerance = 1e-4f;
  auto inside = [&](float uu, float vv) {
    return uu >= -kTolerance && uu <= 1 + kTolerance && vv >= -kTolerance && vv <= 1 + kTolerance;
  };
  if (std::abs(k2) < 1e-7f * std::abs(k1)) {  // a parallelogram: the equation is linear
    v = -k0 / k1;
    u = solveU(v);
    return inside(u, v);
  }
  const float discriminant = k1 * k1 - 4.0f * k0 * k2;
  if (discriminant < 0) return false;
  const float root = std::sqrt(discriminant);
  v = (-k1 - root) / (2.0f * k2);
  u = solveU(v);
  if (inside(u, v)) return true;
  v = (-k1 + root) / (2.0f * k2);
  u = solveU(v);
  return inside(u, v);
}

}  // namespace

void faceCornerWeights(const Scene& scene, const MeshFace& face, const Vec3& p, float weights[4]) {
  const Vec3& a = scene.geometry.positions[face.vertex[0]];
  const Vec3& b = scene.geometry.positions[face.vertex[1]];
  const Vec3& c = scene.geometry.positions[face.vertex[2]];
  weights[3] = 0;
  if (!face.isQuad()) {
    barycentric(a, b, c, p, weights);
    return;
  }
  const Vec3& d = scene.geometry.positions[face.vertex[3]];
  // Project on the plane of the quad's dominant normal axis.
  const Vec3 n = abs(cross(c - a, d - b));
  const int dropped = n.x >= n.y && n.x >= n.z ? 0 : (n.y >= n.z ? 1 : 2);
  const int i = dropped == 0 ? 1 : 0, j = dropped == 2 ? 1 : 2;
  auto project = [&](const Vec3& q) { return Vec2{q[i], q[j]}; };
  float u = 0, v = 0;
  if (inverseBilinear(project(p), project(a), project(b), project(c), project(d), u, v)) {
    u = std::clamp(u, 0.0f, 1.0f);
    v = std::clamp(v, 0.0f, 1.0f);
    weights[0] = (1 - u) * (1 - v);
    weights[1] = u * (1 - v);
    weights[2] = u * v;
    weights[3] = (1 - u) * v;
    return;
  }
  // Strongly warped quad: fall back to the barycentric weights of the nearer half.
  float w[3];
  const Vec3 toP = p - a;
  if (dot(cross(c - a, toP), cross(c - a, b - a)) >= 0) {
    barycentric(a, b, c, p, w);
    weights[0] = w[0], weights[1] = w[1], weights[2] = w[2], weights[3] = 0;
  } else {
    barycentric(a, c, d, p, w);
    weights[0] = w[0], weights[1] = 0, weights[2] = w[1], weights[3] = w[2];
  }
}

// Rebuilding a point from the corners rounds each coordinate relative to the corners' own; the
// triangle test of a ray leaving the point errs relative to the triangle's size, in every direction
// (its frame follows the ray, not the surface), so that part is the same for each coordinate.
Vec3 surfacePointError(const Vec3& a, const Vec3& b, const Vec3& c) {
  const float size = maxComponent(max(max(a, b), c) - min(min(a, b), c));
  return (max(max(abs(a), abs(b)), abs(c)) + Vec3{size, size, size}) * kSurfacePointRelativeError;
}

// The point of the triangle the accelerators tested (a quad is corners 0,1,2 and 0,2,3) nearest
// to p, as a convex combination of its corners, with the bound on its coordinates' error.
void pointOnHitTriangle(const Scene& scene, const MeshFace& face, const Vec3& p, Vec3& point, Vec3& error) {
  const Vec3& a = scene.geometry.positions[face.vertex[0]];
  Vec3 b = scene.geometry.positions[face.vertex[1]];
  Vec3 c = scene.geometry.positions[face.vertex[2]];
  if (face.isQuad() && dot(cross(c - a, p - a), cross(c - a, b - a)) < 0) {
    b = c;
    c = scene.geometry.positions[face.vertex[3]];
  }
  float w[3];
  barycentric(a, b, c, p, w);
  point = a * w[0] + b * w[1] + c * w[2];
  error = surfacePointError(a, b, c);
}

namespace {

// Whether shading reads a point's corner weights on `face` (shading.cpp, field_shading.cpp).
bool needsCornerWeights(const Scene& scene, std::uint32_t face) {
  const ShadingMode mode = scene.appearance.faceShading[face];
  if (mode != ShadingMode::Flat && mode != ShadingMode::Unlit) return true;
  // Isolines read the field at the point (an element-data colour does not).
  if (scene.isolines && scene.isolines->faceStyle[face] != 0) return true;
  if (!scene.fieldColors) return false;
  const std::uint8_t map = scene.fieldColors->faceColorMap[face];
  return map != 0 && (map & FieldColors::kPerFace) == 0;
}

}  // namespace

SurfacePoint makeSurfacePoint(const Scene& scene, const Ray& ray, const Hit& hit) {
  SurfacePoint sp;
  sp.face = hit.face;
  const MeshFace& face = scene.geometry.faces[hit.face];
  if (face.isQuad()) {
    // Bilinear weights are not the hit half's barycentric ones: found again from the point, where
    // something reads them (smooth or Gouraud normals, a per-vertex field colour); a flat quad's
    // shading never does, and inverting the bilinear map is a fair part of its cost.
    const Vec3 alongRay = ray.at(hit.t);
    if (needsCornerWeights(scene, hit.face)) {
      faceCornerWeights(scene, face, alongRay, sp.cornerWeight);
    } else {
      for (float& weight : sp.cornerWeight) weight = 0.25f;
    }
    pointOnHitTriangle(scene, face, alongRay, sp.position, sp.positionError);
  } else {
    // The triangle test's own weights (the accelerators' triangle is the face, corners in order):
    // exact to a few ulps of the triangle, where projecting ray.at(t) errs with the ray's length.
    sp.cornerWeight[0] = 1.0f - hit.b1 - hit.b2;
    sp.cornerWeight[1] = hit.b1;
    sp.cornerWeight[2] = hit.b2;
    sp.cornerWeight[3] = 0.0f;
    const Vec3 &a = scene.geometry.positions[face.vertex[0]], &b = scene.geometry.positions[face.vertex[1]],
               &c = scene.geometry.positions[face.vertex[2]];
    sp.position = a * sp.cornerWeight[0] + b * sp.cornerWeight[1] + c * sp.cornerWeight[2];
    sp.positionError = surfacePointError(a, b, c);
  }

  const Vec3 ng = scene.geometry.faceNormals[hit.face];
  // Two-sided faces: shade the side the ray arrives on.
  sp.normalSign = dot(ng, ray.direction) <= 0.0f ? 1.0f : -1.0f;
  sp.geometricNormal = ng * sp.normalSign;
  sp.shadingNormal = shadingNormal(scene, hit.face, sp.cornerWeight, sp.geometricNormal, sp.normalSign);
  return sp;
}

SurfacePoint makeCapPoint(const Scene& scene, const Ray& ray, const ClipPlane& plane, float t,
                          std::uint32_t face) {
  SurfacePoint cap{};
  cap.face = face;
  cap.position = ray.at(t);
  cap.positionError = rayPointError(ray.origin, ray.direction, t);
  cap.geometricNormal = cap.shadingNormal = plane.normal;
  cap.normalSign = 1.0f;
  cap.isCap = true;
  const int corners = scene.geometry.faces[face].cornerCount();
  for (int c = 0; c < corners; ++c) cap.cornerWeight[c] = 1.0f / static_cast<float>(corners);
  return cap;
}

}  // namespace lancer
