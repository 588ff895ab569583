// The views of a list-based .pos file put on a mesh read from elsewhere (the .msh GetDP solved on):
// a face takes its values from the view element that holds all of the face's corners among its
// nodes, matched by coordinates, so each face keeps its element's own values (a jump between
// elements, a flux density, stays a jump).
#pragma once

#include "lancer/mesh/mesh.hpp"
#include "lancer/mesh/pos/pos_reader.hpp"

namespace lancer {

// Appends each step of each view to mesh.fields as element-node data (pos_fields.hpp names them).
// A face no element of a view covers gets NaN there (GetDP prints views on some regions only).
// Coordinates match when they are the same numbers, as the mesh keeps them (float, relative to its
// origin): GetDP prints the nodes it read from the .msh with the digits gmsh wrote them with.
// A view that covers no face is an InputError naming the view, its file and the mesh; a view of
// points and lines only is skipped with a warning in mesh.source.warnings.
void addPosViews(Mesh& mesh, const PosFile& pos);

}  // namespace lancer
