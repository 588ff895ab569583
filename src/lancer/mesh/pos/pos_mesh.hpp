// A Mesh from a list-based .pos file alone: the geometry its views' elements carry, each step of
// each view an element-node field on it. The elements go through the .msh reader's assembler
// (volumes by their skin, second order split), so a view gives the mesh a .msh of its elements would.
#pragma once

#include <memory>

#include "lancer/mesh/mesh.hpp"
#include "lancer/mesh/pos/pos_reader.hpp"
#include "lancer/mesh/volume/volume_mesh.hpp"

namespace lancer {

// Nodes are the distinct coordinates (the same numbers are one node); an element that several views
// share (the same type on the same nodes, in any order) is one element, and each view's values are
// put in its order. Points and lines are counted, not drawn; there are no physical groups (the
// elements are one entity). source: what the caller knows of the file (path, size); threads: as
// readMsh's. Throws InputError for a view that mixes scalar and vector elements.
// volume: when given, set to the views' volume elements (tetrahedra, hexahedra, prisms, pyramids;
// second order by their corners), their nodes the same merged points, with each step of each view
// that has volume elements as element-node data on them (a view of surfaces alone is not there):
// slices, isosurfaces, field lines and probes of a .pos file.
Mesh meshFromPos(const PosFile& pos, MeshSourceInfo source, int threads = 0,
                 std::shared_ptr<const VolumeMesh>* volume = nullptr);

}  // namespace lancer
