// Slices, isosurfaces and coloured cut caps: what a [[mesh]] shows of its volume. Each becomes a
// mesh of its own (mesh/volume/volume_cut.hpp) added to the scene after the [[mesh]] it comes from,
// with that mesh's material, colours, isolines and arrows; the fields of the volume go with it, every
// step, so that steps, ranges and legends work on it as on any surface. The [[mesh]] itself is then
// drawn as its `skin` style says.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "lancer/mesh/mesh.hpp"
#include "lancer/mesh/volume/volume_mesh.hpp"
#include "lancer/scene/scene_description.hpp"
#include "lancer/scene/toml_table_reader.hpp"

namespace lancer {

struct PlanarDomain;  // mesh/volume/planar_domain.hpp

// What an isosurface's or field lines' mesh is made from. Kept on the mesh's instance
// (MeshInstance::volumeSource) when its field has several steps and the view pins none: an animation
// over steps makes the mesh again at each frame's time (render/step_animation.cpp), its isosurface
// values and seeds those of the first frame.
struct VolumeViewSource {
  std::shared_ptr<const VolumeMesh> volume;
  MeshInstance parent;                // the [[mesh]] whose volume it is, its request in parent.volume
  std::vector<PhysicalGroup> groups;  // the parent mesh's
  std::string path;                   // the parent mesh's file
  bool streamlines = false;           // else isosurfaces
  std::vector<double> values;         // the isosurfaces' values
  // Field lines across a flat 2D mesh: its one-layer volume (`volume` points into it) and the side
  // of its plane the tubes lie on (+1: along its normal).
  std::shared_ptr<const PlanarDomain> planar;
  double planeSide = 1;

  const std::string& field() const;  // the field the view follows
};

// The times of the steps of the source's field (volumeFieldTimeline: their times, or step indices).
std::vector<double> volumeViewTimes(const VolumeViewSource& source);
// The source's mesh with its field at `time` (steps blended between theirs).
Mesh remakeVolumeView(const VolumeViewSource& source, double time);

// A [[mesh.slice]] table: normal (required), point.
SliceSpec readSlice(const TomlTableReader& slice);
// The [mesh] keys `skin`, `isosurfaces` and `streamlines`.
void readVolumeViewKeys(const TomlTableReader& mesh, MeshInstance& instance);
void readStreamlineKeys(const TomlTableReader& mesh, MeshInstance& instance);

// Whether the mesh's volume must be read: it has slices or isosurfaces, or it is coloured by a field
// and cut by a plane with a cap (the cap then shows the field).
bool needsVolume(const SceneDescription& description, const MeshInstance& instance);

// Appends, for each mesh i whose volumes[i] is set, the meshes that draw its slices, isosurfaces and
// coloured caps (with their instances), and applies its skin style (a hidden mesh is removed).
// Throws InputError for a request the volume cannot meet (no volume elements, an isosurface of a
// vector field or of a field it does not have); a slice that misses the volume is a note. A mesh
// without volume elements whose faces lie in one plane (a 2D model) has its field lines traced
// across its faces (mesh/volume/planar_domain.hpp), drawn on its plane.
void addVolumeViews(SceneDescription& description, std::vector<Mesh>& meshes,
                    const std::vector<std::shared_ptr<const VolumeMesh>>& volumes);

}  // namespace lancer
