// Which drawn faces make one element: a second-order element reaches the mesh as several faces
// (a 6-node triangle as four, a 9-node quad as four quads), joined along edges that are no edges of
// the element (their kAllEdges bits clear). Element data gives all of them the element's value; an
// arrow or a vertex mean counts the element once.
#pragma once

#include <cstdint>
#include <vector>

#include "lancer/math/vec3.hpp"
#include "lancer/mesh/mesh.hpp"

namespace lancer {

struct FaceElements {
  std::vector<std::uint32_t> ofFace;  // per mesh face, its element's index (0 .. count - 1)
  std::vector<std::uint32_t> first;   // per element, its first face (the one holding its value)
  std::size_t count() const { return first.size(); }
};

// The elements of `mesh`'s faces: one per face unless second-order faces share an edge of neither
// element (a volume element's skin keeps one element per drawn face of it). Costs nothing beyond
// the two arrays for a first-order mesh.
FaceElements faceElements(const Mesh& mesh);

// Each element's centroid (the area-weighted centroid of its faces) in the mesh's local frame, with
// `positions` for the vertices (the mesh's own, or moved by a warp); and its area.
struct ElementCentroids {
  std::vector<Vec3d> centroid;
  std::vector<double> area;
};
ElementCentroids elementCentroids(const Mesh& mesh, const FaceElements& elements,
                                  const std::vector<Vec3d>& positions);

}  // namespace lancer
