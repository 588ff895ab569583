#include "lancer/mesh/vertex_normals.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <utility>

#include "lancer/math/fast_acos.hpp"
#include "lancer/mesh/face_geometry.hpp"
#include "lancer/mesh/prefetch_corners.hpp"
#include "lancer/mesh/vertex_corners.hpp"
#include "lancer/mesh/vertex_ranges.hpp"
#include "lancer/util/huge_pages.hpp"
#include "lancer/util/parallel_for.hpp"

namespace lancer {

namespace {

// The interior angles of a face at its corners: the weights of the face in its vertices' normals.
// Each edge is normalised once and shared by the two corners at its ends (the edge into a corner is
// the reverse of the one out of the previous corner, and negation is exact, so the angles are the
// same bits as from each corner's own two edges).
std::array<float, 4> cornerAngles(std::span<const Vec3> positions, const MeshFace& face) {
  const int n = face.cornerCount();
  Vec3 out[4];  // out[c]: unit edge from corner c to corner c + 1
  for (int c = 0; c < n; ++c)
    out[c] = normalize(positions[face.vertex[(c + 1) % n]] - positions[face.vertex[c]]);
  std::array<float, 4> angle{0, 0, 0, 0};
  for (int c = 0; c < n; ++c)
    angle[c] = fastAcos(std::clamp(dot(out[c], -out[(c + n - 1) % n]), -1.0f, 1.0f));
  return angle;
}

// Items per chunk of the parallel loops: big enough that a chunk outweighs handing it out.
constexpr std::size_t kGrain = 16384;

}  // namespace

CornerNormals computeCornerNormals(std::span<const Vec3> positions, std::span<const MeshFace> faces,
                                   std::span<const std::int32_t> facePhysicalTag, float creaseAngleDegrees,
                                   int threads, std::vector<Vec3>* unitFaceNormals) {
  const std::size_t faceCount = faces.size();
  const std::size_t vertexCount = positions.size();
  // Per face, in face order (sequential reads, shared out by chunks of faces): its unit normal and
  // the weights of its corners.
  std::vector<Vec3> unitFaceNormal = vectorOnHugePages<Vec3>(faceCount);
  std::vector<std::array<float, 4>> cornerWeight = vectorOnHugePages<std::array<float, 4>>(faceCount);
  parallelFor(faceCount, threads, kGrain, [&](std::size_t f) {
    prefetchCorners(positions.data(), faces, f + kPrefetchFacesAhead);
    unitFaceNormal[f] = faceNormal(positions, faces[f]);
    cornerWeight[f] = cornerAngles(positions, faces[f]);
  });

  const float cosCrease = std::cos(creaseAngleDegrees * std::numbers::pi_v<float> / 180.0f);
  // Half the crease angle less 1 mrad: two normals within it of a third are within the crease angle
  // of each other with a margin (2 mrad) thousands of times the error of a float dot product. (Not
  // for tiny crease angles, nor from 180 degrees on, where the cosine stops falling: there every
  // vertex takes the pairwise test.)
  constexpr float kMarginRadians = 1e-3f;
  const float halfCrease = creaseAngleDegrees * std::numbers::pi_v<float> / 360.0f - kMarginRadians;
  const float cosHalfCreaseWithMargin =
      halfCrease <= 0.0f || creaseAngleDegrees >= 180.0f ? 2.0f : std::cos(halfCrease);

  // Scatter-add in face order: each vertex's weighted sum of its faces' normals, added in face
  // order (the order of a walk over the vertex's faces, so the same bits), and whether all its
  // faces are of the first one's group and within half the crease angle of its normal: then every
  // pair of them is within the crease angle and the vertex is smooth, its sum its one normal (the
  // common case). Shared out by vertex ranges (vertex_ranges.hpp): the faces are read in order,
  // only the vertex records are written out of order, and no one walks a vertex's faces.
  struct VertexSum {
    Vec3 sum{0, 0, 0};
    Vec3 firstNormal{0, 0, 0};
    std::int32_t firstTag = 0;
    std::uint8_t faces = 0;       // 0, 1, or 2 for more
    std::uint8_t withinHalf = 1;  // every face so far in the first one's group and half crease
  };
  std::vector<VertexSum> vertexSum = vectorOnHugePages<VertexSum>(vertexCount);
  forEachVertexRange(vertexCount, threads, [&](std::size_t firstVertex, std::size_t endVertex) {
    for (std::size_t f = 0; f < faceCount; ++f) {
      prefetchCorners(vertexSum.data(), faces, f + kPrefetchFacesAhead);
      const MeshFace& face = faces[f];
      const Vec3 normal = unitFaceNormal[f];
      const std::int32_t tag = facePhysicalTag[f];
      for (int c = 0; c < face.cornerCount(); ++c) {
        const std::uint32_t v = face.vertex[c];
        if (v < firstVertex || v >= endVertex) continue;
        VertexSum& at = vertexSum[v];
        if (at.faces == 0) {
          at.firstNormal = normal;
          at.firstTag = tag;
          at.faces = 1;
        } else {
          at.faces = 2;
          at.withinHalf &= static_cast<std::uint8_t>(tag == at.firstTag &&
                                                     dot(at.firstNormal, normal) >= cosHalfCreaseWithMargin);
        }
        at.sum += normal * cornerWeight[f][c];
      }
    }
  });

  // The other vertices walk their faces (face order): the pairwise test, and where it fails, one
  // sum per corner over the faces smoothed with its own; so do vertices whose faces cancel out.
  auto mustWalk = [&](const VertexSum& at) { return at.faces == 2 && !at.withinHalf; };
  auto cancels = [](const VertexSum& at) {
    const Vec3 normal = normalize(at.sum);
    return !(dot(normal, normal) > 0.5f);
  };
  std::vector<std::uint8_t> walks(vertexCount, 0);
  parallelFor(vertexCount, threads, kGrain, [&](std::size_t v) {
    const VertexSum& at = vertexSum[v];
    walks[v] = at.faces != 0 && (mustWalk(at) || cancels(at));
  });
  VertexCorners vertexCorners;
  if (std::find(walks.begin(), walks.end(), 1) != walks.end())
    vertexCorners = findVertexCorners(faces, vertexCount, threads, walks);  // rows of those only
  const std::vector<std::uint32_t>& rowStart = vertexCorners.rowStart;
  const std::vector<std::uint32_t>& incidentCorner = vertexCorners.corner;  // face << 2 | corner

  CornerNormals result;
  result.faceCorner = vectorOnHugePages<std::array<std::uint32_t, 4>>(faceCount, {0, 0, 0, 0});
  // Per vertex: the index of its one normal, or kPerCorner when its corners were given theirs.
  constexpr std::uint32_t kPerCorner = 0xFFFFFFFFu;
  std::vector<std::uint32_t> vertexNormal(vertexCount, kPerCorner);
  // Vertices in chunks, each with its own list of normals: chunk k's indices are local until the
  // lists are concatenated in chunk order, which gives the same list as one pass over all vertices.
  const ChunkPlan plan(vertexCount, kGrain);
  std::vector<std::vector<Vec3>> chunkNormals(plan.chunks);
  parallelChunks(plan, threads, [&](std::size_t chunk, std::size_t firstVertex, std::size_t endVertex) {
    std::vector<Vec3>& normals = chunkNormals[chunk];
    normals.reserve(endVertex - firstVertex);
    for (auto v = static_cast<std::uint32_t>(firstVertex); v < endVertex; ++v) {
      const VertexSum& at = vertexSum[v];
      if (at.faces == 0) continue;
      const bool walk = mustWalk(at);
      const std::uint32_t first = walk ? rowStart[v] : 0, end = walk ? rowStart[v + 1] : 0;
      auto faceOf = [&](std::uint32_t slot) { return incidentCorner[slot] >> 2; };
      auto weightOf = [&](std::uint32_t slot) {
        const std::uint32_t code = incidentCorner[slot];
        return cornerWeight[code >> 2][code & 3u];
      };
      auto everyPairSmooth = [&] {
        for (std::uint32_t a = first; a < end; ++a) {
          const std::uint32_t f = faceOf(a);
          for (std::uint32_t b = a + 1; b < end; ++b) {
            const std::uint32_t g = faceOf(b);
            // dot is symmetric to the bit, so this one test decides the pair for both corners.
            if (g != f && (facePhysicalTag[g] != facePhysicalTag[f] ||
                           dot(unitFaceNormal[f], unitFaceNormal[g]) < cosCrease))
              return false;
          }
        }
        return true;
      };
      // Smooth vertex: every corner gets the same sum, in the same order, as the loop below would
      // give it: one normal instead of one per corner.
      if (!walk || everyPairSmooth()) {
        const Vec3 normal = normalize(at.sum);
        if (dot(normal, normal) > 0.5f) {
          vertexNormal[v] = static_cast<std::uint32_t>(normals.size());
          normals.push_back(normal);
          continue;
        }
      }
      // Cancelling neighbours (a sum of zero) come here too, and walk the faces after all.
      const std::uint32_t walkFirst = rowStart[v], walkEnd = rowStart[v + 1];
      const std::size_t firstNormal = normals.size();
      for (std::uint32_t slot = walkFirst; slot < walkEnd; ++slot) {
        const std::uint32_t f = faceOf(slot);
        const Vec3 nf = unitFaceNormal[f];
        Vec3 sum{0, 0, 0};
        for (std::uint32_t other = walkFirst; other < walkEnd; ++other) {
          const std::uint32_t g = faceOf(other);
          if (g != f && (facePhysicalTag[g] != facePhysicalTag[f] || dot(nf, unitFaceNormal[g]) < cosCrease))
            continue;
          sum += unitFaceNormal[g] * weightOf(other);
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
        const std::uint32_t code = incidentCorner[slot];
        result.faceCorner[code >> 2][code & 3u] = index;
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
    for (std::size_t v = firstVertex; v < endVertex; ++v) {
      if (vertexNormal[v] != kPerCorner) {
        vertexNormal[v] += chunkBase[chunk];
        continue;
      }
      if (chunkBase[chunk] == 0 || vertexSum[v].faces == 0) continue;
      for (std::uint32_t slot = rowStart[v]; slot < rowStart[v + 1]; ++slot) {
        const std::uint32_t code = incidentCorner[slot];
        result.faceCorner[code >> 2][code & 3u] += chunkBase[chunk];
      }
    }
  });
  // The corners of smooth vertices, in face order.
  parallelFor(faceCount, threads, kGrain, [&](std::size_t f) {
    prefetchCorners(vertexNormal.data(), faces, f + kPrefetchFacesAhead);
    const MeshFace& face = faces[f];
    for (int c = 0; c < face.cornerCount(); ++c) {
      const std::uint32_t index = vertexNormal[face.vertex[c]];
      if (index != kPerCorner) result.faceCorner[f][c] = index;
    }
  });
  if (unitFaceNormals) *unitFaceNormals = std::move(unitFaceNormal);
  return result;
}

}  // namespace lancer
