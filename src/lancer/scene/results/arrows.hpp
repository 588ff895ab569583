// `arrows = { field = "velocity", max_count = 500 }` on a [[mesh]]: reading the key, placing arrows
// on a grid over the surface (one per occupied cell, not one per node, so they read at any mesh
// density) or through the volume (volume_arrows.hpp), and building them as a triangle mesh the scene
// renders like any other. The annotation kind "arrows" (annotation_kinds.hpp).
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "lancer/mesh/mesh.hpp"
#include "lancer/scene/results/annotation_kinds.hpp"
#include "lancer/scene/results/arrow_spec.hpp"
#include "lancer/scene/scene_description.hpp"
#include "lancer/scene/toml_table_reader.hpp"

namespace lancer {

// The mesh table's `arrows`, if present (file: the scene file's path, for messages).
std::optional<ArrowSpec> readArrows(const std::string& file, const TomlTableReader& mesh);
// `--arrow-grid NX,NY,NZ`'s text as a grid, checked as the key's `grid` is (option: its name).
std::array<int, 3> arrowGridFromText(const std::string& text, const std::string& option);
// The arrows of `field` with the defaults, as `--arrows FIELD` asks (where: the option).
ArrowSpec arrowsOfField(const std::string& field, const SourceLocation& where);

// Where arrows go: a grid of cubes `cellSize` wide over the mesh's bounds, as fine as keeps the
// occupied cells at most maxCount; in each occupied cell, the face-used vertex with a non-zero vector
// nearest the cell's centre.
struct ArrowPlacement {
  double cellSize = 0;
  std::vector<std::uint32_t> vertices;
};
ArrowPlacement placeArrows(const Mesh& mesh, const MeshField& field, int maxCount);

// The arrows of `spec` on `mesh` at the step spec pins, else at the scene's `when`, as a closed
// triangle mesh in the mesh's coordinates (same origin), with a node field "<field> magnitude" for
// colouring by magnitude. Node and element-node data (the latter averaged at the vertices) stand at
// vertices placed as placeArrows says; element data stands at each element's centroid (of a volume
// element, at the centroid of each of its drawn skin faces; the faces of a split second-order element
// count once), thinned on the same grid. Their automatic scale is the same at every step (the longest
// arrow over the steps is 0.9 cells, or of an element's mean size when every element has its arrow) unless a
// step is pinned. With `warp`, they stand on the deformed surface. An InputError at spec.where when the field
// does not have 3 components.
Mesh arrowMesh(const ArrowSpec& spec, const Mesh& mesh, const StepSelection& when = {},
               const WarpSettings* warp = nullptr);

// Arrows at `bases` along `vectors` (world coordinates), their automatic scale set by `cellSize`
// and `largest` (the longest vector they stand for over the steps shown): a closed triangle mesh with
// origin `origin`, its node field "<field> magnitude" at `time`. Vectors of zero or non-finite length
// draw no arrow.
struct ArrowVectors {
  std::vector<Vec3d> bases, vectors;
  double cellSize = 0;
  double largest = 0;
};
Mesh arrowsAlong(const ArrowSpec& spec, const ArrowVectors& arrows, const Vec3d& origin,
                 const std::string& path, double time);

// The kind's row in annotation_kinds.cpp: the key read, the arrows built (on the surface, or through
// the volume with `grid`) and styled (by magnitude in the owner's map, sharing its legend when they
// show the field it is coloured by; else in a material of `color`).
std::optional<AnnotationSpec> readArrowAnnotation(const std::string& file, const TomlTableReader& mesh);
Mesh buildArrowAnnotation(const AnnotationSpec& spec, const AnnotationSite& site, MeshInstance& instance);
bool arrowsSampleVolume(const AnnotationSpec& spec);

// The sides of an arrow's shaft and head; each arrow has 6 * kArrowSides triangles.
inline constexpr int kArrowSides = 12;

}  // namespace lancer
