// What a [[mesh]] asks to see inside its volume: slices (`[[mesh.slice]]`, `--slice`), isosurfaces
// (`isosurfaces = {...}`, `--isosurfaces`), field lines (`streamlines = {...}`, `--streamlines`)
// and how its own surface is drawn beside them (`skin`, `--skin`). Read by volume_views.cpp, drawn from the
// mesh's volume (mesh/volume/) as meshes of their own that take the [[mesh]]'s colours, isolines and arrows.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "lancer/math/vec3.hpp"
#include "lancer/util/input_error.hpp"

namespace lancer {

// A plane through the volume, drawn as the section of every element it crosses. Scene coordinates,
// as clipping planes; no point: through the centre of the volume's bounding box.
struct SliceSpec {
  std::optional<Vec3d> point;
  Vec3d normal{0, 0, 1};  // unit
  SourceLocation where;
};

// The mesh's own surface when slices or isosurfaces are drawn: as it is, a faint transparent copy
// (the default), its feature edges only, or not at all.
enum class SkinStyle { Shown, Ghost, Edges, Hidden };
inline constexpr std::array<std::string_view, 4> kSkinStyles = {"shown", "ghost", "edges", "hidden"};

// The most isosurfaces, and field lines, one mesh may ask for.
inline constexpr int kMaxIsosurfaces = 100;
inline constexpr int kMaxStreamlines = 100000;
// The largest tube radius in pixels (a tube as wide as a large picture).
inline constexpr double kMaxRadiusPixels = 10000;

// `isosurfaces = { field = "v", values = [0.2, 0.4] }` (or `count = 5`): the surfaces where a scalar
// field of the volume takes each value, coloured by `color_by` (another field; default: the field
// itself, each surface in its value's colour) or one `color`.
struct IsosurfaceSpec {
  std::string field;
  std::optional<int> step;     // default: the scene's step
  std::vector<double> values;  // explicit values, else `count` evenly spaced inside the range
  int count = 5;
  std::optional<Vec3> color;
  std::optional<std::string> colorBy;
  SourceLocation where;
};

// `streamlines = { field = "e", count = 100, ... }`: field lines of a vector field of the volume,
// drawn as tubes. Seeds (scene coordinates): `seed_points`, `count` points evenly along `seed_line`,
// `count` points on the disk `seed_center`/`seed_normal`/`seed_radius`, `count` points in a grid on
// the rectangle `seed_rectangle` (a corner and its two edges), or by default `count` points spread
// evenly through the volume (across a flat 2D mesh).
struct StreamlineSpec {
  enum class Seeds { Automatic, Line, Points, Disk, Rectangle };
  std::string field;
  std::optional<int> step;  // default: the scene's step
  Seeds seeds = Seeds::Automatic;
  int count = 50;
  std::vector<Vec3d> points;  // Points; Line: its two ends
  Vec3d diskCenter{}, diskNormal{0, 0, 1};
  double diskRadius = 0;
  Vec3d rectangleCorner{}, rectangleEdgeU{}, rectangleEdgeV{};  // Rectangle
  // The tubes' radius: in model units (`radius = 0.01`), or in pixels of the picture (`radius =
  // "2px"`, converted at the camera's target: camera_placement.hpp); default: 0.3% of the
  // volume's diagonal.
  std::optional<double> radius;
  std::optional<double> radiusPixels;
  std::optional<double> maxLength;  // each way from the seed; default: 4 diagonals
  bool forward = true, backward = true;
  std::optional<Vec3> color;
  std::optional<std::string> colorBy;  // default: the field's magnitude
  SourceLocation where;
};

// What an isosurface's or field lines' mesh is made from (results/volume_views.hpp).
struct VolumeViewSource;

struct VolumeViews {
  std::vector<SliceSpec> slices;
  std::optional<IsosurfaceSpec> isosurfaces;
  std::optional<StreamlineSpec> streamlines;
  std::optional<SkinStyle> skin;  // default: Ghost when slices, isosurfaces or streamlines are drawn
  bool any() const { return !slices.empty() || isosurfaces.has_value() || streamlines.has_value(); }
};

}  // namespace lancer
