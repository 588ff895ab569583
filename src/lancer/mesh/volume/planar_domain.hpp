// A flat 2D mesh (its triangles and quads all in one plane: a 2D gmsh model and its results) as a
// volume of one layer, so that field lines are traced across it by the volume's locator and
// integrator (field_lines.hpp). Each triangle becomes a prism and each quad a hexahedron, as thick as
// a mean cell is wide and centred on the plane; every field is carried to both layers unchanged, so
// it is constant across the thickness. A field linear on a triangle is then linear on the prism and
// its tetrahedra interpolate it exactly: the line is the one the 2D element gives. A quad is
// interpolated as a hexahedron is (piecewise linear on its tetrahedra, not bilinear).
#pragma once

#include <vector>

#include "lancer/mesh/mesh.hpp"
#include "lancer/mesh/volume/field_lines.hpp"
#include "lancer/mesh/volume/volume_mesh.hpp"

namespace lancer {

// The plane of a mesh's faces, in the mesh's frame (relative to its origin).
struct PlaneFit {
  Vec3d point;          // the mean of the faces' vertices
  Vec3d normal;         // unit, its largest component positive (+z for gmsh's 2D models in the xy plane)
  double farthest = 0;  // the largest distance of a face's vertex from the plane
  double diagonal = 0;  // of the faces' bounding box
  Vec3d farthestVertex;
  // Flat: every vertex within a millionth of the diagonal of the plane (float positions round at
  // about a ten-millionth).
  bool flat() const { return diagonal > 0 && farthest <= 1e-6 * diagonal; }
};

// The plane through the faces (the area-weighted mean of their normals, each turned to agree with
// the largest face's, so that a mesh wound both ways still finds it). A mesh without faces of
// non-zero area gives diagonal = 0.
PlaneFit fitPlane(const Mesh& surface);

struct PlanarDomain {
  VolumeMesh volume;     // the one-layer volume, in the surface's frame (same origin)
  Vec3d point;           // on the plane, the volume's frame
  Vec3d normal;          // unit
  double cellSize = 0;   // the square root of the mean face area: the integrator's scale
  double thickness = 0;  // of the layer
};

// The one-layer volume of a flat surface (fit.flat()) with every field of the surface (node,
// element and element-node data; stored steps are read back).
PlanarDomain planarDomain(const Mesh& surface, const PlaneFit& fit);

// The field's vectors with their component along `normal` taken off: what moves a point across the
// plane (a field with an out-of-plane part, or rounding) is not followed. Nothing for a field of
// other than 3 components.
void projectIntoPlane(VolumeField& field, const Vec3d& normal);

// `count` seeds spread evenly across the domain: the points of a Halton sequence (bases 2 and 3) in
// its bounding rectangle in the plane that fall on a face, in sequence order (as automaticSeeds
// does through a volume's box, which a tilted plane would mostly miss).
std::vector<Vec3d> automaticPlanarSeeds(const PlanarDomain& domain, const VolumeLocator& locator, int count);

// `point` moved onto the domain's plane.
Vec3d ontoPlane(const PlanarDomain& domain, const Vec3d& point);

// The lines' points moved onto the plane, then `height` along its normal (a tube of that radius
// then lies on the plane); `where` is kept, so the tubes take the fields of the points traced.
void liftOntoPlane(std::vector<FieldLine>& lines, const PlanarDomain& domain, double height);

}  // namespace lancer
