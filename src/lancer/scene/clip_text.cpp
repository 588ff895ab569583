#include "lancer/scene/clip_text.hpp"

#include <fmt/format.h>

#include <cstdlib>
#include <optional>

#include "lancer/scene/up_axis.hpp"

namespace lancer {
namespace {

// A whole string as a number, or nothing.
std::optional<double> numberOf(const std::string& text) {
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (text.empty() || end != text.c_str() + text.size()) return std::nullopt;
  return value;
}

}  // namespace

ClipSettings clipFromText(const std::string& text, const SourceLocation& where) {
  const auto fail = [&]() -> ClipSettings {
    throw InputError(
        where, fmt::format("'{}' is not a cutting plane: use AXIS=VALUE (x=0.5 removes x > 0.5, -z=0 "
                           "removes z < 0) or PX,PY,PZ,NX,NY,NZ (a point on the plane, then the normal of "
                           "the side removed)",
                           text));
  };
  ClipSettings clip;
  if (const std::size_t equals = text.find('='); equals != std::string::npos) {
    const std::optional<UpAxis> axis = parseUpAxis(text.substr(0, equals));
    const std::optional<double> value = numberOf(text.substr(equals + 1));
    if (!axis || !value) return fail();
    clip.normal = upVector(*axis);
    const int index = static_cast<int>(*axis) % 3;
    clip.point[index] = *value;
    return clip;
  }
  double numbers[6];
  std::size_t start = 0;
  for (int i = 0; i < 6; ++i) {
    const std::size_t comma = i < 5 ? text.find(',', start) : text.size();
    if (comma == std::string::npos) return fail();
    const std::optional<double> number = numberOf(text.substr(start, comma - start));
    if (!number) return fail();
    numbers[i] = *number;
    start = comma + 1;
  }
  clip.point = {numbers[0], numbers[1], numbers[2]};
  clip.normal = {numbers[3], numbers[4], numbers[5]};
  return clip;
}

}  // namespace lancer
