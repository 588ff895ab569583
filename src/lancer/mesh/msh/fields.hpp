// Internal to the .msh reader: $NodeData and $ElementData, gmsh's post-processing data, read into
// MeshField steps. The layout is the same in MSH 2.2 and 4.1: a text header of string tags (the
// view's name first), real tags (the time first) and integer tags (time step, components, count),
// then `count` records of a tag and `components` values (binary: a 4-byte int and doubles).
#pragma once

#include "lancer/mesh/msh/sections.hpp"

namespace lancer {

// Reads one $NodeData section (after its opening token) into state.assembler.nodeFields, with values
// in node-table order; the assembler maps them onto mesh vertices in finish().
void readMshNodeData(MshReadState& state, const char* sectionStart);
// Reads one $ElementData section into state.assembler.elementFields (values per record, with the
// records' element tags); finish() gives each face its element's value.
void readMshElementData(MshReadState& state, const char* sectionStart);

}  // namespace lancer
