#include "lancer/mesh/mesh_field.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "lancer/mesh/msh/stored_steps.hpp"

namespace lancer {

float MeshField::scalar(std::size_t item) const {
  const float* v = values.data() + item * static_cast<std::size_t>(components);
  if (components == 1) return v[0];
  double sum = 0;
  for (int c = 0; c < components; ++c) sum += static_cast<double>(v[c]) * v[c];
  return static_cast<float>(std::sqrt(sum));
}

std::pair<float, float> MeshField::range() const {
  if (!ranges.empty()) {  // the magnitude's (a scalar's own), kept by the reader
    const std::pair<float, float> kept = ranges.at(static_cast<std::size_t>(components));
    return kept.first <= kept.second ? kept : std::pair{0.0f, 0.0f};
  }
  float low = std::numeric_limits<float>::infinity(), high = -low;
  for (std::size_t i = 0; i < itemCount(); ++i) {
    const float value = scalar(i);
    if (std::isnan(value)) continue;
    low = std::min(low, value);
    high = std::max(high, value);
  }
  return low <= high ? std::pair{low, high} : std::pair{0.0f, 0.0f};
}

MeshField loadedField(const MeshField& field) {
  if (!field.stored) return field;
  MeshField copy = field;  // no values to copy: they are in the file
  copy.stored.reset();
  copy.values = *field.stored->file->load(field.stored->section);
  return copy;
}

}  // namespace lancer
