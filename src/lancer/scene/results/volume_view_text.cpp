#include "lancer/scene/results/volume_view_text.hpp"

#include <fmt/format.h>

#include <cmath>
#include <cstdlib>

#include "lancer/scene/clip_text.hpp"
#include "lancer/scene/up_axis.hpp"

namespace lancer {

SliceSpec sliceFromText(const std::string& text, const SourceLocation& where) {
  SliceSpec slice;
  slice.where = where;
  if (const std::optional<UpAxis> axis = parseUpAxis(text)) {
    slice.normal = upVector(*axis);
    return slice;
  }
  try {
    const ClipSettings plane = clipFromText(text, where);
    slice.point = plane.point;
    slice.normal = plane.normal;
  } catch (const InputError&) {
    throw InputError(where,
                     fmt::format("'{}' is not a plane: use AXIS (x, y or z: through the volume's centre), "
                                 "AXIS=VALUE (z=0.3) or PX,PY,PZ,NX,NY,NZ (a point and the normal)",
                                 text));
  }
  return slice;
}

std::pair<std::string, std::optional<int>> fieldAndCountFromText(const std::string& text,
                                                                 const std::string& option, int most) {
  const std::size_t colon = text.rfind(':');
  std::pair<std::string, std::optional<int>> result{text.substr(0, colon), std::nullopt};
  if (colon != std::string::npos) {
    const std::string countText = text.substr(colon + 1);
    char* end = nullptr;
    const double count = std::strtod(countText.c_str(), &end);
    if (countText.empty() || end != countText.c_str() + countText.size() || !(count >= 1) || count > most ||
        count != std::floor(count))
      throw InputError(
          SourceLocation{option},
          fmt::format("'{}' is not FIELD[:COUNT]: COUNT is a whole number from 1 to {}", text, most));
    result.second = static_cast<int>(count);
  }
  if (result.first.empty())
    throw InputError(SourceLocation{option}, fmt::format("give the field: {} FIELD[:COUNT]", option));
  return result;
}

std::optional<double> pixelsFromText(const std::string& text) {
  if (text.size() < 3 || text.compare(text.size() - 2, 2, "px") != 0) return std::nullopt;
  std::string number = text.substr(0, text.size() - 2);
  while (!number.empty() && number.back() == ' ') number.pop_back();
  char* end = nullptr;
  const double value = std::strtod(number.c_str(), &end);
  if (number.empty() || end != number.c_str() + number.size() || !std::isfinite(value)) return std::nullopt;
  return value;
}

}  // namespace lancer
