// Internal to the .msh reader: $NodeData, $ElementData and $ElementNodeData, gmsh's post-processing data,
// read into MeshField steps. The layout is the same in MSH 2.2 and 4.1: a text header of string tags (the
// view's name first), real tags (the time first) and integer tags (time step, components, count),
// then `count` records of a tag and `components` values (binary: a 4-byte int and doubles).
//
// The reader's pass over the file reads each section's header and notes where its records are
// (MshFieldSection); the records are parsed once the mesh is assembled (readMshFieldRecords), straight
// into mesh order, and again later for a step left in the file (mesh/msh/stored_steps.hpp).
#pragma once

#include <string>
#include <vector>

#include "lancer/mesh/msh/field_mapping.hpp"
#include "lancer/mesh/msh/sections.hpp"

namespace lancer {

// Reads one $NodeData or $ElementData section's header (after its opening token) and skips its
// records to the end marker, noting the section in state.fieldSections.
void readMshNodeData(MshReadState& state, const char* sectionStart);
void readMshElementData(MshReadState& state, const char* sectionStart);
// $ElementNodeData: records of an element tag, its number of nodes and that many nodes' values.
void readMshElementNodeData(MshReadState& state, const char* sectionStart);

// Parses a section's records from `cursor` (placed at them) into the section's field in mesh order:
// node values per mesh vertex (NaN for a node the file gives none), element values per face.
// Values for nodes or elements the file does not have are dropped with one warning in `warnings`.
// Throws InputError at a bad record.
MeshField readMshFieldRecords(MshCursor& cursor, const MshFieldSection& section,
                              const MshFieldMapping& mapping, std::vector<std::string>& warnings);

}  // namespace lancer
