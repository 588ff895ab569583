// `arrows = { field = "velocity", max_count = 500 }` on a [[mesh]]: reading the key, placing arrows
// on a grid over the surface (one per occupied cell, not one per node, so they read at any mesh
// density) and building them as a triangle mesh the scene renders like any other.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "lancer/mesh/mesh.hpp"
#include "lancer/scene/results/color_by_spec.hpp"
#include "lancer/scene/scene_description.hpp"
#include "lancer/scene/toml_table_reader.hpp"

namespace lancer {

// The mesh table's `arrows`, if present (file: the scene file's path, for messages).
std::optional<ArrowSpec> readArrows(const std::string& file, const TomlTableReader& mesh);

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

// The sides of an arrow's shaft and head; each arrow has 6 * kArrowSides triangles.
inline constexpr int kArrowSides = 12;

}  // namespace lancer
