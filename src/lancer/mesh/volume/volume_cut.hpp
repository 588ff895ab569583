// Where a function of the volume takes one value, as triangles: a slice is where the signed distance
// to a plane is zero, an isosurface where a scalar field equals a value. Marching tetrahedra over
// every cell's split (cell_tetrahedra.hpp): the function is linear on each tetrahedron, so the cut is
// exact for a linear function on tetrahedra, and the triangles of neighbouring cells meet edge to edge
// (their shared faces are split alike and a continuous function has one value at each node).
//
// The triangles become a Mesh (positions in the volume's frame, each face tagged with its cell's
// physical and elementary tags) that lancer draws like any surface, coloured by a field of the
// volume carried over to it (cutField).
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <vector>

#include "lancer/mesh/mesh.hpp"
#include "lancer/mesh/volume/volume_mesh.hpp"

namespace lancer {

// A point of a cut: on the segment from tetrahedron point a to b of `cell` (corners or kCellCentre),
// at a + t (b - a).
struct CutPoint {
  std::uint32_t cell;
  std::uint8_t a, b;
  float t;
};

struct VolumeCut {
  Mesh surface;                                      // triangles; origin is the volume's
  std::vector<std::uint32_t> faceCell;               // per face
  std::vector<std::array<CutPoint, 3>> faceCorners;  // per face corner, in its cell's terms
  std::vector<CutPoint> vertexPoint;                 // per vertex, in the terms of a cell it is in
};

// The level function on one cell: its value at each corner k (out[k]) and at the centre
// (out[kCellCentre]).
using CellLevels = std::function<void(std::uint32_t cell, float* out)>;

// The triangles where `levels` equals `level`, wound so that their normal points towards higher
// values. continuous: the function has one value at each node (node data, a plane), so triangles
// of neighbouring cells share their vertices; otherwise each cell keeps its own.
VolumeCut cutVolume(const VolumeMesh& volume, const CellLevels& levels, float level, bool continuous);

// The slice by the plane through `point` with normal `normal` (the volume's frame).
VolumeCut sliceVolume(const VolumeMesh& volume, const Vec3d& point, const Vec3d& normal);

// The field's values carried over to the cut: per vertex for node data, per face for element data,
// per face corner for element-node data (as Mesh fields are given).
MeshField cutField(const VolumeCut& cut, const VolumeMesh& volume, const VolumeField& field);

}  // namespace lancer
