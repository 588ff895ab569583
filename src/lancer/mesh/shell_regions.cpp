#include "lancer/mesh/shell_regions.hpp"

#include <algorithm>
#include <cmath>

#include "lancer/mesh/disjoint_sets.hpp"
#include "lancer/mesh/face_geometry.hpp"

namespace lancer {
namespace {

Vec3d cornerOf(std::span<const Vec3> positions, const MeshFace& face, int c) {
  return toDouble(positions[face.vertex[c]]);
}

}  // namespace

ShellRegions findShellRegions(std::span<const Vec3> positions, const std::vector<MeshFace>& faces,
                              const FaceShells& shells) {
  ShellRegions result;
  const HugePageArray<FaceEdge>& edges = shells.edges;
  // Shells with an edge of three or more faces and none of one.
  std::vector<std::uint8_t> candidate(shells.shellCount(), 0);
  bool any = false;
  for (std::size_t s = 0; s < shells.shellCount(); ++s)
    any |= (candidate[s] = shells.branched[s] && !shells.bordered[s]) != 0;
  if (!any) return result;

  // Around each edge, the wedge between neighbouring faces joins the sides that face into it.
  // Face sides: side 2f is in front of face f (its normal's side), 2f + 1 behind it.
  DisjointSets sides(2 * faces.size());
  std::vector<std::uint8_t> rejected(shells.shellCount(), 0);
  struct Wing {
    std::uint32_t face;
    double angle;
    bool frontFacesForward;  // the face's front looks towards increasing angle
  };
  std::vector<Wing> wings;
  // The edges of smaller vertex lo, one bucket of the table, grouped by larger vertex.
  std::uint32_t lo = 0;
  for (std::size_t i = 0; i < edges.size();) {
    while (shells.edgeStart[lo + 1] <= i) ++lo;
    const std::size_t bucketEnd = shells.edgeStart[lo + 1];
    std::size_t j = i + 1;
    while (j < bucketEnd && edges[j].larger == edges[i].larger) ++j;
    const std::uint32_t shell = shells.shellOfFace[edges[i].face()];
    if (!candidate[shell] || rejected[shell]) {
      i = j;
      continue;
    }
    const std::uint32_t hi = edges[i].larger;
    const Vec3d origin = toDouble(positions[lo]);
    const Vec3d axis = normalize(toDouble(positions[hi]) - origin);
    wings.clear();
    Vec3d u{}, v{};
    for (std::size_t k = i; k < j; ++k) {
      const MeshFace& face = faces[edges[k].face()];
      // The face leaves the edge towards the mean of its other corners, seen across the axis.
      Vec3d away{0, 0, 0};
      int others = 0;
      for (int c = 0; c < face.cornerCount(); ++c)
        if (face.vertex[c] != lo && face.vertex[c] != hi)
          away += cornerOf(positions, face, c) - origin, ++others;
      away = away * (1.0 / std::max(others, 1));
      away = away - axis * dot(away, axis);
      if (k == i) {
        u = normalize(away);
        v = cross(axis, u);
      }
      const double angle = std::atan2(dot(away, v), dot(away, u));
      const Vec3d forward = cross(axis, away);  // the direction of increasing angle, at the face
      wings.push_back({edges[k].face(), angle, dot(twiceVectorArea(positions, face), forward) > 0});
    }
    std::sort(wings.begin(), wings.end(), [](const Wing& a, const Wing& b) { return a.angle < b.angle; });
    for (std::size_t k = 0; k + 1 < wings.size(); ++k)
      if (!(wings[k + 1].angle - wings[k].angle > 1e-9)) rejected[shell] = 1;  // two faces on one side
    for (std::size_t k = 0; k < wings.size() && !rejected[shell]; ++k) {
      const Wing& from = wings[k];
      const Wing& to = wings[(k + 1) % wings.size()];
      const std::uint32_t fromSide = 2 * from.face + (from.frontFacesForward ? 0 : 1);
      const std::uint32_t toSide = 2 * to.face + (to.frontFacesForward ? 1 : 0);
      sides.unite(fromSide, toSide);
    }
    i = j;
  }

  // Regions and their volumes: a region behind a face gets its cone, one in front the opposite.
  std::vector<std::uint32_t> regionOfRoot(2 * faces.size(), kNoRegion);
  std::vector<double> volume;
  std::vector<std::uint32_t> regionShell;
  result.front.assign(faces.size(), kNoRegion);
  result.back.assign(faces.size(), kNoRegion);
  for (std::size_t f = 0; f < faces.size(); ++f) {
    const std::uint32_t shell = shells.shellOfFace[f];
    if (!candidate[shell] || rejected[shell]) continue;
    for (int side = 0; side < 2; ++side) {
      const std::uint32_t root = sides.find(static_cast<std::uint32_t>(2 * f + side));
      if (regionOfRoot[root] == kNoRegion) {
        regionOfRoot[root] = static_cast<std::uint32_t>(volume.size());
        volume.push_back(0);
        regionShell.push_back(shell);
      }
      const std::uint32_t region = regionOfRoot[root];
      (side == 0 ? result.front : result.back)[f] = region;
      volume[region] += (side == 0 ? -1.0 : 1.0) * sixfoldConeVolume(positions, faces[f]);
    }
    if (result.front[f] == result.back[f]) rejected[shell] = 1;  // a region on both sides: a leak
  }
  // A shell's regions must be one outside (negative volume) and bounded cells (positive).
  std::vector<int> outsides(shells.shellCount(), 0);
  result.bounded.assign(volume.size(), 0);
  for (std::size_t r = 0; r < volume.size(); ++r) {
    if (volume[r] > 0)
      result.bounded[r] = 1;
    else
      ++outsides[regionShell[r]];
  }
  for (std::size_t s = 0; s < shells.shellCount(); ++s)
    if (candidate[s] && outsides[s] != 1) rejected[s] = 1;
  for (std::size_t f = 0; f < faces.size(); ++f) {
    if (result.front[f] != kNoRegion && rejected[shells.shellOfFace[f]])
      result.front[f] = result.back[f] = kNoRegion;
  }
  return result;
}

}  // namespace lancer
