#include "lancer/scene/scene_entries.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <utility>

#include "lancer/scene/results/annotation_kinds.hpp"
#include "lancer/scene/results/warp.hpp"
#include "lancer/util/input_error.hpp"

namespace lancer {
MeshInstance backdropInstance(const MeshInstance& instance, bool ghost, std::vector<Material>& materials) {
  MeshInstance copy = instance;
  copy.warp.reset();
  copy.isolines.reset();
  // What samples the volume (arrows through it) stays: the skin drawn as a backdrop shows them,
  // in the colours (map, range, legend) the mesh was given, which it no longer paints.
  std::erase_if(copy.annotations, [](const AnnotationSpec& annotation) {
    return !annotationKind(annotation).samplesVolume(annotation);
  });
  if (copy.colorBy && !copy.annotations.empty()) {
    copy.colorBy->paintsSurface = false;
    copy.colorBy->ownLegend = false;
  } else {
    copy.colorBy.reset();
  }
  copy.groupMaterials.clear();
  copy.undeformed = UndeformedStyle::None;
  copy.volume = VolumeViews{};
  Material material;
  material.name = ghost ? "ghost" : "outline";
  // Edges are lines on a surface that lets every ray through untinted (no shadow of its own).
  material.ka = material.kd = ghost ? Vec3{0.8f, 0.8f, 0.85f} : Vec3{1, 1, 1};
  material.ks = {0, 0, 0};
  material.transparency = ghost ? 0.8f : 1.0f;
  material.ior = 1;
  materials.push_back(material);
  copy.material = static_cast<int>(materials.size() - 1);
  if (!ghost) {
    EdgeSettings edges;
    edges.featuresOnly = true;
    edges.color = {0.25f, 0.25f, 0.25f};
    copy.edges = edges;
  } else {
    copy.edges.reset();
  }
  return copy;
}

// Everything of a mesh but its fields: what a step's scene is built from (the fields stay with the
// mesh as read, which holds every step).
Mesh geometryOf(const Mesh& mesh) {
  Mesh copy;
  copy.origin = mesh.origin;
  copy.positions = mesh.positions;
  copy.faces = mesh.faces;
  copy.facePhysicalTag = mesh.facePhysicalTag;
  copy.faceEntityTag = mesh.faceEntityTag;
  copy.faceEdgeMask = mesh.faceEdgeMask;
  copy.volumeSides = mesh.volumeSides;
  copy.physicalGroups = mesh.physicalGroups;
  copy.extraPhysicalGroups = mesh.extraPhysicalGroups;
  copy.source = mesh.source;
  return copy;
}

SceneColorings resolveSceneColorings(const SceneDescription& description,
                                     const std::vector<const Mesh*>& sources) {
  SceneColorings result;
  std::vector<std::optional<ColorBy>>& specs = result.specs;
  std::vector<std::optional<FieldColoring>>& colorings = result.colorings;
  specs.resize(sources.size());
  colorings.resize(sources.size());
  for (std::size_t i = 0; i < sources.size(); ++i) {
    specs[i] = description.meshes[i].colorBy;
    // A mesh that only carries its arrows' colours paints nothing and shows no legend: nothing to
    // resolve (its field may be given only inside the volume).
    if (specs[i] && specs[i]->ownLegend)
      colorings[i] = resolveColorBy(*specs[i], *sources[i], description.when);
  }
  for (std::size_t i = 0; i < sources.size(); ++i) {
    if (!specs[i] || specs[i]->range || specs[i]->perStepRange || !specs[i]->ownLegend) continue;
    std::pair<double, double> range{colorings[i]->low, colorings[i]->high};
    for (std::size_t j = 0; j < sources.size(); ++j)
      if (specs[j] && !specs[j]->range && !specs[j]->perStepRange && specs[j]->ownLegend &&
          specs[j]->field == specs[i]->field && specs[j]->map == specs[i]->map) {
        range.first = std::min(range.first, colorings[j]->low);
        range.second = std::max(range.second, colorings[j]->high);
      }
    if (range.first != colorings[i]->low || range.second != colorings[i]->high) {
      ColorBy shared = *specs[i];
      shared.range = range;
      colorings[i] = resolveColorBy(shared, *sources[i], description.when);
    }
  }
  return result;
}

// The meshes at description.when: colours resolved, warps applied (undeformed copies added after
// their mesh). `fields[i]` holds mesh i's views; null: mesh i itself (read for this scene alone).
std::vector<SceneEntry> sceneEntries(const SceneDescription& description, std::vector<Mesh> meshes,
                                     const std::vector<const Mesh*>& fields, std::vector<Material>& materials,
                                     std::vector<std::string>& warnings) {
  std::vector<const Mesh*> sources(meshes.size());
  for (std::size_t i = 0; i < meshes.size(); ++i) sources[i] = fields[i] ? fields[i] : &meshes[i];
  SceneColorings resolved = resolveSceneColorings(description, sources);
  std::vector<SceneEntry> entries;
  for (std::size_t i = 0; i < meshes.size(); ++i) {
    const MeshInstance& instance = description.meshes[i];
    SceneEntry entry{
        instance, std::move(meshes[i]), std::move(resolved.colorings[i]), resolved.specs[i], fields[i], i};
    const Mesh& source = fields[i] ? *fields[i] : entry.mesh;
    std::optional<SceneEntry> undeformed;
    if (instance.warp) {
      if (instance.undeformed != UndeformedStyle::None)
        undeformed =
            SceneEntry{backdropInstance(instance, instance.undeformed == UndeformedStyle::Ghost, materials),
                       geometryOf(entry.mesh),
                       std::nullopt,
                       std::nullopt,
                       nullptr,
                       i,
                       true};
      std::vector<float>* perFace =
          entry.coloring && entry.coloring->at != FieldAt::kNode ? &entry.coloring->t : nullptr;
      const WarpReport report = warpMesh(entry.mesh, source, *instance.warp, description.when, perFace);
      entry.collapsedFaces = report.collapsedFaces;
      if (report.collapsedFaces)
        warnings.push_back(formatInputWarning(
            instance.warp->where,
            fmt::format("{} of {}'s faces collapsed under the warp (factor {}) and were dropped",
                        report.collapsedFaces, source.source.path, instance.warp->factor)));
    }
    entries.push_back(std::move(entry));
    if (undeformed) entries.push_back(std::move(*undeformed));
  }
  return entries;
}

}  // namespace lancer
