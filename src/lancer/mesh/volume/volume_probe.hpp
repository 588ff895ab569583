// The value of a volume's fields at a point, interpolated in the cell that holds it (`lancer probe`,
// Mesh.probe in Python): how a user checks what a picture shows.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "lancer/mesh/volume/volume_locator.hpp"
#include "lancer/mesh/volume/volume_mesh.hpp"

namespace lancer {

struct ProbeValue {
  std::string name;
  FieldAt at = FieldAt::kNode;
  int step = 0;
  double time = 0;
  std::vector<float> values;  // the field's components
};

struct ProbeResult {
  std::uint32_t cell = 0;
  CellShape shape = CellShape::kTetrahedron;
  std::vector<ProbeValue> values;
};

// The fields named (every field when `field` is empty) at `point` (world coordinates), at step
// `step` (every step when none). Throws InputError naming `file` when the volume has no cells, the
// point is in none of them, the field or the step does not exist.
ProbeResult probeVolume(const VolumeMesh& volume, const VolumeLocator& locator, const Vec3d& point,
                        const std::string& field, std::optional<int> step, const std::string& file);

}  // namespace lancer
