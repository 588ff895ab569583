#include "lancer/mesh/mesh_field.hpp"

#include <algorithm>
#include <cmath>

#include "lancer/mesh/field_steps.hpp"
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
  const auto [low, high] = componentRange(*this, FieldComponent{});  // the magnitude (a scalar's own)
  return low <= high ? std::pair{static_cast<float>(low), static_cast<float>(high)} : std::pair{0.0f, 0.0f};
}

const std::vector<float>& fieldValues(const MeshField& field,
                                      std::shared_ptr<const std::vector<float>>& keep) {
  if (!field.stored) return field.values;
  keep = field.stored->file->load(field.stored->section);
  if (const std::vector<std::uint32_t>* order = field.stored->order.get()) {
    const auto width = static_cast<std::size_t>(field.components);
    auto renumbered = std::make_shared<std::vector<float>>(keep->size());
    for (std::size_t i = 0; i < order->size(); ++i)
      std::copy_n(keep->data() + std::size_t((*order)[i]) * width, width, renumbered->data() + i * width);
    keep = std::move(renumbered);
  }
  return *keep;
}

void forgetKeptSteps(const MeshField& field) {
  if (field.stored) field.stored->file->forgetKept();
}

MeshField loadedField(const MeshField& field) {
  if (!field.stored) return field;
  MeshField copy = field;  // no values to copy: they are in the file
  copy.stored.reset();
  std::shared_ptr<const std::vector<float>> keep;
  copy.values = fieldValues(field, keep);
  return copy;
}

}  // namespace lancer
