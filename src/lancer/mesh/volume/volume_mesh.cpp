#include "lancer/mesh/volume/volume_mesh.hpp"

namespace lancer {

const char* cellShapeName(CellShape shape) {
  switch (shape) {
    case CellShape::kTetrahedron:
      return "tetrahedron";
    case CellShape::kHexahedron:
      return "hexahedron";
    case CellShape::kPrism:
      return "prism";
    case CellShape::kPyramid:
      break;
  }
  return "pyramid";
}

const VolumeField* VolumeMesh::findField(const std::string& name, int step) const {
  for (const VolumeField& field : fields)
    if (field.name == name && field.step == step) return &field;
  return nullptr;
}

std::vector<const VolumeField*> VolumeMesh::fieldSteps(const std::string& name) const {
  std::vector<const VolumeField*> steps;
  for (const VolumeField& field : fields)
    if (field.name == name) steps.push_back(&field);
  return steps;
}

}  // namespace lancer
