// What the STL, OBJ and PLY readers collect (points, faces in named groups, vertex values) and the
// Mesh made of it by the .msh reader's assembler (mesh_from_elements.hpp), so that a surface file
// gives the mesh its .msh would: groups as physical surfaces (materials by group), vertex values as
// node fields (color_by), degenerate faces dropped, nodes recentred.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "lancer/math/vec3.hpp"
#include "lancer/mesh/mesh.hpp"

namespace lancer {

// Faces of one group: corners as indices into SurfaceData::points, three a triangle, four a quad.
struct SurfaceGroup {
  std::string name;  // "" for an unnamed group
  std::vector<std::uint32_t> triangles;
  std::vector<std::uint32_t> quads;
  std::size_t faceCount() const { return triangles.size() / 3 + quads.size() / 4; }
};

// A scalar value per point (a PLY vertex property): a node field named `name`.
struct SurfaceVertexField {
  std::string name;
  std::vector<double> values;
};

struct SurfaceData {
  std::vector<Vec3d> points;
  std::vector<SurfaceGroup> groups;
  std::vector<SurfaceVertexField> fields;

  // The group called `name`, made when it is new: a name used twice is one group (OBJ's `g`).
  SurfaceGroup& group(std::string_view name);

 private:
  std::unordered_map<std::string, std::size_t> groupIndex_;
};

// Groups become physical surfaces 1, 2, ... in their order (empty ones left out), each its own
// elementary entity; the readers checked every corner against points.size().
Mesh meshFromSurface(const SurfaceData& data, MeshSourceInfo source);

// Points that STL repeats for every facet, made one: `points` (three a facet) keeps the distinct
// points in the order they first appear, and the result gives each former point's new index.
std::vector<std::uint32_t> weldPoints(std::vector<Vec3d>& points);

}  // namespace lancer
