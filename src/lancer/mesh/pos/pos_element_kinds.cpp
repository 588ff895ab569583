#include "lancer/mesh/pos/pos_element_kinds.hpp"

#include <fmt/format.h>

namespace lancer {
namespace {

struct Shape {
  const char* name;
  int dimension;
  int firstOrderType, firstOrderNodes;
  int secondOrderType, secondOrderNodes;  // 0: none (a point has no second order)
  char letter;
};

// gmsh's MSH element types and node counts (gmsh reference manual, "MSH file format", element types).
constexpr Shape kShapes[] = {
    {"point", 0, 15, 1, 0, 0, 'P'},        {"line", 1, 1, 2, 8, 3, 'L'},
    {"triangle", 2, 2, 3, 9, 6, 'T'},      {"quadrangle", 2, 3, 4, 10, 9, 'Q'},
    {"tetrahedron", 3, 4, 4, 11, 10, 'S'}, {"hexahedron", 3, 5, 8, 12, 27, 'H'},
    {"prism", 3, 6, 6, 13, 18, 'I'},       {"pyramid", 3, 7, 5, 14, 14, 'Y'},
};

}  // namespace

std::optional<PosElementKind> posElementKind(std::string_view code) {
  if (code.size() != 2 && !(code.size() == 3 && code[2] == '2')) return std::nullopt;
  PosElementKind kind;
  switch (code[0]) {
    case 'S':
      kind.components = 1;
      break;
    case 'V':
      kind.components = 3;
      break;
    case 'T':
      kind.components = 9;
      break;
    default:
      return std::nullopt;
  }
  for (int shape = 0; shape < 8; ++shape) {
    const Shape& s = kShapes[shape];
    if (code[1] != s.letter) continue;
    kind.shape = shape;
    kind.dimension = s.dimension;
    kind.order = code.size() == 3 ? 2 : 1;
    if (kind.order == 2 && s.secondOrderType == 0) return std::nullopt;
    kind.gmshType = kind.order == 2 ? s.secondOrderType : s.firstOrderType;
    kind.nodes = kind.order == 2 ? s.secondOrderNodes : s.firstOrderNodes;
    return kind;
  }
  return std::nullopt;
}

std::string PosElementKind::code() const {
  std::string text;
  text += components == 1 ? 'S' : components == 3 ? 'V' : 'T';
  text += kShapes[shape].letter;
  if (order == 2) text += '2';
  return text;
}

std::string PosElementKind::description() const {
  const char* kind = components == 1 ? "scalar" : components == 3 ? "vector" : "tensor";
  if (order == 2) return fmt::format("{} {}-node {}", kind, nodes, kShapes[shape].name);
  return fmt::format("{} {}", kind, kShapes[shape].name);
}

const char* posElementCodeHelp() {
  return "an element code is S, V or T (scalar, vector, tensor) followed by P, L, T, Q, S, H, I or Y "
         "(point, line, triangle, quadrangle, tetrahedron, hexahedron, prism, pyramid), with 2 after it "
         "for second order: ST, VQ, TS2";
}

}  // namespace lancer
