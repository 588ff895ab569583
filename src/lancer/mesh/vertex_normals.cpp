#include "lancer/mesh/vertex_normals.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <numbers>
#include <utility>

#include "lancer/mesh/face_geometry.hpp"
#include "lancer/mesh/face_terms.hpp"
#include "lancer/mesh/prefetch_corners.hpp"
#include "lancer/mesh/vertex_corners.hpp"
#include "lancer/mesh/vertex_ranges.hpp"
#include "lancer/util/huge_page_array.hpp"
#include "lancer/util/huge_pages.hpp"
#include "lancer/util/parallel_for.hpp"

namespace lancer {

namespace {

// Items per chunk of the parallel loops: big enough that a chunk outweighs handing it out.
constexpr std::size_t kGrain = 16384;
// Faces whose corner angles are computed together when asked one by one, in order.
constexpr std::size_t kAngleBlock = 32;

// The two tests of the smoothing: the crease itself, and half of it with a margin.
struct SmoothingAngles {
  float cosCrease;
  // Half the crease angle less 1 mrad: two normals within it of a third are within the crease
  // angle of each other with a margin (2 mrad) thousands of times the error of a float dot product.
  // (Not for tiny crease angles, nor from 180 degrees on, where the cosine stops falling: there
  // every vertex takes the pairwise test.)
  float cosHalfCreaseWithMargin;
  explicit SmoothingAngles(float creaseAngleDegrees)
      : cosCrease(std::cos(creaseAngleDegrees * std::numbers::pi_v<float> / 180.0f)) {
    constexpr float kMarginRadians = 1e-3f;
    const float halfCrease = creaseAngleDegrees * std::numbers::pi_v<float> / 360.0f - kMarginRadians;
    cosHalfCreaseWithMargin =
        halfCrease <= 0.0f || creaseAngleDegrees >= 180.0f ? 2.0f : std::cos(halfCrease);
  }
};

// Each vertex's weighted sum of its faces' normals, added in face order (the order of a walk over
// the vertex's faces, so the same bits), and whether all its faces are of the first one's group
// and within half the crease angle of its normal: then every pair of them is within the crease
// angle and the vertex is smooth, its sum its one normal (the common case).
struct VertexSum {
  Vec3 sum{0, 0, 0};
  Vec3 firstNormal{0, 0, 0};
  std::int32_t firstTag = 0;
  std::uint8_t faces = 0;       // 0, 1, or 2 for more
  std::uint8_t withinHalf = 1;  // every face so far in the first one's group and half crease

  // The next face (in face order) at this vertex, of unit normal `normal`, weighing `weight` here.
  void add(const Vec3& normal, std::int32_t tag, float weight, float cosHalfCreaseWithMargin) {
    if (faces == 0) {
      firstNormal = normal;
      firstTag = tag;
      faces = 1;
    } else {
      faces = 2;
      withinHalf &=
          static_cast<std::uint8_t>(tag == firstTag && dot(firstNormal, normal) >= cosHalfCreaseWithMargin);
    }
    sum += normal * weight;
  }
};

// What updateCornerNormals sums per vertex (VertexSum's part for a vertex known to have been smooth):
// the weighted sum, how many faces, and the least cosine between a face's normal and the normal the
// vertex had.
struct SmoothVertexSum {
  Vec3 sum{0, 0, 0};
  float leastCosine = 1;
  std::uint32_t faces = 0;
};

// A vertex whose faces must be compared pair by pair, and one whose faces' normals cancel out:
// both walk their faces.
bool mustWalk(const VertexSum& at) { return at.faces == 2 && !at.withinHalf; }
bool cancels(const VertexSum& at) {
  const Vec3 normal = normalize(at.sum);
  return !(dot(normal, normal) > 0.5f);
}

// What the smoothing reads per face: unit normals, and the corners' weights, kept per face or
// (cornerWeight null) computed again from the positions where needed (the same bits).
struct FaceTerms {
  const Vec3* unitFaceNormal;
  const std::array<float, 4>* cornerWeight;
  std::span<const std::int32_t> facePhysicalTag;
  SmoothingAngles angles;
  std::span<const Vec3> positions;
  std::span<const MeshFace> faces;
  float weight(std::uint32_t face, int corner) const {
    if (cornerWeight) return cornerWeight[face][corner];
    Vec3 normal;
    std::array<float, 4> faceAngles;
    faceTermsOf(positions, faces.subspan(face, 1), &normal, &faceAngles);
    return faceAngles[corner];
  }
};

// visit(f) for each face, in order, with a corner among the vertices [firstVertex, endVertex) (the
// faces' vertex numbers less vertexBase), asking for the records `perVertex` holds of the faces a
// few ahead (prefetchCorners, with the base).
template <typename T, typename Visit>
void forFacesTouching(std::span<const MeshFace> faces, std::uint32_t vertexBase, std::size_t firstVertex,
                      std::size_t endVertex, const T* perVertex, Visit&& visit) {
  for (std::size_t f = 0; f < faces.size(); ++f) {
    if (f + kPrefetchFacesAhead < faces.size())
      for (int c = 0; c < 3; ++c)
        __builtin_prefetch(perVertex + (faces[f + kPrefetchFacesAhead].vertex[c] - vertexBase));
    const MeshFace& face = faces[f];
    bool touches = false;
    for (int c = 0; c < face.cornerCount(); ++c)
      touches =
          touches || (face.vertex[c] - vertexBase >= firstVertex && face.vertex[c] - vertexBase < endVertex);
    if (touches) visit(f);
  }
}

// The sums of the mesh's vertices. Shared out by vertex ranges (vertex_ranges.hpp): the faces are
// read in order, only the vertex records are written out of order, and no one walks a vertex's
// faces.
void sumVertexNormals(std::span<const MeshFace> faces, std::size_t vertexCount, const FaceTerms& terms,
                      int threads, std::vector<VertexSum>& vertexSum) {
  vertexSum = vectorOnHugePages<VertexSum>(vertexCount);
  forEachVertexRange(vertexCount, threads, [&](std::size_t firstVertex, std::size_t endVertex) {
    forFacesTouching(faces, 0, firstVertex, endVertex, vertexSum.data(), [&](std::size_t f) {
      const MeshFace& face = faces[f];
      const Vec3 normal = terms.unitFaceNormal[f];
      const std::int32_t tag = terms.facePhysicalTag[f];
      for (int c = 0; c < face.cornerCount(); ++c) {
        const std::uint32_t v = face.vertex[c];
        if (v < firstVertex || v >= endVertex) continue;
        vertexSum[v].add(normal, tag, terms.cornerWeight[f][c], terms.angles.cosHalfCreaseWithMargin);
      }
    });
  });
}

// Appends the normals of a vertex with faces to `normals`: one, its sum, when the vertex is smooth
// (returns true: every corner takes it), else one per set of corners smoothed together, each corner
// of `row` (its corners, face << 2 | corner; needed when it must walk or its faces cancel) told its
// normal's index by setCorner(slot in row, index) (returns false).
template <typename SetCorner>
bool appendVertexNormals(const VertexSum& at, std::span<const std::uint32_t> row, const FaceTerms& terms,
                         std::vector<Vec3>& normals, SetCorner&& setCorner) {
  auto faceOf = [&](std::uint32_t slot) { return row[slot] >> 2; };
  auto weightOf = [&](std::uint32_t slot) {
    return terms.weight(row[slot] >> 2, static_cast<int>(row[slot] & 3u));
  };
  const std::span<const std::int32_t> tags = terms.facePhysicalTag;
  const Vec3* unitFaceNormal = terms.unitFaceNormal;
  const float cosCrease = terms.angles.cosCrease;
  const bool walk = mustWalk(at);
  const auto end = static_cast<std::uint32_t>(row.size());
  auto everyPairSmooth = [&] {
    for (std::uint32_t a = 0; a < end; ++a) {
      const std::uint32_t f = faceOf(a);
      for (std::uint32_t b = a + 1; b < end; ++b) {
        const std::uint32_t g = faceOf(b);
        // dot is symmetric to the bit, so this one test decides the pair for both corners.
        if (g != f && (tags[g] != tags[f] || dot(unitFaceNormal[f], unitFaceNormal[g]) < cosCrease))
          return false;
      }
    }
    return true;
  };
  // Smooth vertex: every corner gets the same sum, in the same order, as the loop below would give
  // it: one normal instead of one per corner.
  if (!walk || everyPairSmooth()) {
    const Vec3 normal = normalize(at.sum);
    if (dot(normal, normal) > 0.5f) {
      normals.push_back(normal);
      return true;
    }
  }
  // Cancelling neighbours (a sum of zero) come here too, and walk the faces after all.
  const std::size_t firstNormal = normals.size();
  for (std::uint32_t slot = 0; slot < end; ++slot) {
    const std::uint32_t f = faceOf(slot);
    const Vec3 nf = unitFaceNormal[f];
    Vec3 sum{0, 0, 0};
    for (std::uint32_t other = 0; other < end; ++other) {
      const std::uint32_t g = faceOf(other);
      if (g != f && (tags[g] != tags[f] || dot(nf, unitFaceNormal[g]) < cosCrease)) continue;
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
    setCorner(slot, index);
  }
  return false;
}

}  // namespace

struct CornerNormalsScratch::Sums {
  std::vector<SmoothVertexSum> vertexSum;
};
CornerNormalsScratch::CornerNormalsScratch() : sums(std::make_unique<Sums>()) {}
CornerNormalsScratch::~CornerNormalsScratch() = default;
CornerNormalsScratch::CornerNormalsScratch(CornerNormalsScratch&&) noexcept = default;
CornerNormalsScratch& CornerNormalsScratch::operator=(CornerNormalsScratch&&) noexcept = default;
void CornerNormalsScratch::release() {
  if (sums) std::vector<SmoothVertexSum>().swap(sums->vertexSum);
}

CornerNormals computeCornerNormals(std::span<const Vec3> positions, std::span<const MeshFace> faces,
                                   std::span<const std::int32_t> facePhysicalTag, float creaseAngleDegrees,
                                   int threads, std::vector<Vec3>* unitFaceNormals,
                                   CornerNormalWalks* walked) {
  const std::size_t faceCount = faces.size();
  const std::size_t vertexCount = positions.size();
  // Per face, in face order (sequential reads, shared out by chunks of faces): its unit normal and
  // the weights of its corners.
  std::vector<Vec3> unitFaceNormal = vectorOnHugePages<Vec3>(faceCount);
  HugePageArray<std::array<float, 4>> cornerWeight(faceCount);  // written whole by the loop below
  parallelChunks(ChunkPlan(faceCount, kGrain), threads, [&](std::size_t, std::size_t begin, std::size_t end) {
    faceTermsOf(positions, faces.subspan(begin, end - begin), unitFaceNormal.data() + begin,
                cornerWeight.data() + begin);
  });
  const FaceTerms terms{unitFaceNormal.data(),
                        cornerWeight.data(),
                        facePhysicalTag,
                        SmoothingAngles(creaseAngleDegrees),
                        positions,
                        faces};
  std::vector<VertexSum> vertexSum;
  sumVertexNormals(faces, vertexCount, terms, threads, vertexSum);

  // The other vertices walk their faces (face order): the pairwise test, and where it fails, one
  // sum per corner over the faces smoothed with its own; so do vertices whose faces cancel out.
  std::vector<std::uint8_t> walks(vertexCount, 0);
  parallelFor(vertexCount, threads, kGrain, [&](std::size_t v) {
    const VertexSum& at = vertexSum[v];
    walks[v] = at.faces != 0 && (mustWalk(at) || cancels(at));
  });
  VertexCorners vertexCorners;
  if (std::find(walks.begin(), walks.end(), 1) != walks.end())
    vertexCorners = findVertexCorners(faces, vertexCount, threads, walks);  // rows of those only
  const std::vector<std::uint32_t>& rowStart = vertexCorners.rowStart;
  auto rowOf = [&](std::size_t v) {
    return rowStart.empty() ? std::span<const std::uint32_t>{}
                            : std::span<const std::uint32_t>(vertexCorners.corner)
                                  .subspan(rowStart[v], rowStart[v + 1] - rowStart[v]);
  };

  // The walked vertices' corners' normals, in step with vertexCorners.corner (chunk-local indices
  // until the lists are concatenated): the faces' corners are allocated only once the sums and
  // weights are given back.
  std::vector<std::uint32_t> cornerNormal(vertexCorners.corner.size());
  // Per vertex: the index of its one normal, or kPerCorner when its corners were given theirs.
  constexpr std::uint32_t kPerCorner = 0xFFFFFFFFu;
  std::vector<std::uint32_t> vertexNormal(vertexCount, kPerCorner);
  // Vertices in chunks, each with its own list of normals: chunk k's indices are local until the
  // lists are concatenated in chunk order, which gives the same list as one pass over all vertices.
  const ChunkPlan plan(vertexCount, kGrain);
  std::vector<std::vector<Vec3>> chunkNormals(plan.chunks);
  parallelChunks(plan, threads, [&](std::size_t chunk, std::size_t firstVertex, std::size_t endVertex) {
    // Room for the most a chunk can append (one normal per vertex, one per corner of a walked
    // vertex): a list that outgrew a guess would hold its old and new capacity at once.
    std::size_t most = 0;
    for (std::size_t v = firstVertex; v < endVertex; ++v) most += walks[v] ? rowOf(v).size() : 1;
    std::vector<Vec3>& normals = chunkNormals[chunk];
    normals.reserve(most);
    for (auto v = static_cast<std::uint32_t>(firstVertex); v < endVertex; ++v) {
      if (vertexSum[v].faces == 0) continue;
      const bool one = appendVertexNormals(
          vertexSum[v], walks[v] ? rowOf(v) : std::span<const std::uint32_t>{}, terms, normals,
          [&](std::uint32_t slot, std::uint32_t index) { cornerNormal[rowStart[v] + slot] = index; });
      if (one) vertexNormal[v] = static_cast<std::uint32_t>(normals.size() - 1);
    }
  });
  // The sums and weights are done with: given back before the faces' corners and the whole list are
  // allocated, which then take their pages (util/huge_page_blocks.hpp) instead of adding to the peak.
  std::vector<VertexSum>().swap(vertexSum);
  cornerWeight.reset();
  CornerNormals result;
  result.faceCorner = vectorOnHugePages<std::array<std::uint32_t, 4>>(faceCount, {0, 0, 0, 0});
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
      if (!walks[v]) continue;
      const std::span<const std::uint32_t> row = rowOf(v);
      for (std::size_t slot = 0; slot < row.size(); ++slot)
        result.faceCorner[row[slot] >> 2][row[slot] & 3u] =
            cornerNormal[rowStart[v] + slot] + chunkBase[chunk];
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
  if (walked) {  // the walked vertices' rows, packed
    *walked = CornerNormalWalks{};
    walked->rowStart.push_back(0);
    for (std::size_t v = 0; v < vertexCount; ++v) {
      if (!walks[v]) continue;
      const std::span<const std::uint32_t> row = rowOf(v);
      walked->vertex.push_back(static_cast<std::uint32_t>(v));
      walked->corner.insert(walked->corner.end(), row.begin(), row.end());
      walked->rowStart.push_back(static_cast<std::uint32_t>(walked->corner.size()));
    }
  }
  if (unitFaceNormals) *unitFaceNormals = std::move(unitFaceNormal);
  return result;
}

NormalsUpdate updateCornerNormals(std::span<const Vec3> positions, const CornerNormalsSpan& mesh,
                                  std::span<const std::int32_t> facePhysicalTag, float creaseAngleDegrees,
                                  const CornerNormalWalks& walks, int threads, std::span<Vec3> normals,
                                  std::span<const std::array<std::uint32_t, 4>> faceCorner,
                                  std::span<Vec3> unitFaceNormals, CornerNormalsScratch* scratch) {
  const std::span<const MeshFace> faces = mesh.faces;
  const std::size_t faceCount = faces.size();
  const std::size_t vertexCount = mesh.vertexCount;
  // One pass: each vertex range sums the faces that touch it, computing their normals and weights
  // (again, for a face across two ranges); the range of a face's first vertex writes its normal.
  // A vertex computeCornerNormals found smooth stays so while its faces stay within half the crease
  // angle of the one normal it had (then every two are within the crease angle, and the pairwise
  // test would pass), so its faces need not be compared with its first face's: what is summed is
  // the sum, in face order as there, and the least cosine to that normal.
  std::atomic<bool> ok{true};
  const FaceTerms terms{unitFaceNormals.data(),
                        nullptr,
                        facePhysicalTag,
                        SmoothingAngles(creaseAngleDegrees),
                        positions,
                        faces};
  std::vector<SmoothVertexSum> ownSums;
  if (scratch && !scratch->sums) scratch->sums = std::make_unique<CornerNormalsScratch::Sums>();
  std::vector<SmoothVertexSum>& vertexSum = scratch ? scratch->sums->vertexSum : ownSums;
  if (vertexSum.capacity() < vertexCount) {
    vertexSum = vectorOnHugePages<SmoothVertexSum>(vertexCount);
  } else {
    vertexSum.assign(vertexCount, SmoothVertexSum{});
  }
  const std::uint32_t vertexBase = mesh.vertexBase;
  forEachVertexRange(vertexCount, threads, [&](std::size_t firstVertex, std::size_t endVertex) {
    // The terms of the block of faces from the one asked, computed together.
    std::array<std::array<float, 4>, kAngleBlock> blockAngles{};
    std::array<Vec3, kAngleBlock> blockNormals{};
    std::size_t blockFirst = faceCount;
    forFacesTouching(faces, vertexBase, firstVertex, endVertex, vertexSum.data(), [&](std::size_t f) {
      const MeshFace& face = faces[f];
      if (f < blockFirst || f >= blockFirst + kAngleBlock) {
        blockFirst = f;
        // A degenerate face has no normal: the step's scene is built again, without it.
        if (!faceTermsOf(positions, faces.subspan(f, std::min(kAngleBlock, faceCount - f)),
                         blockNormals.data(), blockAngles.data()))
          ok = false;
      }
      const Vec3 normal = blockNormals[f - blockFirst];
      const std::array<float, 4>& weight = blockAngles[f - blockFirst];
      const std::uint32_t owner = face.vertex[0] - vertexBase;
      if (owner >= firstVertex && owner < endVertex) unitFaceNormals[f] = normal;
      for (int c = 0; c < face.cornerCount(); ++c) {
        const std::uint32_t v = face.vertex[c] - vertexBase;
        if (v < firstVertex || v >= endVertex) continue;
        SmoothVertexSum& at = vertexSum[v];
        at.leastCosine = std::min(at.leastCosine, dot(normals[faceCorner[f][c] - mesh.normalBase], normal));
        ++at.faces;
        at.sum += normal * weight[c];
      }
    });
  });
  if (!ok) return NormalsUpdate::FaceDegenerate;
  // A walked vertex's sum as computeCornerNormals's pass makes it, from its corners (face order).
  auto walkedSum = [&](std::span<const std::uint32_t> row) {
    VertexSum at;
    for (const std::uint32_t code : row) {
      const std::uint32_t f = code >> 2;
      at.add(unitFaceNormals[f], facePhysicalTag[f], terms.weight(f, static_cast<int>(code & 3u)),
             terms.angles.cosHalfCreaseWithMargin);
    }
    return at;
  };
  // Still smooth: one face, or every face within half the crease angle (less the margin), and a sum
  // that does not cancel.
  auto stillSmooth = [&](const SmoothVertexSum& at) {
    const Vec3 n = normalize(at.sum);
    return (at.faces == 1 || at.leastCosine >= terms.angles.cosHalfCreaseWithMargin) && dot(n, n) > 0.5f;
  };
  // The normals lie in vertex order (computeCornerNormals's chunks, concatenated): none for a
  // vertex without faces, one for a smooth vertex, and for a walked one as many as its corners'
  // indices span. Each chunk of vertices counts its own first, then writes from its offset.
  auto rowOf = [&](std::size_t k) {
    return std::span<const std::uint32_t>(walks.corner)
        .subspan(walks.rowStart[k], walks.rowStart[k + 1] - walks.rowStart[k]);
  };
  auto firstWalked = [&](std::size_t vertex) {
    return static_cast<std::size_t>(std::lower_bound(walks.vertex.begin(), walks.vertex.end(), vertex) -
                                    walks.vertex.begin());
  };
  // The span of indices a walked vertex's corners hold (local to the mesh's normals).
  auto heldIndices = [&](std::span<const std::uint32_t> row) {
    std::uint32_t low = 0xFFFFFFFFu, high = 0;
    for (const std::uint32_t code : row) {
      const std::uint32_t index = faceCorner[code >> 2][code & 3u] - mesh.normalBase;
      low = std::min(low, index);
      high = std::max(high, index);
    }
    return std::pair{low, high};
  };
  const ChunkPlan plan(vertexCount, kGrain);
  std::vector<std::uint32_t> chunkBase(plan.chunks + 1, 0);
  parallelChunks(plan, threads, [&](std::size_t chunk, std::size_t firstVertex, std::size_t endVertex) {
    std::uint32_t count = 0;
    std::size_t k = firstWalked(firstVertex);
    for (std::size_t v = firstVertex; v < endVertex; ++v) {
      const SmoothVertexSum& at = vertexSum[v];
      if (k < walks.vertex.size() && walks.vertex[k] == v) {
        const auto [low, high] = heldIndices(rowOf(k++));
        count += high - low + 1;
      } else if (at.faces != 0) {
        if (!stillSmooth(at)) ok = false;  // its smoothing may have changed: a crease appeared
        ++count;
      }
    }
    chunkBase[chunk + 1] = count;
  });
  if (!ok) return NormalsUpdate::SmoothingChanged;
  for (std::size_t k = 0; k < plan.chunks; ++k) chunkBase[k + 1] += chunkBase[k];
  if (chunkBase[plan.chunks] != normals.size()) return NormalsUpdate::SmoothingChanged;

  parallelChunks(plan, threads, [&](std::size_t chunk, std::size_t firstVertex, std::size_t endVertex) {
    std::uint32_t next = chunkBase[chunk];
    std::size_t k = firstWalked(firstVertex);
    std::vector<Vec3> own;  // a walked vertex's normals
    for (std::size_t v = firstVertex; v < endVertex; ++v) {
      const SmoothVertexSum& at = vertexSum[v];
      if (k < walks.vertex.size() && walks.vertex[k] == v) {
        const std::span<const std::uint32_t> row = rowOf(k++);
        const auto [low, high] = heldIndices(row);
        own.clear();
        bool same = low == next;
        appendVertexNormals(walkedSum(row), row, terms, own, [&](std::uint32_t slot, std::uint32_t index) {
          const std::uint32_t code = row[slot];
          same = same && faceCorner[code >> 2][code & 3u] - mesh.normalBase == next + index;
        });
        if (!same || own.size() != high - low + 1) {  // (one normal: own.size() is 1)
          ok = false;
          return;
        }
        std::copy(own.begin(), own.end(), normals.begin() + next);
        next += static_cast<std::uint32_t>(own.size());
      } else if (at.faces != 0) {
        normals[next++] = normalize(at.sum);
      }
    }
  });

  return ok ? NormalsUpdate::Updated : NormalsUpdate::SmoothingChanged;
}

}  // namespace lancer
