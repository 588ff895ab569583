#include "lancer/accel/kd/binned_split.hpp"
#include "lancer/accel/kd/window_sweep.hpp"

namespace lancer::binned {

namespace {

// The cell's geometry along one axis, for the SAH cost of a plane at p (Wald & Havran 2006, sec. 3).
struct AxisCost {
  float lo, hi, capArea, girth, invArea, kt, ki;
  AxisCost(const Box& cell, int axis, float invArea_, const KdBuildOptions& options)
      : lo(cell.lo[axis]),
        hi(cell.hi[axis]),
        invArea(invArea_),
        kt(options.traversalCost),
        ki(options.intersectionCost) {
    const float a = cell.hi[(axis + 1) % 3] - cell.lo[(axis + 1) % 3];
    const float b = cell.hi[(axis + 2) % 3] - cell.lo[(axis + 2) % 3];
    capArea = a * b;
    girth = a + b;
  }
  float sideArea(float length) const { return 2.0f * (capArea + length * girth) * invArea; }
  float operator()(float p, std::uint32_t nl, std::uint32_t nr) const {
    return kt + ki * (sideArea(p - lo) * float(nl) + sideArea(hi - p) * float(nr));
  }
};

}  // namespace

Split bestBinnedSplit(const BinCounts& counts, const BinGrid& grid, const Cell& cell, std::uint32_t n,
                      const KdBuildOptions& options) {
  Split best;
  const float area = cell.box.area();
  if (!(area > 0.0f)) return best;
  const float invArea = 1.0f / area;
  const float kt = options.traversalCost, ki = options.intersectionCost;
  auto consider = [&](int axis, float pos, bool planarLeft, float cost, int bin) {
    if (cost < best.cost) best = {axis, pos, planarLeft, cost, bin};
  };
  for (int axis = 0; axis < 3; ++axis) {
    const float lo = cell.box.lo[axis], hi = cell.box.hi[axis];
    if (!(hi > lo)) continue;
    const AxisCost planeCost(cell.box, axis, invArea, options);
    const float flat = 2.0f * planeCost.capArea * invArea;
    if (const std::uint32_t planars = counts.planarAtLo[axis]; planars > 0) {
      const std::uint32_t rest = n - planars;
      const float c = kt + ki * (flat * float(planars) + float(rest));
      consider(axis, lo, true, rest > 0 ? c : c * options.emptySpaceFactor, -1);
    }
    if (const std::uint32_t planars = counts.planarAtHi[axis]; planars > 0) {
      const std::uint32_t rest = n - planars;
      const float c = kt + ki * (float(rest) + flat * float(planars));
      consider(axis, hi, false, rest > 0 ? c : c * options.emptySpaceFactor, -1);
    }
    const float usedLo = cell.used.lo[axis], usedHi = cell.used.hi[axis];
    const float minSlab = options.emptySpaceMinFraction * (hi - lo);
    if (usedLo - lo >= minSlab) {
      consider(axis, usedLo, false,
               (kt + ki * planeCost.sideArea(hi - usedLo) * float(n)) * options.emptySpaceFactor, -1);
    }
    if (hi - usedHi >= minSlab) {
      consider(axis, usedHi, true,
               (kt + ki * planeCost.sideArea(usedHi - lo) * float(n)) * options.emptySpaceFactor, -1);
    }
    if (grid.scale[axis] == 0.0f) continue;
    // Boundary b lies between bins b-1 and b: references starting below it reach the left, those
    // ending at or above it the right (exact up to where in its bin a bound falls).
    const float step = (usedHi - usedLo) / float(grid.bins);
    std::uint32_t nl = 0, nr = n;
    for (int bin = 1; bin < grid.bins; ++bin) {
      nl += counts.rows[axis][bin - 1];
      nr -= counts.rows[axis + 3][bin - 1];
      const float p = usedLo + step * float(bin);
      if (p > lo && p < hi) consider(axis, p, true, planeCost(p, nl, nr), bin);
    }
  }
  return best;
}

void collectWindow(const Ref* refs, std::size_t n, const BinGrid& grid, int axis, int first, int last,
                   std::vector<WindowEvent>& events) {
  // Most bounds lie far from the window: two compares reject them before the bin is computed.
  const float slack = 1.0f / grid.scale[axis];
  const float from = grid.lo[axis] + float(first - 1) * slack, to = grid.lo[axis] + float(last + 2) * slack;
  auto inWindow = [&](float x) {
    if (!(x >= from && x <= to)) return false;
    const int bin = grid.binOf(axis, x);
    return bin >= first && bin <= last;
  };
  for (std::size_t i = 0; i < n; ++i) {
    const float lo = refs[i].lo[axis], hi = refs[i].hi[axis];
    if (lo == hi) {
      if (inWindow(lo)) events.push_back({lo, 1});
      continue;
    }
    if (inWindow(lo)) events.push_back({lo, 2});
    if (inWindow(hi)) events.push_back({hi, 0});
  }
}

void refineInWindow(Split& best, const BinCounts& counts, const Cell& cell, std::uint32_t n,
                    std::vector<WindowEvent>& events, const KdBuildOptions& options) {
  const int axis = best.axis;
  const int first = std::max(best.bin - 1, 0);
  std::uint32_t nl = 0, nr = n;
  for (int bin = 0; bin < first; ++bin) {
    nl += counts.rows[axis][bin];
    nr -= counts.rows[axis + 3][bin];
  }
  std::sort(events.begin(), events.end());
  const AxisCost planeCost(cell.box, axis, 1.0f / cell.box.area(), options);
  sweepWindowEvents(std::span<const WindowEvent>(events), planeCost, nl, nr,
                    [&](float p, bool planarsLeft, float cost) {
                      if (cost < best.cost) best = {axis, p, planarsLeft, cost, -1};
                    });
}

}  // namespace lancer::binned
