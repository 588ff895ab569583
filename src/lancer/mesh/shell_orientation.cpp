#include "lancer/mesh/shell_orientation.hpp"

#include <algorithm>
#include <map>

#include "lancer/mesh/face_geometry.hpp"
#include "lancer/mesh/face_shells.hpp"
#include "lancer/mesh/shell_nesting.hpp"
#include "lancer/mesh/shell_regions.hpp"
#include "lancer/util/parallel_for.hpp"

namespace lancer {
namespace {

// Surfaces only, meeting three or more on edges (shell_regions.hpp): each face is turned to face
// out of a bounded region behind it and bounds a solid; a face between two regions becomes an
// interface whose sides take their regions' groups (the group most of a region's outer faces
// carry, or of all its faces when none is outer).
void orientShellRegions(std::span<const Vec3> positions, std::vector<MeshFace>& faces,
                        std::vector<std::uint8_t>& edgeMasks, std::span<const std::int32_t> facePhysicalTag,
                        const FaceShells& shells, ShellOrientationReport& report) {
  const ShellRegions regions = findShellRegions(positions, faces, shells);
  if (regions.empty()) return;
  const std::size_t faceCount = faces.size();
  std::vector<std::int32_t> regionTag(regions.bounded.size(), 0);
  if (!facePhysicalTag.empty()) {
    // Votes per region: outer faces first; a region with none counts all its faces.
    std::vector<std::map<std::int32_t, std::uint64_t>> outerVotes(regions.bounded.size()),
        allVotes(regions.bounded.size());
    for (std::size_t f = 0; f < faceCount; ++f) {
      if (regions.front[f] == kNoRegion) continue;
      for (const std::uint32_t region : {regions.front[f], regions.back[f]}) {
        if (!regions.bounded[region]) continue;
        ++allVotes[region][facePhysicalTag[f]];
        const std::uint32_t other = region == regions.front[f] ? regions.back[f] : regions.front[f];
        if (!regions.bounded[other]) ++outerVotes[region][facePhysicalTag[f]];
      }
    }
    for (std::size_t r = 0; r < regionTag.size(); ++r) {
      const auto& votes = outerVotes[r].empty() ? allVotes[r] : outerVotes[r];
      std::uint64_t best = 0;
      for (const auto& [tag, count] : votes)
        if (count > best) best = count, regionTag[r] = tag;
    }
  }
  std::uint8_t unusedMask = kAllEdges;
  for (std::size_t f = 0; f < faceCount; ++f) {
    if (regions.front[f] == kNoRegion) continue;
    report.faceBoundsSolid[f] = 1;
    const std::uint32_t front = regions.front[f], back = regions.back[f];
    if (!regions.bounded[back]) {  // the bounded region is in front: turn the face out of it
      reverseWinding(faces[f], edgeMasks.empty() ? unusedMask : edgeMasks[f]);
      ++report.flippedFaces;
      continue;
    }
    if (!regions.bounded[front] || facePhysicalTag.empty()) continue;
    // Between two regions: behind it the back region's group, in front the front region's.
    report.faceRegionTags.push_back({static_cast<std::uint32_t>(f), regionTag[back]});
    if (report.faceEnclosedBy.empty())
      report.faceEnclosedBy.assign(faceCount, ShellOrientationReport::kNotEnclosed);
    report.faceEnclosedBy[f] = regionTag[front];
  }
}

// What shellsKeepOrientation needs of the shells just oriented.
void keepOrientedShells(const FaceShells& shells, const std::vector<std::uint8_t>& solidShell,
                        const std::vector<std::uint8_t>& cavity, bool regionsPossible,
                        OrientedShells& oriented) {
  oriented = OrientedShells{};
  oriented.kept = !(regionsPossible &&
                    std::find(shells.branched.begin(), shells.branched.end(), 1) != shells.branched.end());
  if (!oriented.kept) return;
  std::vector<std::uint32_t> number(shells.shellCount(), OrientedShells::kNotSolid);
  for (std::size_t s = 0; s < shells.shellCount(); ++s) {
    if (!solidShell[s]) continue;
    number[s] = static_cast<std::uint32_t>(oriented.cavity.size());
    oriented.cavity.push_back(cavity[s]);
  }
  const std::size_t faceCount = shells.shellOfFace.size();
  // Runs while they stay few (a shell's faces mostly follow each other), else face by face.
  const std::size_t maxRuns = faceCount / 16 + 64;
  for (std::size_t f = 0; f < faceCount && oriented.runs.size() <= maxRuns; ++f) {
    const std::uint32_t shell = number[shells.shellOfFace[f]];
    if (oriented.runs.empty() || oriented.runs.back().shell != shell)
      oriented.runs.push_back({static_cast<std::uint32_t>(f), shell});
  }
  if (oriented.runs.size() <= maxRuns) return;
  std::vector<OrientedShells::Run>().swap(oriented.runs);
  if (oriented.cavity.size() >= OrientedShells::kNotSolidFace) {
    oriented.kept = false;
    return;
  }
  oriented.faceShell.resize(faceCount);
  for (std::size_t f = 0; f < faceCount; ++f) {
    const std::uint32_t shell = number[shells.shellOfFace[f]];
    oriented.faceShell[f] = shell == OrientedShells::kNotSolid ? OrientedShells::kNotSolidFace
                                                               : static_cast<std::uint16_t>(shell);
  }
}

}  // namespace

ShellOrientationReport orientClosedShellsOutward(std::span<const Vec3> positions,
                                                 std::vector<MeshFace>& faces,
                                                 std::vector<std::uint8_t>& edgeMasks,
                                                 std::span<const std::int32_t> facePhysicalTag,
                                                 std::span<const FaceSide> faceSide, int threads,
                                                 OrientedShells* oriented) {
  ShellOrientationReport report;
  const std::size_t faceCount = faces.size();
  report.faceBoundsSolid.assign(faceCount, 0);
  if (faceCount == 0) return report;
  const FaceShells shells = findFaceShells(faces, threads);
  report.shells = shells.shellCount();

  // flip[f]: whether face f must be reversed to agree with its shell's first face (findFaceShells
  // propagates that across the shared edges); the signed volume of each closed shell so turned.
  const std::vector<std::uint8_t>& flip = shells.flip;
  const std::vector<std::uint8_t>& orientable = shells.orientable;
  // Summed by chunks of faces (the chunks depend on the face count only, so the sums do not depend
  // on the thread count); a chunk keeps one partial sum per run of faces of one shell, which is
  // one or a few per chunk, as a shell's faces mostly follow each other.
  struct ShellSum {
    std::uint32_t shell;
    double volume6;
  };
  const ChunkPlan plan(faceCount, 65536);
  std::vector<std::vector<ShellSum>> chunkSums(plan.chunks);
  parallelChunks(plan, threads, [&](std::size_t chunk, std::size_t begin, std::size_t end) {
    std::vector<ShellSum>& sums = chunkSums[chunk];
    for (std::size_t f = begin; f < end; ++f) {
      const std::uint32_t shell = shells.shellOfFace[f];
      if (!shells.closed[shell]) continue;
      const double v = sixfoldConeVolume(positions, faces[f]);
      if (sums.empty() || sums.back().shell != shell) sums.push_back({shell, 0.0});
      sums.back().volume6 += flip[f] ? -v : v;
    }
  });
  std::vector<double> volume6(shells.shellCount(), 0.0);
  for (const std::vector<ShellSum>& sums : chunkSums)
    for (const ShellSum& sum : sums) volume6[sum.shell] += sum.volume6;

  // A cavity wall faces into the cavity (out of the material around it): negative volume.
  std::vector<std::uint8_t> solidShell(shells.shellCount(), 0);
  for (std::size_t s = 0; s < shells.shellCount(); ++s) solidShell[s] = shells.closed[s] && orientable[s];
  // Without interfaces, solids nested in solids of another group (surfaces only: a steel ball drawn
  // inside a glass ball) learn which group surrounds them, as interfaces know their outer volume.
  const bool findEnclosing = faceSide.empty() && !facePhysicalTag.empty();
  ShellNesting nesting =
      findShellNesting(positions, faces, shells, facePhysicalTag, solidShell, findEnclosing);
  std::vector<std::uint8_t>& cavity = nesting.cavity;
  // (Nothing to learn when no shell lies in another: the passes over the faces are skipped.)
  if (findEnclosing && std::any_of(nesting.enclosing.begin(), nesting.enclosing.end(),
                                   [](std::uint32_t around) { return around != kNoShell; })) {
    std::vector<std::uint32_t> firstFace(shells.shellCount(), kNoShell);
    for (std::size_t f = faceCount; f-- > 0;)
      firstFace[shells.shellOfFace[f]] = static_cast<std::uint32_t>(f);
    for (std::size_t f = 0; f < faceCount; ++f) {
      const std::uint32_t shell = shells.shellOfFace[f];
      const std::uint32_t around = nesting.enclosing[shell];
      if (!solidShell[shell] || cavity[shell] || around == kNoShell || cavity[around]) continue;
      if (report.faceEnclosedBy.empty())
        report.faceEnclosedBy.assign(faceCount, ShellOrientationReport::kNotEnclosed);
      report.faceEnclosedBy[f] = facePhysicalTag[firstFace[around]];
    }
  }
  std::vector<std::uint8_t> interfaceShell(faceSide.empty() ? 0 : shells.shellCount(), 0);
  for (std::size_t f = 0; f < faceSide.size(); ++f)
    if (faceSide[f] == FaceSide::kInterface) interfaceShell[shells.shellOfFace[f]] = 1;
  for (std::size_t s = 0; s < interfaceShell.size(); ++s)
    if (interfaceShell[s]) cavity[s] = 0;

  if (faceSide.empty()) orientShellRegions(positions, faces, edgeMasks, facePhysicalTag, shells, report);
  // Each face turned on its own, by chunks of faces; the reversed interfaces concatenated in chunk
  // order (face order, as one pass gives them).
  std::vector<std::uint8_t> reverseShell(shells.shellCount(), 0);
  for (std::size_t s = 0; s < shells.shellCount(); ++s)
    reverseShell[s] = (volume6[s] < 0.0) != (cavity[s] != 0);
  std::vector<std::uint64_t> chunkFlipped(plan.chunks, 0);
  std::vector<std::vector<std::uint32_t>> chunkInterfaces(plan.chunks);
  parallelChunks(plan, threads, [&](std::size_t chunk, std::size_t begin, std::size_t end) {
    std::uint8_t unusedMask = kAllEdges;
    for (std::size_t f = begin; f < end; ++f) {
      const std::uint32_t shell = shells.shellOfFace[f];
      if (!solidShell[shell]) {
        if (!faceSide.empty() && faceSide[f] != FaceSide::kSurface) report.faceBoundsSolid[f] = 1;
        continue;
      }
      report.faceBoundsSolid[f] = 1;
      if ((flip[f] != 0) == (reverseShell[shell] != 0)) continue;
      reverseWinding(faces[f], edgeMasks.empty() ? unusedMask : edgeMasks[f]);
      ++chunkFlipped[chunk];
      if (!faceSide.empty() && faceSide[f] == FaceSide::kInterface)
        chunkInterfaces[chunk].push_back(static_cast<std::uint32_t>(f));
    }
  });
  for (std::size_t k = 0; k < plan.chunks; ++k) {
    report.flippedFaces += chunkFlipped[k];
    report.reversedInterfaces.insert(report.reversedInterfaces.end(), chunkInterfaces[k].begin(),
                                     chunkInterfaces[k].end());
  }
  if (oriented) keepOrientedShells(shells, solidShell, cavity, faceSide.empty(), *oriented);
  for (std::size_t s = 0; s < shells.shellCount(); ++s) {
    if (!shells.closed[s]) continue;
    ++report.closedShells;
    if (!orientable[s]) ++report.unorientableShells;
    if (cavity[s]) ++report.cavityShells;
  }
  return report;
}

bool shellsKeepOrientation(std::span<const Vec3> positions, std::span<const MeshFace> faces,
                           const OrientedShells& oriented, int threads) {
  if (!oriented.kept) return false;
  const std::vector<OrientedShells::Run>& runs = oriented.runs;
  const bool byFace = !oriented.faceShell.empty();
  if (byFace && oriented.faceShell.size() != faces.size()) return false;
  // Chunks of faces sum the volumes of the shells they meet, in runs of one shell, then each shell
  // adds up its runs'.
  struct RunSum {
    std::uint32_t shell;
    double volume6;
  };
  const ChunkPlan plan(faces.size(), 65536);
  std::vector<std::vector<RunSum>> chunkSums(plan.chunks);
  parallelChunks(plan, threads, [&](std::size_t chunk, std::size_t begin, std::size_t end) {
    std::size_t r = 0;
    if (!byFace) {
      r = static_cast<std::size_t>(
          std::upper_bound(runs.begin(), runs.end(), begin,
                           [](std::size_t f, const OrientedShells::Run& run) { return f < run.firstFace; }) -
          runs.begin());
      r = r == 0 ? 0 : r - 1;
    }
    std::vector<RunSum>& sums = chunkSums[chunk];
    for (std::size_t f = begin; f < end; ++f) {
      std::uint32_t shell = OrientedShells::kNotSolid;
      if (byFace) {
        if (oriented.faceShell[f] != OrientedShells::kNotSolidFace) shell = oriented.faceShell[f];
      } else if (!runs.empty()) {
        while (r + 1 < runs.size() && runs[r + 1].firstFace <= f) ++r;
        shell = runs[r].shell;
      }
      if (shell == OrientedShells::kNotSolid) continue;
      if (sums.empty() || sums.back().shell != shell) sums.push_back({shell, 0.0});
      sums.back().volume6 += sixfoldConeVolume(positions, faces[f]);
    }
  });
  std::vector<double> volume6(oriented.cavity.size(), 0.0);
  std::vector<std::uint8_t> solid(oriented.cavity.size(), 0);
  for (const std::vector<RunSum>& sums : chunkSums)
    for (const RunSum& sum : sums) volume6[sum.shell] += sum.volume6, solid[sum.shell] = 1;
  for (std::size_t s = 0; s < volume6.size(); ++s)
    if (solid[s] && !(oriented.cavity[s] ? volume6[s] < 0.0 : volume6[s] > 0.0)) return false;
  return true;
}

}  // namespace lancer
