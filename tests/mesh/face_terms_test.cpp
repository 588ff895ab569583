// A face's normal and corner angles (the weights of its vertices' smooth normals) against their
// definitions in double: triangles and quads of any shape, a block of eight and a face alone give
// the same bits, and a sliver of a face is reported.
#include "lancer/mesh/face_terms.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <numbers>
#include <random>

#include "lancer/mesh/face_geometry.hpp"

namespace lancer {
namespace {

double angleAt(const Vec3& previous, const Vec3& corner, const Vec3& next) {
  const Vec3d a = toDouble(previous) - toDouble(corner), b = toDouble(next) - toDouble(corner);
  return std::acos(std::clamp(dot(a, b) / std::sqrt(dot(a, a) * dot(b, b)), -1.0, 1.0));
}

TEST(FaceTerms, NormalsAndAnglesAreTheirDefinitions) {
  std::mt19937 random(7);
  std::uniform_real_distribution<float> coordinate(-1.0f, 1.0f);
  std::vector<Vec3> positions;
  std::vector<MeshFace> faces;
  for (int k = 0; k < 203; ++k) {  // not a multiple of eight: a short last block
    const auto first = static_cast<std::uint32_t>(positions.size());
    const bool quad = k % 3 != 0;
    // A quad from a random convex planar quadrilateral (a square pulled out of shape), turned in space.
    const float s = 0.5f + coordinate(random) * 0.3f, t = 0.3f * coordinate(random);
    const Vec3 u = normalize(Vec3{coordinate(random), coordinate(random), coordinate(random)});
    const Vec3 v = normalize(cross(u, normalize(Vec3{coordinate(random), coordinate(random), 1.0f})));
    const Vec3 origin{coordinate(random), coordinate(random), coordinate(random)};
    positions.push_back(origin);
    positions.push_back(origin + u * (1.0f + t));
    positions.push_back(origin + u * (0.8f + s) + v * (0.9f - t));
    if (quad) positions.push_back(origin + u * (0.1f * s) + v * (0.7f + s));
    faces.push_back({{first, first + 1, first + 2, quad ? first + 3 : kNoVertex}});
  }
  std::vector<Vec3> normals(faces.size());
  std::vector<std::array<float, 4>> angles(faces.size());
  EXPECT_TRUE(faceTermsOf(positions, faces, normals.data(), angles.data()));
  for (std::size_t f = 0; f < faces.size(); ++f) {
    const MeshFace& face = faces[f];
    const int n = face.cornerCount();
    double sum = 0;
    for (int c = 0; c < n; ++c) {
      const double expected = angleAt(positions[face.vertex[(c + n - 1) % n]], positions[face.vertex[c]],
                                      positions[face.vertex[(c + 1) % n]]);
      EXPECT_NEAR(angles[f][c], expected, 2e-5) << "face " << f << " corner " << c;
      sum += angles[f][c];
    }
    if (n == 3) {
      EXPECT_EQ(angles[f][3], 0.0f);
    }
    EXPECT_NEAR(sum, (n - 2) * std::numbers::pi, 1e-4) << "face " << f;  // planar faces
    const Vec3 exact = faceNormal(positions, face);
    EXPECT_GT(dot(normals[f], exact), 1.0f - 1e-6f) << "face " << f;
    EXPECT_NEAR(length(normals[f]), 1.0f, 1e-6f);
    // Alone, the same bits as in its block.
    Vec3 aloneNormal;
    std::array<float, 4> aloneAngles;
    faceTermsOf(positions, std::span<const MeshFace>(faces).subspan(f, 1), &aloneNormal, &aloneAngles);
    EXPECT_EQ(std::memcmp(&aloneNormal, &normals[f], sizeof(Vec3)), 0);
    EXPECT_EQ(std::memcmp(aloneAngles.data(), angles[f].data(), sizeof(aloneAngles)), 0);
  }
}

TEST(FaceTerms, ASliverIsNotClearOfDegenerate) {
  const std::vector<Vec3> positions = {{0, 0, 0}, {1, 0, 0}, {0.5f, 1e-7f, 0}, {0, 1, 0}};
  const std::vector<MeshFace> faces = {{{0, 1, 3, kNoVertex}}, {{0, 1, 2, kNoVertex}}};
  std::vector<Vec3> normals(2);
  std::vector<std::array<float, 4>> angles(2);
  EXPECT_TRUE(
      faceTermsOf(positions, std::span<const MeshFace>(faces).first(1), normals.data(), angles.data()));
  EXPECT_FALSE(faceTermsOf(positions, faces, normals.data(), angles.data()));
}

}  // namespace
}  // namespace lancer
