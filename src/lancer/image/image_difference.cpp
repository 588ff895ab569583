#include "lancer/image/image_difference.hpp"

#include <cmath>
#include <stdexcept>

namespace lancer {

double rootMeanSquareDifference(const Image& a, const Image& b) {
  if (a.width() != b.width() || a.height() != b.height() || a.empty())
    throw std::invalid_argument("rootMeanSquareDifference: the images must have one size and not be empty");
  const auto first = a.pixels(), second = b.pixels();
  double sum = 0;
  for (std::size_t i = 0; i < first.size(); ++i) {
    const Vec3 d = first[i].rgb() - second[i].rgb();
    sum += static_cast<double>(d.x) * d.x + static_cast<double>(d.y) * d.y + static_cast<double>(d.z) * d.z;
  }
  return std::sqrt(sum / (3.0 * static_cast<double>(first.size())));
}

}  // namespace lancer
