// Reads gmsh's list-based post-processing views (.pos text, `View "name" { ST(...){...}; ... };`, as
// GetDP writes them by default and gmsh's parsed format): per view, its elements' node coordinates and
// values.
//
// Layout. A view holds one block per element code it uses (ST, VQ2, ...), in order of first use; a
// block holds its elements in file order: coordinates per element, per node, (x, y, z); values per
// element, per time step, per node, per component, as the file lists them (gmsh's list format: all
// the nodes' values of step 0, then step 1, ...). Nodes come in gmsh's node order for the element
// type, the order of $ElementNodeData, so a caller maps a view onto mesh elements the way it maps
// $ElementNodeData. Every element of a view has the same number of steps; views may differ.
//
// What is read: S/V/T (1, 3, 9 components) on P, L, T, Q, S, H, I, Y (point, line, triangle,
// quadrangle, tetrahedron, hexahedron, prism, pyramid), first order and second order (ST2, ...),
// TIME{...}, several views per file, // and /* */ comments. Text annotations (T2, T3) are skipped
// with a warning. Refused with an InputError (file:line:col): gmsh's older $PostFormat files (ASCII
// or binary; the message says how gmsh converts them), INTERPOLATION_SCHEME views, .geo expressions
// and commands, NaN and infinite numbers, values beyond float range, inconsistent value counts.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "lancer/mesh/pos/pos_element_kinds.hpp"
#include "lancer/util/input_error.hpp"

namespace lancer {

// The elements of one element code in one view.
struct PosElementBlock {
  PosElementKind kind;              // code, components, gmshType (MSH element type), nodes per element
  std::vector<double> coords;       // per element, per node: x, y, z
  std::vector<float> values;        // per element, per step, per node, per component
  std::vector<std::int64_t> lines;  // the file line each element starts on (for messages)

  std::size_t elementCount() const { return lines.size(); }
  int nodesPerElement() const { return kind.nodes; }
  int components() const { return kind.components; }
};

struct PosView {
  std::string name;
  std::int64_t line = 0;      // where `View "name" {` is
  int stepCount = 0;          // time steps of every element (0 for a view without elements or TIME)
  std::vector<double> times;  // one per step: TIME{...} when the view has one, else 0, 1, 2, ... (gmsh's)
  bool timesGiven = false;    // the view has a TIME list
  std::vector<PosElementBlock> blocks;
  std::size_t skippedTexts = 0;  // T2 and T3 annotations, not read

  std::size_t elementCount() const;
  // The components every block has (1, 3 or 9), or 0 when the blocks mix them (or there are none).
  int components() const;
  // The values of `element` of `block` at `step`: nodesPerElement * components floats.
  const float* elementValues(const PosElementBlock& block, std::size_t element, int step) const {
    const std::size_t perStep = static_cast<std::size_t>(block.kind.nodes * block.kind.components);
    return block.values.data() + (element * static_cast<std::size_t>(stepCount) + step) * perStep;
  }
};

struct PosFile {
  std::string file;  // the name errors and warnings show
  std::vector<PosView> views;
  // "az.pos:12:1: warning: ...": what was read but not kept (text annotations).
  std::vector<std::string> warnings;
};

// Memory-maps and reads a list-based .pos file. Throws InputError on anything it cannot read whole.
// threads: as readMsh's (0: lancer's default count); a file of a few MB or more is parsed in pieces
// on that many threads, with the same result, and the same first error, as on one.
PosFile readPosFile(const std::string& path, int threads = 0);
// The same from bytes in memory (tests, fuzzing); nameForErrors is the file name errors show.
PosFile readPosFromMemory(std::span<const char> bytes, const std::string& nameForErrors, int threads = 0);

}  // namespace lancer
