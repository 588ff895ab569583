// Field lines as tubes: real, closed geometry (rings of `sides` vertices around each point, joined
// by quads, capped at both ends) that is lit, shadowed and seen in mirrors like any surface. Every
// field of the volume is carried to the tube's vertices (each ring takes its centre point's values),
// so a tube is coloured by the field's magnitude or by any other field.
#pragma once

#include <span>

#include "lancer/mesh/mesh.hpp"
#include "lancer/mesh/volume/field_lines.hpp"

namespace lancer {

// The tubes of radius `radius` (model units) around the lines of at least two points, in the
// volume's frame; the rings turn with the line without twisting (a parallel-transported frame).
Mesh fieldLineTubes(const VolumeMesh& volume, const VolumeLocator& locator, std::span<const FieldLine> lines,
                    double radius, int sides = 8);

}  // namespace lancer
