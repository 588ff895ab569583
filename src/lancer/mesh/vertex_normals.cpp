#include "lancer/mesh/vertex_normals.hpp"

#include <cmath>
#include <numbers>

#include "lancer/mesh/face_geometry.hpp"

namespace lancer {

namespace {

// Interior angle of the face at corner `corner`: the weight of that face in the vertex normal.
float cornerAngle(std::span<const Vec3> positions, const MeshFace& face, int corner) {
  const int n = face.cornerCount();
  const Vec3& p = positions[face.vertex[corner]];
  const Vec3 toNext = normalize(positions[face.vertex[(corner + 1) % n]] - p);
  const Vec3 toPrev = normalize(positions[face.vertex[(corner + n - 1) % n]] - p);
  return std::acos(std::clamp(dot(toNext, toPrev), -1.0f, 1.0f));
}

}  // namespace

CornerNormals computeCornerNormals(std::span<const Vec3> positions, std::span<const MeshFace> faces,
                                   std::span<const std::int32_t> facePhysicalTag, float creaseAngleDegrees) {
  const std::size_t faceCount = faces.size();
  std::vector<Vec3> unitFaceNormal(faceCount);
  for (std::size_t f = 0; f < faceCount; ++f) unitFaceNormal[f] = faceNormal(positions, faces[f]);

  // Vertex -> incident (face, corner) pairs in compressed rows.
  std::vector<std::uint32_t> rowStart(positions.size() + 1, 0);
  for (const MeshFace& face : faces)
    for (int c = 0; c < face.cornerCount(); ++c) ++rowStart[face.vertex[c] + 1];
  for (std::size_t v = 0; v < positions.size(); ++v) rowStart[v + 1] += rowStart[v];
  std::vector<std::uint32_t> fill(rowStart.begin(), rowStart.end() - 1);
  std::vector<std::uint32_t> incidentFace(rowStart.back());
  std::vector<float> incidentWeight(rowStart.back());
  for (std::uint32_t f = 0; f < faceCount; ++f) {
    for (int c = 0; c < faces[f].cornerCount(); ++c) {
      const std::uint32_t slot = fill[faces[f].vertex[c]]++;
      incidentFace[slot] = f;
      incidentWeight[slot] = cornerAngle(positions, faces[f], c);
    }
  }

  const float cosCrease = std::cos(creaseAngleDegrees * std::numbers::pi_v<float> / 180.0f);
  CornerNormals result;
  result.faceCorner.assign(faceCount, {0, 0, 0, 0});
  result.normals.reserve(positions.size());
  auto assignCorners = [&](std::uint32_t f, std::uint32_t v, std::uint32_t index) {
    const MeshFace& face = faces[f];
    for (int c = 0; c < face.cornerCount(); ++c)
      if (face.vertex[c] == v) result.faceCorner[f][c] = index;
  };
  for (std::uint32_t v = 0; v < positions.size(); ++v) {
    const std::size_t firstNormal = result.normals.size();
    // Smooth vertex (the common case): every pair of its faces is smoothed together, so every
    // corner gets the same sum, in the same order, as the general loop below would give it: one
    // sum and one normal instead of one per corner (the loop below took 7% of a big render).
    bool smooth = true;
    for (std::uint32_t a = rowStart[v]; a < rowStart[v + 1] && smooth; ++a) {
      const std::uint32_t f = incidentFace[a];
      for (std::uint32_t b = a + 1; b < rowStart[v + 1]; ++b) {
        const std::uint32_t g = incidentFace[b];
        // dot is symmetric to the bit, so this one test decides the pair for both corners.
        if (g != f && (facePhysicalTag[g] != facePhysicalTag[f] ||
                       dot(unitFaceNormal[f], unitFaceNormal[g]) < cosCrease)) {
          smooth = false;
          break;
        }
      }
    }
    if (smooth && rowStart[v + 1] > rowStart[v]) {
      Vec3 sum{0, 0, 0};
      for (std::uint32_t slot = rowStart[v]; slot < rowStart[v + 1]; ++slot)
        sum += unitFaceNormal[incidentFace[slot]] * incidentWeight[slot];
      const Vec3 normal = normalize(sum);
      if (dot(normal, normal) > 0.5f) {
        const auto index = static_cast<std::uint32_t>(result.normals.size());
        result.normals.push_back(normal);
        for (std::uint32_t slot = rowStart[v]; slot < rowStart[v + 1]; ++slot)
          assignCorners(incidentFace[slot], v, index);
        continue;
      }
    }
    for (std::uint32_t slot = rowStart[v]; slot < rowStart[v + 1]; ++slot) {
      const std::uint32_t f = incidentFace[slot];
      const Vec3 nf = unitFaceNormal[f];
      Vec3 sum{0, 0, 0};
      for (std::uint32_t other = rowStart[v]; other < rowStart[v + 1]; ++other) {
        const std::uint32_t g = incidentFace[other];
        if (g != f && (facePhysicalTag[g] != facePhysicalTag[f] || dot(nf, unitFaceNormal[g]) < cosCrease))
          continue;
        sum += unitFaceNormal[g] * incidentWeight[other];
      }
      Vec3 normal = normalize(sum);
      if (!(dot(normal, normal) > 0.5f)) normal = nf;  // cancelling neighbours: keep the face's own
      // Corners with the same smoothing set produce bit-identical sums: share one normal.
      std::uint32_t index = static_cast<std::uint32_t>(result.normals.size());
      for (std::size_t k = firstNormal; k < result.normals.size(); ++k) {
        if (result.normals[k] == normal) {
          index = static_cast<std::uint32_t>(k);
          break;
        }
      }
      if (index == result.normals.size()) result.normals.push_back(normal);
      assignCorners(f, v, index);
    }
  }
  return result;
}

}  // namespace lancer
