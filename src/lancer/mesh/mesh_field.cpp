#include "lancer/mesh/mesh_field.hpp"

#include <cmath>

namespace lancer {

float MeshField::scalar(std::size_t item) const {
  const float* v = values.data() + item * static_cast<std::size_t>(components);
  if (components == 1) return v[0];
  double sum = 0;
  for (int c = 0; c < components; ++c) sum += static_cast<double>(v[c]) * v[c];
  return static_cast<float>(std::sqrt(sum));
}

}  // namespace lancer
