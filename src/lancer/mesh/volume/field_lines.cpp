#include "lancer/mesh/volume/field_lines.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "lancer/util/parallel_for.hpp"

namespace lancer {
namespace {

// The unit direction of the field at a point, or why there is none.
struct Direction {
  Vec3d unit;
  CellPoint at;
  bool outside = false;
  bool zero = false;
};

class DirectionField {
 public:
  DirectionField(const VolumeLocator& locator, const VolumeField& field, double sign, double zeroSpeed)
      : locator_(locator), field_(field), sign_(sign), zeroSpeed_(zeroSpeed) {}

  Direction at(const Vec3d& point, std::uint32_t hint) const {
    Direction direction;
    direction.at = locator_.locate(point, hint);
    if (!direction.at.inside()) {
      direction.outside = true;
      return direction;
    }
    float value[3];
    locator_.interpolate(field_, direction.at, value);
    const Vec3d v{value[0], value[1], value[2]};
    const double speed = length(v);
    if (!(speed > zeroSpeed_)) {
      direction.zero = true;
      return direction;
    }
    direction.unit = v * (sign_ / speed);
    return direction;
  }

 private:
  const VolumeLocator& locator_;
  const VolumeField& field_;
  double sign_;
  double zeroSpeed_;
};

// Dormand-Prince 5(4): nodes, coefficients, the fifth-order weights and the error weights (fifth
// minus fourth order).
constexpr double kA[7][6] = {
    {},
    {1.0 / 5},
    {3.0 / 40, 9.0 / 40},
    {44.0 / 45, -56.0 / 15, 32.0 / 9},
    {19372.0 / 6561, -25360.0 / 2187, 64448.0 / 6561, -212.0 / 729},
    {9017.0 / 3168, -355.0 / 33, 46732.0 / 5247, 49.0 / 176, -5103.0 / 18656},
    {35.0 / 384, 0, 500.0 / 1113, 125.0 / 192, -2187.0 / 6784, 11.0 / 84},
};
constexpr double kError[7] = {71.0 / 57600,      0,          -71.0 / 16695, 71.0 / 1920,
                              -17253.0 / 339200, 22.0 / 525, -1.0 / 40};

struct HalfLine {
  std::vector<Vec3d> points;
  std::vector<CellPoint> where;
  FieldLineEnd end = FieldLineEnd::kSteps;
};

// One way from the seed (not included), in arc length along the unit direction field.
HalfLine traceOneWay(const DirectionField& field, const Direction& start, const Vec3d& seed, double cellSize,
                     const FieldLineSettings& settings, double maxLength) {
  HalfLine line;
  const double tolerance = settings.tolerance > 0 ? settings.tolerance : 1e-3 * cellSize;
  const double smallest = 1e-4 * cellSize, largest = 2 * cellSize;
  double h = 0.25 * cellSize;
  double travelled = 0;
  Vec3d x = seed;
  Direction k1 = start;
  std::array<Vec3d, 7> k{};
  for (int step = 0; step < settings.maxSteps; ++step) {
    if (travelled >= maxLength) {
      line.end = FieldLineEnd::kLength;
      return line;
    }
    h = std::min(h, maxLength - travelled);
    bool accepted = false;
    Direction last;
    while (!accepted) {
      k[0] = k1.unit;
      bool left = false, stopped = false;
      std::uint32_t hint = k1.at.cell;
      for (int s = 1; s < 7 && !left && !stopped; ++s) {
        Vec3d y = x;
        for (int j = 0; j < s; ++j) y = y + k[static_cast<std::size_t>(j)] * (h * kA[s][j]);
        const Direction d = field.at(y, hint);
        if (d.outside) left = true;
        if (d.zero) stopped = true;
        k[static_cast<std::size_t>(s)] = d.unit;
        hint = d.at.cell;
        if (s == 6) last = d;
      }
      if (left || stopped) {
        // The step leaves the volume or meets a zero of the field: shorter, until it is too short.
        if (h <= smallest) {
          line.end = left ? FieldLineEnd::kBoundary : FieldLineEnd::kZeroField;
          return line;
        }
        h = std::max(smallest, h * 0.25);
        continue;
      }
      Vec3d error{};
      for (int s = 0; s < 7; ++s) error = error + k[static_cast<std::size_t>(s)] * (h * kError[s]);
      const double size = length(error);
      if (size <= tolerance || h <= smallest) {
        accepted = true;
      } else {
        h = std::max(smallest, h * std::clamp(0.9 * std::pow(tolerance / size, 0.2), 0.2, 1.0));
        continue;
      }
      // The fifth-order point is the last stage's (first same as last).
      Vec3d next = x;
      for (int j = 0; j < 6; ++j) next = next + k[static_cast<std::size_t>(j)] * (h * kA[6][j]);
      travelled += length(next - x);
      x = next;
      line.points.push_back(x);
      line.where.push_back(last.at);
      k1 = last;
      h = std::min(largest,
                   h * std::clamp(0.9 * std::pow(tolerance / std::max(size, 1e-300), 0.2), 1.0, 5.0));
    }
  }
  line.end = FieldLineEnd::kSteps;
  return line;
}

double maxSpeed(const VolumeField& field) {
  double largest = 0;
  for (std::size_t i = 0; i + 2 < field.values.size(); i += 3) {
    const double speed = std::sqrt(double{field.values[i]} * field.values[i] +
                                   double{field.values[i + 1]} * field.values[i + 1] +
                                   double{field.values[i + 2]} * field.values[i + 2]);
    if (std::isfinite(speed)) largest = std::max(largest, speed);
  }
  return largest;
}

double halton(std::uint32_t index, std::uint32_t base) {
  double result = 0, fraction = 1.0 / base;
  for (; index > 0; index /= base, fraction /= base) result += fraction * (index % base);
  return result;
}

}  // namespace

std::vector<FieldLine> traceFieldLines(const VolumeMesh& volume, const VolumeLocator& locator,
                                       const VolumeField& field, std::span<const Vec3d> seeds,
                                       const FieldLineSettings& settings) {
  std::vector<FieldLine> lines(seeds.size());
  if (volume.empty() || field.components != 3) return lines;
  const Vec3d extent = locator.bounds().extent();
  const double diagonal = length(extent);
  const double boxVolume = std::max(extent.x, 1e-12 * diagonal) * std::max(extent.y, 1e-12 * diagonal) *
                           std::max(extent.z, 1e-12 * diagonal);
  const double cellSize = settings.cellSize > 0
                              ? settings.cellSize
                              : std::cbrt(boxVolume / static_cast<double>(volume.cellCount()));
  const double maxLength = settings.maxLength > 0 ? settings.maxLength : 4 * diagonal;
  // A field below a billionth of its largest magnitude is taken as zero (a stagnation point).
  const double zeroSpeed = 1e-9 * maxSpeed(field);
  const DirectionField along(locator, field, 1, zeroSpeed), against(locator, field, -1, zeroSpeed);
  parallelFor(seeds.size(), settings.threads, 1, [&](std::size_t i) {
    FieldLine& line = lines[i];
    const Direction start = along.at(seeds[i], 0xFFFFFFFFu);
    if (start.outside) return;
    HalfLine back, forth;
    if (!start.zero) {
      if (settings.backward) {
        Direction reversed = start;
        reversed.unit = start.unit * -1.0;
        back = traceOneWay(against, reversed, seeds[i], cellSize, settings, maxLength);
        line.backwardEnd = back.end;
      }
      if (settings.forward) {
        forth = traceOneWay(along, start, seeds[i], cellSize, settings, maxLength);
        line.forwardEnd = forth.end;
      }
    } else {
      line.backwardEnd = line.forwardEnd = FieldLineEnd::kZeroField;
    }
    line.points.assign(back.points.rbegin(), back.points.rend());
    line.where.assign(back.where.rbegin(), back.where.rend());
    line.seedIndex = line.points.size();
    line.points.push_back(seeds[i]);
    line.where.push_back(start.at);
    line.points.insert(line.points.end(), forth.points.begin(), forth.points.end());
    line.where.insert(line.where.end(), forth.where.begin(), forth.where.end());
  });
  return lines;
}

std::vector<Vec3d> automaticSeeds(const VolumeMesh& volume, const VolumeLocator& locator, int count) {
  std::vector<Vec3d> seeds;
  if (volume.empty() || count <= 0) return seeds;
  const Aabbd& box = locator.bounds();
  const Vec3d extent = box.extent();
  // Points outside the elements (a volume that does not fill its box) are skipped; the sequence is
  // long enough for a volume filling a hundredth of its box.
  const auto wanted = static_cast<std::uint32_t>(count);
  for (std::uint32_t i = 1; seeds.size() < wanted && i < 100 * wanted + 1000; ++i) {
    const Vec3d p =
        box.lower + Vec3d{halton(i, 2) * extent.x, halton(i, 3) * extent.y, halton(i, 5) * extent.z};
    if (locator.locate(p).inside()) seeds.push_back(p);
  }
  return seeds;
}

}  // namespace lancer
