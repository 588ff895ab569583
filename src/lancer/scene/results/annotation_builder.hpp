// The scene builder's part for what annotates a result (buildScene calls these mesh by mesh): the
// legends of field-coloured meshes (one per field, with one range shared by its meshes), colour
// bands and isolines; and the annotations that are meshes of their own (arrows).
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "lancer/mesh/volume/volume_mesh.hpp"
#include "lancer/scene/results/color_by.hpp"
#include "lancer/scene/results/isolines.hpp"
#include "lancer/scene/scene.hpp"

namespace lancer {

// Each mesh's color_by with the range its legend shows: meshes colouring by one field (name, step
// and map) without a range of their own share the union of their ranges, so a colour means one
// value on all of them. nullopt for meshes that are not coloured.
std::vector<std::optional<ColorBy>> sharedColorRanges(const SceneDescription& description,
                                                      const std::vector<Mesh>& meshes);

// Adds the mesh's legend (or folds it into the one for its field) and its bands to `fields`, whose
// faces from faceBase on are the mesh's. Call after appendFieldColoring.
void appendLegendAndBands(FieldColors& fields, const ColorBy& spec, const FieldColoring& coloring,
                          std::size_t faceBase, std::size_t faceEnd);
// faceBands in step with the faces, when some mesh has bands.
void finishBands(FieldColors& fields, std::size_t faceCount);

// The colours of isolines at `values` for color = "map": each value's in `map` over [low, high],
// placed on it by `scale` as the surface's colours are.
std::vector<Vec3> isolineValueColors(const std::vector<float>& values, const ColorMap& map, double low,
                                     double high, ColorScale scale = ColorScale::Linear);
// Records a mesh's isolines (resolveIsolines's, drawn as `spec` says, in valueColors when given):
// its vertices start at vertexBase and faces at faceBase in the scene, whose faces are sceneFaces.
void appendIsolines(std::optional<IsolineOverlay>& overlay, const IsolineSpec& spec,
                    ResolvedIsolines resolved, std::uint32_t vertexBase, std::size_t faceBase,
                    std::size_t faceEnd, std::size_t vertexEnd, const std::vector<MeshFace>& sceneFaces,
                    std::vector<Vec3> valueColors = {});
void finishIsolines(Scene& scene, std::optional<IsolineOverlay> overlay);

// A mesh's part in the scene's annotations: what it is coloured by and where its vertices and faces
// lie in the scene.
struct EntryAnnotation {
  const MeshInstance* instance = nullptr;
  const FieldColoring* coloring = nullptr;  // null: not coloured
  const ColorBy* colorBy = nullptr;         // what `coloring` was resolved from
  const Mesh* fields = nullptr;             // the mesh's views (isolines)
  std::uint32_t vertexBase = 0;
  std::size_t vertexEnd = 0, faceBase = 0, faceEnd = 0;
};
// The scene's field colours, legends, bands and isolines, the meshes' in order (`when`: the step
// shown). Replaces those the scene had.
void annotateScene(Scene& scene, const StepSelection& when, const std::vector<EntryAnnotation>& entries);

// Whether some mesh asks for annotations that are meshes of their own (annotation_kinds.hpp).
bool hasAnnotationMeshes(const SceneDescription& description);
// Turns each mesh's annotations into mesh instances of their own (after the others), built by their
// kind at description.when, placed like their mesh (on its warped shape). Clears the annotations of
// the originals and returns the annotations' meshes, in the order of their new instances.
std::vector<Mesh> addAnnotationMeshes(SceneDescription& description, const std::vector<Mesh>& meshes);
// Gives each mesh whose annotations sample its volume the volume read with it (volumes[i], as
// readSceneMeshes returns them); call before addVolumeViews, which may remove a hidden mesh.
void attachAnnotationVolumes(SceneDescription& description,
                             const std::vector<std::shared_ptr<const VolumeMesh>>& volumes);

}  // namespace lancer
