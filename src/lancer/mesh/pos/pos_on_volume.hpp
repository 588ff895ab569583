// The views of a list-based .pos file put on the volume of a mesh read from elsewhere (the .msh
// GetDP solved on): each volume element of a view gives its corner values to the cell whose corners
// stand at its corners, matched by coordinates as pos_on_mesh.hpp matches faces, so every cell keeps
// its element's own values (a jump between elements stays a jump inside the volume too).
#pragma once

#include "lancer/mesh/pos/pos_reader.hpp"
#include "lancer/mesh/volume/volume_mesh.hpp"

namespace lancer {

// Appends each step of each view that has volume elements to volume.fields as element-node data,
// named and numbered as addPosViews(Mesh&) numbers them on the mesh; a cell no element of a view
// matches gets NaN there. Coordinates match when they are the same numbers as the volume keeps them
// (float, relative to its origin). Views of surfaces, lines and points alone add nothing; a view
// whose volume elements match no cell is an InputError naming the view, when the volume has cells.
void addPosViews(VolumeMesh& volume, const PosFile& pos);

}  // namespace lancer
