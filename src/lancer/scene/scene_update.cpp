#include "lancer/scene/scene_update.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <optional>
#include <span>
#include <vector>

#include "lancer/scene/instance_transform.hpp"
#include "lancer/scene/results/annotation_builder.hpp"
#include "lancer/scene/results/warp.hpp"
#include "lancer/scene/scene_entries.hpp"
#include "lancer/util/parallel_for.hpp"
#include "lancer/util/stopwatch.hpp"

namespace lancer {
namespace {

// Moves the mesh's vertices in the scene to where its warp puts them at description.when, as the
// build places them (warped in the mesh's float frame, then transformed in double about the
// scene's origin). False when a vertex has no displacement or leaves the floats.
bool warpInPlace(SceneGeometry& geometry, const SceneEntryLayout& entry, const MeshInstance& instance,
                 const Mesh& mesh, const StepSelection& when, int threads) {
  if (entry.vertexCount != mesh.positions.size()) return false;
  const ViewValues step = warpDisplacement(mesh, *instance.warp, when, mesh.positions.size());
  const InstanceTransform transform(instance);
  const auto factor = static_cast<float>(instance.warp->factor);
  std::atomic<bool> finite{true};
  parallelChunks(
      ChunkPlan(mesh.positions.size(), 16384), threads, [&](std::size_t, std::size_t begin, std::size_t end) {
        bool ok = true;
        for (std::size_t v = begin; v < end; ++v) {
          const Vec3 d{step[3 * v], step[3 * v + 1], step[3 * v + 2]};
          const Vec3 moved = mesh.positions[v] + factor * d;
          const Vec3 placed = toFloat(transform.apply(mesh.origin + toDouble(moved)) - geometry.origin);
          ok = ok && isFinite(moved) && isFinite(placed);
          geometry.positions[entry.vertexBase + v] = placed;
        }
        if (!ok) finite = false;
      });
  return finite;
}

// The mesh's normals computed afresh (a vertex's smoothing may have changed: a crease formed or
// went), spliced into the scene's: the normals of the meshes after it move along, and the layout
// with them.
void recomputeNormals(SceneGeometry& geometry, SceneLayout& layout, std::size_t k, std::size_t normalEnd,
                      std::span<const std::int32_t> tags, float creaseAngleDegrees, int threads) {
  SceneEntryLayout& entry = layout.entries[k];
  const auto faces = std::span<const MeshFace>(geometry.faces).subspan(entry.faceBase, entry.faceCount);
  std::vector<MeshFace> shifted;  // numbered from the mesh's first vertex, as computeCornerNormals wants
  if (entry.vertexBase != 0) {
    shifted.assign(faces.begin(), faces.end());
    for (MeshFace& face : shifted)
      for (int c = 0; c < face.cornerCount(); ++c) face.vertex[c] -= entry.vertexBase;
  }
  std::vector<Vec3> faceNormals;
  CornerNormalWalks walks;
  CornerNormals fresh = computeCornerNormals(
      std::span<const Vec3>(geometry.positions).subspan(entry.vertexBase, entry.vertexCount),
      entry.vertexBase != 0 ? std::span<const MeshFace>(shifted) : faces, tags, creaseAngleDegrees, threads,
      &faceNormals, &walks);
  std::copy(faceNormals.begin(), faceNormals.end(), geometry.faceNormals.begin() + entry.faceBase);
  CornerNormals& normals = geometry.cornerNormals;
  const std::size_t held = normalEnd - entry.normalBase;
  if (fresh.normals.size() == held) {
    std::copy(fresh.normals.begin(), fresh.normals.end(), normals.normals.begin() + entry.normalBase);
  } else {
    normals.normals.erase(normals.normals.begin() + entry.normalBase, normals.normals.begin() + normalEnd);
    normals.normals.insert(normals.normals.begin() + entry.normalBase, fresh.normals.begin(),
                           fresh.normals.end());
  }
  for (std::size_t f = 0; f < faces.size(); ++f) {
    std::array<std::uint32_t, 4> corners = fresh.faceCorner[f];
    for (int c = 0; c < faces[f].cornerCount(); ++c) corners[c] += entry.normalBase;
    normals.faceCorner[entry.faceBase + f] = corners;
  }
  const auto shift = static_cast<std::uint32_t>(fresh.normals.size() - held);  // modulo 2^32: may go down
  for (std::size_t later = k + 1; later < layout.entries.size(); ++later) {
    SceneEntryLayout& next = layout.entries[later];
    next.normalBase += shift;
    for (std::size_t f = next.faceBase; f < std::size_t{next.faceBase} + next.faceCount; ++f)
      for (int c = 0; c < geometry.faces[f].cornerCount(); ++c) normals.faceCorner[f][c] += shift;
  }
  entry.walks = std::move(walks);
}

// The mesh's normals at its new positions; false when its faces would be oriented otherwise or one
// collapsed.
bool normalsInPlace(SceneGeometry& geometry, SceneLayout& layout, std::size_t k, std::size_t normalEnd,
                    const MeshInstance& instance, const Mesh& mesh, int threads,
                    CornerNormalsScratch* scratch, StageTimes& times) {
  const SceneEntryLayout& entry = layout.entries[k];
  const std::span<const MeshFace> faces =
      std::span<const MeshFace>(geometry.faces).subspan(entry.faceBase, entry.faceCount);
  if (mesh.facePhysicalTag.size() != entry.faceCount) return false;
  if (!shellsKeepOrientation(geometry.positions, faces, entry.shells, threads)) return false;
  // The orientation gave reversed interfaces their outer volume's tag (the smoothing compares tags).
  std::span<const std::int32_t> tags = mesh.facePhysicalTag;
  std::vector<std::int32_t> swapped;
  if (!entry.reversedInterfaces.empty()) {
    swapped = mesh.facePhysicalTag;
    for (const std::uint32_t f : entry.reversedInterfaces) swapped[f] = mesh.volumeSides.outerPhysicalTag[f];
    tags = swapped;
  }
  CornerNormals& normals = geometry.cornerNormals;
  const NormalsUpdate update = updateCornerNormals(
      geometry.positions, CornerNormalsSpan{faces, entry.vertexBase, entry.vertexCount, entry.normalBase},
      tags, instance.smoothAngleDegrees, entry.walks, threads,
      std::span<Vec3>(normals.normals).subspan(entry.normalBase, normalEnd - entry.normalBase),
      std::span<const std::array<std::uint32_t, 4>>(normals.faceCorner)
          .subspan(entry.faceBase, entry.faceCount),
      std::span<Vec3>(geometry.faceNormals).subspan(entry.faceBase, entry.faceCount), scratch);
  if (update == NormalsUpdate::FaceDegenerate) return false;
  if (update == NormalsUpdate::SmoothingChanged) {
    const Stopwatch again;
    if (scratch) scratch->release();  // the full computation's memory instead
    recomputeNormals(geometry, layout, k, normalEnd, tags, instance.smoothAngleDegrees, threads);
    times.add("normals again", again.seconds());
  }
  return true;
}

}  // namespace

bool updateSceneAt(Scene& scene, SceneLayout& layout, const SceneDescription& description,
                   const std::vector<Mesh>& meshes, int threads, StageTimes* timesOrNull,
                   CornerNormalsScratch* scratch) {
  StageTimes unused;
  StageTimes& times = timesOrNull ? *timesOrNull : unused;
  if (layout.entries.empty() || hasAnnotationMeshes(description) ||
      meshes.size() != description.meshes.size())
    return false;
  auto warped = [&](const SceneEntryLayout& entry) {
    return !entry.undeformedCopy && description.meshes[entry.meshIndex].warp.has_value();
  };
  for (const SceneEntryLayout& entry : layout.entries) {
    if (entry.meshIndex >= meshes.size()) return false;
    if (warped(entry) && (entry.collapsedFaces || entry.featureEdges || !entry.shells.kept)) return false;
  }
  SceneGeometry& geometry = scene.geometry;
  const Stopwatch warpClock;
  for (const SceneEntryLayout& entry : layout.entries)
    if (warped(entry) && !warpInPlace(geometry, entry, description.meshes[entry.meshIndex],
                                      meshes[entry.meshIndex], description.when, threads))
      return false;
  times.add("warp", warpClock.seconds());

  const Stopwatch normalsClock;
  for (std::size_t k = 0; k < layout.entries.size(); ++k) {
    const SceneEntryLayout& entry = layout.entries[k];
    const std::size_t normalEnd = k + 1 < layout.entries.size() ? layout.entries[k + 1].normalBase
                                                                : geometry.cornerNormals.normals.size();
    if (warped(entry) && !normalsInPlace(geometry, layout, k, normalEnd, description.meshes[entry.meshIndex],
                                         meshes[entry.meshIndex], threads, scratch, times))
      return false;
  }
  times.add("normals", normalsClock.seconds());

  // The colours, legends and isolines of every mesh at the new step (undeformed copies have none).
  const Stopwatch annotateClock;
  std::vector<const Mesh*> sources;
  sources.reserve(meshes.size());
  for (const Mesh& mesh : meshes) sources.push_back(&mesh);
  const SceneColorings colorings = resolveSceneColorings(description, sources);
  std::vector<EntryAnnotation> annotations;
  annotations.reserve(layout.entries.size());
  for (const SceneEntryLayout& entry : layout.entries) {
    if (entry.undeformedCopy) continue;
    const std::size_t i = entry.meshIndex;
    const std::optional<FieldColoring>& coloring = colorings.colorings[i];
    annotations.push_back({&description.meshes[i], coloring ? &*coloring : nullptr,
                           colorings.specs[i] ? &*colorings.specs[i] : nullptr, &meshes[i], entry.vertexBase,
                           std::size_t{entry.vertexBase} + entry.vertexCount, entry.faceBase,
                           std::size_t{entry.faceBase} + entry.faceCount});
  }
  annotateScene(scene, description.when, annotations);
  if (description.floor) scene.shadowCatcher = shadowCatcherOf(*description.floor, geometry);
  times.add("annotate", annotateClock.seconds());
  return true;
}

}  // namespace lancer
