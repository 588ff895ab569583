// A post-processing field that a .msh file carries beside its mesh ($NodeData or $ElementData: one
// time step of one gmsh view), mapped onto the mesh lancer renders so that surfaces can be coloured
// by it. Values are float: a colour map needs no more, and a field costs 4 bytes per vertex and
// component instead of 8.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace lancer {

struct MeshField {
  std::string name;         // the view's name (first string tag)
  bool perElement = false;  // $ElementData: one value per face; $NodeData: one per mesh vertex
  int components = 1;       // 1 scalar, 3 vector, 9 tensor
  int step = 0;             // time step index (first integer tag)
  double time = 0;          // time value (first real tag)
  // components values per mesh vertex (node data) or per face (element data), in mesh order; NaN
  // where the file gives no value (e.g. the centre lancer adds to an 8-node quad).
  std::vector<float> values;

  std::size_t itemCount() const {
    return components > 0 ? values.size() / static_cast<std::size_t>(components) : 0;
  }
  // The scalar colour maps show: the value of a scalar, the length of a vector or tensor.
  float scalar(std::size_t item) const;
  // The least and greatest scalar over the items, ignoring NaN; {0, 0} when there is none.
  std::pair<float, float> range() const;
};

}  // namespace lancer
