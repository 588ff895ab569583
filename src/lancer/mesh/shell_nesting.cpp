#include "lancer/mesh/shell_nesting.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace lancer {
namespace {

// Directions that are not axis-aligned and not along a box diagonal, so a ray from a vertex of a
// structured mesh rarely runs along an edge or through a vertex; each later one is a retry.
constexpr std::array<Vec3d, 6> kRayDirections = {{{0.5773, 0.6123, 0.5403},
                                                  {-0.4132, 0.7071, -0.5739},
                                                  {0.8017, -0.2672, 0.5345},
                                                  {-0.6247, -0.5164, 0.5855},
                                                  {0.1951, -0.8315, -0.5199},
                                                  {0.7419, 0.3310, -0.5831}}};
constexpr double kBarycentricMargin = 1e-9;  // closer to an edge than this (relative): ambiguous
constexpr double kParallelMargin = 1e-12;    // |cos| between ray and face plane below this: ambiguous
constexpr int kVerticesTried = 4;

enum class Crossings { kEven, kOdd, kAmbiguousRay, kOnSurface };

// Parity of a ray's crossings with the triangles of one shell (quads fanned from corner 0).
// Möller–Trumbore (J. Graphics Tools 2(1), 1997) in double.
Crossings countCrossings(std::span<const Vec3> positions, const std::vector<MeshFace>& faces,
                         std::span<const std::uint32_t> shellFaces, const Vec3d& origin,
                         const Vec3d& direction, double distanceEpsilon) {
  bool odd = false;
  for (const std::uint32_t f : shellFaces) {
    const MeshFace& face = faces[f];
    const Vec3d a = toDouble(positions[face.vertex[0]]);
    for (int c = 1; c + 1 < face.cornerCount(); ++c) {
      const Vec3d e1 = toDouble(positions[face.vertex[c]]) - a;
      const Vec3d e2 = toDouble(positions[face.vertex[c + 1]]) - a;
      const Vec3d p = cross(direction, e2);
      const double det = dot(e1, p);
      const Vec3d s = origin - a;
      const Vec3d q = cross(s, e1);
      const double areaScale = length(cross(e1, e2));
      if (std::abs(det) <= kParallelMargin * areaScale) {
        // The ray runs in the triangle's plane: ambiguous only when that plane passes the origin.
        if (std::abs(dot(s, cross(e1, e2))) <= distanceEpsilon * areaScale) return Crossings::kAmbiguousRay;
        continue;
      }
      const double u = dot(s, p) / det;
      const double v = dot(direction, q) / det;
      const double t = dot(e2, q) / det;
      if (u < -kBarycentricMargin || v < -kBarycentricMargin || u + v > 1 + kBarycentricMargin) continue;
      if (std::abs(t) <= distanceEpsilon) return Crossings::kOnSurface;
      if (t < 0) continue;
      if (u < kBarycentricMargin || v < kBarycentricMargin || u + v > 1 - kBarycentricMargin)
        return Crossings::kAmbiguousRay;
      odd = !odd;
    }
  }
  return odd ? Crossings::kOdd : Crossings::kEven;
}

// Whether shell `inner` lies inside closed shell `outer` (they are disjoint, so one vertex decides).
bool shellInside(std::span<const Vec3> positions, const std::vector<MeshFace>& faces,
                 std::span<const std::uint32_t> innerFaces, std::span<const std::uint32_t> outerFaces,
                 const Aabbd& outerBox) {
  const double distanceEpsilon = 1e-9 * length(outerBox.extent());
  const std::size_t vertexCount = std::min<std::size_t>(innerFaces.size(), kVerticesTried);
  for (std::size_t i = 0; i < vertexCount; ++i) {
    const Vec3d origin = toDouble(positions[faces[innerFaces[i]].vertex[0]]);
    for (const Vec3d& direction : kRayDirections) {
      const Crossings crossings =
          countCrossings(positions, faces, outerFaces, origin, direction, distanceEpsilon);
      if (crossings == Crossings::kOnSurface) break;  // this vertex touches `outer`: try the next one
      if (crossings != Crossings::kAmbiguousRay) return crossings == Crossings::kOdd;
    }
  }
  return false;  // every vertex tried touches `outer` or grazes its edges: call it outside
}

bool strictlyContains(const Aabbd& outer, const Aabbd& inner) {
  return outer.lower.x < inner.lower.x && outer.lower.y < inner.lower.y && outer.lower.z < inner.lower.z &&
         inner.upper.x < outer.upper.x && inner.upper.y < outer.upper.y && inner.upper.z < outer.upper.z;
}

bool shareTag(std::span<const std::int32_t> a, std::span<const std::int32_t> b) {
  return std::find_first_of(a.begin(), a.end(), b.begin(), b.end()) != a.end();
}

}  // namespace

std::vector<std::uint8_t> findCavityShells(std::span<const Vec3> positions,
                                           const std::vector<MeshFace>& faces, const FaceShells& shells,
                                           std::span<const std::int32_t> facePhysicalTag,
                                           std::span<const std::uint8_t> candidates) {
  return findShellNesting(positions, faces, shells, facePhysicalTag, candidates, false).cavity;
}

ShellNesting findShellNesting(std::span<const Vec3> positions, const std::vector<MeshFace>& faces,
                              const FaceShells& shells, std::span<const std::int32_t> facePhysicalTag,
                              std::span<const std::uint8_t> candidates, bool withEnclosing) {
  const std::size_t shellCount = shells.shellCount();
  ShellNesting nesting;
  nesting.cavity.assign(shellCount, 0);
  if (withEnclosing) nesting.enclosing.assign(shellCount, kNoShell);
  std::vector<std::uint8_t>& cavity = nesting.cavity;
  std::vector<std::uint32_t> candidateShells;
  for (std::size_t s = 0; s < shellCount; ++s)
    if (candidates[s]) candidateShells.push_back(static_cast<std::uint32_t>(s));
  if (candidateShells.size() < 2) return nesting;

  // Faces grouped by shell (first[s] .. first[s + 1] in shellFaces), each shell's box and tags.
  std::vector<std::uint32_t> first(shellCount + 1, 0);
  for (const std::uint32_t s : shells.shellOfFace) ++first[s + 1];
  for (std::size_t s = 0; s < shellCount; ++s) first[s + 1] += first[s];
  std::vector<std::uint32_t> shellFaces(faces.size());
  std::vector<std::uint32_t> fill(first.begin(), first.end() - 1);
  std::vector<Aabbd> box(shellCount);
  for (std::size_t f = 0; f < faces.size(); ++f) {
    const std::uint32_t s = shells.shellOfFace[f];
    shellFaces[fill[s]++] = static_cast<std::uint32_t>(f);
    for (int c = 0; c < faces[f].cornerCount(); ++c) box[s].extend(toDouble(positions[faces[f].vertex[c]]));
  }
  auto facesOf = [&](std::uint32_t s) {
    return std::span<const std::uint32_t>(shellFaces).subspan(first[s], first[s + 1] - first[s]);
  };
  // A shell's faces usually carry one physical tag; two shells are in one group when they share one.
  std::vector<std::vector<std::int32_t>> tags(shellCount);
  for (const std::uint32_t s : candidateShells) {
    std::vector<std::int32_t>& shellTags = tags[s];
    if (facePhysicalTag.empty()) {
      shellTags.push_back(0);
      continue;
    }
    for (const std::uint32_t f : facesOf(s)) shellTags.push_back(facePhysicalTag[f]);
    std::sort(shellTags.begin(), shellTags.end());
    shellTags.erase(std::unique(shellTags.begin(), shellTags.end()), shellTags.end());
  }

  // Sweep along x: a shell can only be inside shells that start before it in x and have not ended
  // by its start, so each shell is tested against that active set, not against all k shells (a
  // packing of 100K separate particles would otherwise take 10^10 box tests).
  std::sort(candidateShells.begin(), candidateShells.end(),
            [&](std::uint32_t a, std::uint32_t b) { return box[a].lower.x < box[b].lower.x; });
  std::vector<std::uint32_t> active;
  for (const std::uint32_t inner : candidateShells) {
    const double start = box[inner].lower.x;
    std::erase_if(active, [&](std::uint32_t outer) { return box[outer].upper.x <= start; });
    bool odd = false;
    double innermostSize = 0;
    for (const std::uint32_t outer : active) {
      if (!strictlyContains(box[outer], box[inner])) continue;
      const bool sameGroup = shareTag(tags[outer], tags[inner]);
      if (!sameGroup && !withEnclosing) continue;
      if (!shellInside(positions, faces, facesOf(inner), facesOf(outer), box[outer])) continue;
      if (sameGroup) odd = !odd;
      // Of the shells around it, the innermost has the smallest box (nested boxes nest).
      const double size = length(box[outer].extent());
      if (withEnclosing && (nesting.enclosing[inner] == kNoShell || size < innermostSize)) {
        nesting.enclosing[inner] = outer;
        innermostSize = size;
      }
    }
    cavity[inner] = odd ? 1 : 0;
    active.push_back(inner);
  }
  return nesting;
}

}  // namespace lancer
