#include "lancer/mesh/vertex_normals.hpp"

#include <cmath>
#include <numbers>

#include "lancer/mesh/face_geometry.hpp"
#include "lancer/util/parallel_for.hpp"

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

// Items per chunk of the parallel loops: big enough that a chunk outweighs handing it out.
constexpr std::size_t kGrain = 16384;

}  // namespace

CornerNormals computeCornerNormals(std::span<const Vec3> positions, std::span<const MeshFace> faces,
                                   std::span<const std::int32_t> facePhysicalTag, float creaseAngleDegrees,
                                   int threads) {
  const std::size_t faceCount = faces.size();
  std::vector<Vec3> unitFaceNormal(faceCount);
  parallelFor(faceCount, threads, kGrain,
              [&](std::size_t f) { unitFaceNormal[f] = faceNormal(positions, faces[f]); });

  // Vertex -> incident (face, corner) pairs in compressed rows, in face order (the order of the sums
  // below, so the normals do not depend on the thread count).
  std::vector<std::uint32_t> rowStart(positions.size() + 1, 0);
  for (const MeshFace& face : faces)
    for (int c = 0; c < face.cornerCount(); ++c) ++rowStart[face.vertex[c] + 1];
  for (std::size_t v = 0; v < positions.size(); ++v) rowStart[v + 1] += rowStart[v];
  std::vector<std::uint32_t> fill(rowStart.begin(), rowStart.end() - 1);
  std::vector<std::uint32_t> incidentCorner(rowStart.back());  // face << 2 | corner
  for (std::uint32_t f = 0; f < faceCount; ++f)
    for (int c = 0; c < faces[f].cornerCount(); ++c)
      incidentCorner[fill[faces[f].vertex[c]]++] = f << 2 | static_cast<std::uint32_t>(c);
  std::vector<std::uint32_t>().swap(fill);

  const float cosCrease = std::cos(creaseAngleDegrees * std::numbers::pi_v<float> / 180.0f);
  CornerNormals result;
  result.faceCorner.assign(faceCount, {0, 0, 0, 0});
  // Vertices in chunks, each with its own list of normals: chunk k's indices are local until the
  // lists are concatenated in chunk order, which gives the same list as one pass over all vertices.
  const ChunkPlan plan(positions.size(), kGrain);
  std::vector<std::vector<Vec3>> chunkNormals(plan.chunks);
  parallelChunks(plan, threads, [&](std::size_t chunk, std::size_t firstVertex, std::size_t endVertex) {
    std::vector<Vec3>& normals = chunkNormals[chunk];
    normals.reserve(endVertex - firstVertex);
    std::vector<float> incidentWeight;
    for (auto v = static_cast<std::uint32_t>(firstVertex); v < endVertex; ++v) {
      const std::uint32_t first = rowStart[v], end = rowStart[v + 1];
      const std::size_t firstNormal = normals.size();
      incidentWeight.resize(end - first);
      for (std::uint32_t slot = first; slot < end; ++slot) {
        const std::uint32_t code = incidentCorner[slot];
        incidentWeight[slot - first] = cornerAngle(positions, faces[code >> 2], static_cast<int>(code & 3u));
      }
      auto faceOf = [&](std::uint32_t slot) { return incidentCorner[slot] >> 2; };
      auto assign = [&](std::uint32_t slot, std::uint32_t index) {
        const std::uint32_t code = incidentCorner[slot];
        result.faceCorner[code >> 2][code & 3u] = index;
      };
      // Smooth vertex (the common case): every pair of its faces is smoothed together, so every
      // corner gets the same sum, in the same order, as the general loop below would give it: one
      // sum and one normal instead of one per corner (the loop below took 7% of a big render).
      bool smooth = true;
      for (std::uint32_t a = first; a < end && smooth; ++a) {
        const std::uint32_t f = faceOf(a);
        for (std::uint32_t b = a + 1; b < end; ++b) {
          const std::uint32_t g = faceOf(b);
          // dot is symmetric to the bit, so this one test decides the pair for both corners.
          if (g != f && (facePhysicalTag[g] != facePhysicalTag[f] ||
                         dot(unitFaceNormal[f], unitFaceNormal[g]) < cosCrease)) {
            smooth = false;
            break;
          }
        }
      }
      if (smooth && end > first) {
        Vec3 sum{0, 0, 0};
        for (std::uint32_t slot = first; slot < end; ++slot)
          sum += unitFaceNormal[faceOf(slot)] * incidentWeight[slot - first];
        const Vec3 normal = normalize(sum);
        if (dot(normal, normal) > 0.5f) {
          const auto index = static_cast<std::uint32_t>(normals.size());
          normals.push_back(normal);
          for (std::uint32_t slot = first; slot < end; ++slot) assign(slot, index);
          continue;
        }
      }
      for (std::uint32_t slot = first; slot < end; ++slot) {
        const std::uint32_t f = faceOf(slot);
        const Vec3 nf = unitFaceNormal[f];
        Vec3 sum{0, 0, 0};
        for (std::uint32_t other = first; other < end; ++other) {
          const std::uint32_t g = faceOf(other);
          if (g != f && (facePhysicalTag[g] != facePhysicalTag[f] || dot(nf, unitFaceNormal[g]) < cosCrease))
            continue;
          sum += unitFaceNormal[g] * incidentWeight[other - first];
        }
        Vec3 normal = normalize(sum);
        if (!(dot(normal, normal) > 0.5f)) normal = nf;  // cancelling neighbours: keep the face's own
        // Corners with the same smoothing set produce bit-identical sums: share one normal.
        auto index = static_cast<std::uint32_t>(normals.size());
        for (std::size_t k = firstNormal; k < normals.size(); ++k) {
          if (normals[k] == normal) {
            index = static_cast<std::uint32_t>(k);
            break;
          }
        }
        if (index == normals.size()) normals.push_back(normal);
        assign(slot, index);
      }
    }
  });
  // Concatenate, and turn each chunk's local indices into indices into the whole list.
  std::vector<std::uint32_t> chunkBase(plan.chunks + 1, 0);
  for (std::size_t k = 0; k < plan.chunks; ++k)
    chunkBase[k + 1] = chunkBase[k] + static_cast<std::uint32_t>(chunkNormals[k].size());
  result.normals.resize(chunkBase[plan.chunks]);
  parallelChunks(plan, threads, [&](std::size_t chunk, std::size_t firstVertex, std::size_t endVertex) {
    std::copy(chunkNormals[chunk].begin(), chunkNormals[chunk].end(),
              result.normals.begin() + chunkBase[chunk]);
    if (chunkBase[chunk] == 0) return;
    for (std::uint32_t slot = rowStart[firstVertex]; slot < rowStart[endVertex]; ++slot) {
      const std::uint32_t code = incidentCorner[slot];
      result.faceCorner[code >> 2][code & 3u] += chunkBase[chunk];
    }
  });
  return result;
}

}  // namespace lancer
