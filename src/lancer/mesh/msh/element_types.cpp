#include "lancer/mesh/msh/element_types.hpp"

#include <fmt/format.h>

namespace lancer {
namespace {

enum Family : std::uint8_t {
  kNone,
  kPoint,
  kLine,
  kTriangle,
  kQuad,
  kTet,
  kHex,
  kPrism,
  kPyramid,
  kPolygon,
  kPolyhedron,
  kTrihedron
};

struct TypeEntry {
  std::uint16_t nodes;
  Family family;
};

// Indexed by gmsh type number (GmshDefines.h, MSH_LIN_2 = 1 ... MSH_TRIH_4 = 140). Variable-size
// types (polygons, B-spline lines) and the undefined numbers 76-78 and 133-136 have 0 nodes.
// clang-format off
constexpr TypeEntry kTypes[kMaxMshElementType + 1] = {
    {0, kNone},                                                                    // 0
    {2, kLine}, {3, kTriangle}, {4, kQuad}, {4, kTet}, {8, kHex}, {6, kPrism},      // 1-6
    {5, kPyramid}, {3, kLine}, {6, kTriangle}, {9, kQuad}, {10, kTet}, {27, kHex},  // 7-12
    {18, kPrism}, {14, kPyramid}, {1, kPoint}, {8, kQuad}, {20, kHex}, {15, kPrism},  // 13-18
    {13, kPyramid}, {9, kTriangle}, {10, kTriangle}, {12, kTriangle}, {15, kTriangle},  // 19-23
    {15, kTriangle}, {21, kTriangle}, {4, kLine}, {5, kLine}, {6, kLine}, {20, kTet},  // 24-29
    {35, kTet}, {56, kTet}, {22, kTet}, {28, kTet}, {0, kPolygon}, {0, kPolyhedron},  // 30-35
    {16, kQuad}, {25, kQuad}, {36, kQuad}, {12, kQuad}, {16, kQuad}, {20, kQuad},     // 36-41
    {28, kTriangle}, {36, kTriangle}, {45, kTriangle}, {55, kTriangle}, {66, kTriangle},  // 42-46
    {49, kQuad}, {64, kQuad}, {81, kQuad}, {100, kQuad}, {121, kQuad},                // 47-51
    {18, kTriangle}, {21, kTriangle}, {24, kTriangle}, {27, kTriangle}, {30, kTriangle},  // 52-56
    {24, kQuad}, {28, kQuad}, {32, kQuad}, {36, kQuad}, {40, kQuad},                  // 57-61
    {7, kLine}, {8, kLine}, {9, kLine}, {10, kLine}, {11, kLine},                     // 62-66
    {0, kLine}, {0, kTriangle}, {0, kPolygon}, {0, kLine},                            // 67-70
    {84, kTet}, {120, kTet}, {165, kTet}, {220, kTet}, {286, kTet},                   // 71-75
    {0, kNone}, {0, kNone}, {0, kNone},                                               // 76-78
    {34, kTet}, {40, kTet}, {46, kTet}, {52, kTet}, {58, kTet},                       // 79-83
    {1, kLine}, {1, kTriangle}, {1, kQuad}, {1, kTet}, {1, kHex}, {1, kPrism},        // 84-89
    {40, kPrism}, {75, kPrism},                                                       // 90-91
    {64, kHex}, {125, kHex}, {216, kHex}, {343, kHex}, {512, kHex}, {729, kHex}, {1000, kHex},  // 92-98
    {32, kHex}, {44, kHex}, {56, kHex}, {68, kHex}, {80, kHex}, {92, kHex}, {104, kHex},  // 99-105
    {126, kPrism}, {196, kPrism}, {288, kPrism}, {405, kPrism}, {550, kPrism},        // 106-110
    {24, kPrism}, {33, kPrism}, {42, kPrism}, {51, kPrism}, {60, kPrism}, {69, kPrism},  // 111-116
    {78, kPrism},                                                                     // 117
    {30, kPyramid}, {55, kPyramid}, {91, kPyramid}, {140, kPyramid}, {204, kPyramid}, {285, kPyramid},
    {385, kPyramid},                                                                  // 118-124
    {21, kPyramid}, {29, kPyramid}, {37, kPyramid}, {45, kPyramid}, {53, kPyramid}, {61, kPyramid},
    {69, kPyramid},                                                                   // 125-131
    {1, kPyramid}, {0, kNone}, {0, kNone}, {0, kNone}, {0, kNone},                    // 132-136
    {16, kTet}, {4, kTriangle}, {5, kTet}, {4, kTrihedron},                           // 137-140
};
// clang-format on

int familyDimension(Family family) {
  switch (family) {
    case kPoint:
      return 0;
    case kLine:
      return 1;
    case kTriangle:
    case kQuad:
    case kPolygon:
      return 2;
    default:
      return 3;
  }
}

const char* familyName(Family family) {
  switch (family) {
    case kPoint:
      return "point";
    case kLine:
      return "line";
    case kTriangle:
      return "triangle";
    case kQuad:
      return "quadrangle";
    case kTet:
      return "tetrahedron";
    case kHex:
      return "hexahedron";
    case kPrism:
      return "prism";
    case kPyramid:
      return "pyramid";
    case kPolygon:
      return "polygon";
    case kPolyhedron:
      return "polyhedron";
    case kTrihedron:
      return "trihedron";
    default:
      return "element";
  }
}

int cornerCount(Family family) {
  switch (family) {
    case kTriangle:
      return 3;
    case kQuad:
    case kTet:
      return 4;
    case kHex:
      return 8;
    case kPrism:
      return 6;
    case kPyramid:
      return 5;
    default:
      return 0;  // points and lines are not drawn; polygons and polyhedra have no fixed corners
  }
}

}  // namespace

MshElementType mshElementType(int type) {
  if (type < 1 || type > kMaxMshElementType) return {};
  const TypeEntry& entry = kTypes[type];
  MshElementType result{entry.nodes, familyDimension(entry.family), MshElementRole::kUnrenderable};
  if (mshIsLowOrderVolume(type)) {
    result.role = MshElementRole::kVolume;
    return result;
  }
  switch (type) {
    case 1:
    case 8:
    case 15:
    case 26:
    case 27:
    case 28:
    case 62:
    case 63:
    case 64:
    case 65:
    case 66:
      result.role = MshElementRole::kIgnored;
      break;
    case 2:
    case 3:
    case 9:
    case 10:
    case 16:
      result.role = MshElementRole::kSurface;
      break;
    default:
      // Order 3 and up: surfaces are split through their nodes (high_order.cpp), volumes give
      // their skin through their corners. Types with fewer nodes than corners are gmsh's one-node
      // "elements" (84-89, 132), which have no shape to draw.
      if (entry.nodes >= cornerCount(entry.family) && cornerCount(entry.family) > 0)
        result.role = familyDimension(entry.family) == 2 ? MshElementRole::kSurface : MshElementRole::kVolume;
      break;
  }
  return result;
}

int mshCompleteSurfaceOrder(int type) {
  switch (type) {
    case 21:
    case 36:
      return 3;
    case 23:
    case 37:
      return 4;
    case 25:
    case 38:
      return 5;
    case 42:
    case 47:
      return 6;
    case 43:
    case 48:
      return 7;
    case 44:
    case 49:
      return 8;
    case 45:
    case 50:
      return 9;
    case 46:
    case 51:
      return 10;
    default:
      return 0;
  }
}

int mshSurfaceCorners(int type) {
  const MshElementType info = mshElementType(type);
  if (info.role != MshElementRole::kSurface) return 0;
  return cornerCount(kTypes[type].family);
}

std::string mshElementRenderNote(int type) {
  const MshElementType info = mshElementType(type);
  if (type <= 19 || (info.role != MshElementRole::kSurface && info.role != MshElementRole::kVolume))
    return {};
  if (info.role == MshElementRole::kVolume)
    return "drawn through its corner nodes (its skin's faces are flat)";
  if (mshCompleteSurfaceOrder(type)) return "split into flat faces through all its nodes";
  return "drawn through its corner nodes (incomplete element: no interior nodes)";
}

std::string mshElementTypeName(int type) {
  if (type < 1 || type > kMaxMshElementType || kTypes[type].family == kNone)
    return fmt::format("type {}", type);
  const TypeEntry& entry = kTypes[type];
  if (entry.nodes == 0) return fmt::format("variable-size {}", familyName(entry.family));
  return fmt::format("{}-node {}", entry.nodes, familyName(entry.family));
}

}  // namespace lancer
