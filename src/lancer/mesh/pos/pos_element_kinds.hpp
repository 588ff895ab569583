// The element codes of gmsh's list-based post-processing format (ST, VQ2, TS, ...): what each one
// holds (components, shape, order, nodes) and its gmsh MSH element type. gmsh's parser (Gmsh.y) and
// PViewDataList::setOrder2 define them; the node counts of second-order lists are those of MSH types
// 8-14 (a second-order list carries every node of the complete element).
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace lancer {

struct PosElementKind {
  int components = 0;  // 1 scalar (S), 3 vector (V), 9 tensor (T)
  int shape = 0;       // index of P, L, T, Q, S, H, I, Y (point ... pyramid)
  int order = 1;       // 1, or 2 for the codes ending in 2
  int gmshType = 0;    // MSH element type: 15, 1, 2, 3, 4, 5, 6, 7; second order 8-14
  int nodes = 0;       // nodes per element, in gmsh's node order
  int dimension = 0;   // 0 point, 1 line, 2 surface, 3 volume

  // "ST", "VS2": the code the file uses.
  std::string code() const;
  // "scalar triangle", "vector 10-node tetrahedron": for messages.
  std::string description() const;
  // Index of the kind among every list kind (for per-view tables): shape, order and components.
  int slot() const { return (shape * 2 + (order - 1)) * 3 + (components == 1 ? 0 : components == 3 ? 1 : 2); }
};

inline constexpr int kPosKindSlots = 8 * 2 * 3;

// The kind a code names, or nullopt for anything else ("SX", "SP2", "ST3", "SG").
std::optional<PosElementKind> posElementKind(std::string_view code);

// "S, V or T (scalar, vector, tensor) then P, L, T, Q, S, H, I or Y (...), and 2 for second order".
const char* posElementCodeHelp();

}  // namespace lancer
