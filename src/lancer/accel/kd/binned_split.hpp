// The one binned-SAH search of the kd-tree builds (the default binned_build.cpp, and the binned top
// of sah_build.cpp): a cell's references, the bins one pass over them fills, and the plane those
// bins and an exact sweep of their window choose; small cells are searched exactly instead
// (exactSmallSplit). The BVH bins centroids and boxes instead of planes (bvh/build_parts.hpp).
#pragma once

#include <algorithm>
#include <cstdint>
#include <limits>
#include <memory>
#include <vector>

#include "lancer/accel/kd_tree.hpp"
#include "lancer/math/aabb.hpp"

namespace lancer::binned {

// A triangle as a cell holds it: the bounds of its part inside the cell, and its build id. 32
// bytes, aligned: one vector load or store moves it, and the six bounds are contiguous.
struct alignas(32) Ref {
  float lo[3];
  float hi[3];
  std::uint32_t id;
  std::uint32_t unused;
};
static_assert(sizeof(Ref) == 32);

// Bounds as plain arrays: Vec3's operator[] is a select chain, slow with a run-time axis.
struct Box {
  float lo[3] = {std::numeric_limits<float>::max(), std::numeric_limits<float>::max(),
                 std::numeric_limits<float>::max()};
  float hi[3] = {-std::numeric_limits<float>::max(), -std::numeric_limits<float>::max(),
                 -std::numeric_limits<float>::max()};

  void extend(const Ref& r) {
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], r.lo[k]);
      hi[k] = std::max(hi[k], r.hi[k]);
    }
  }
  void extend(const Box& b) {
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], b.lo[k]);
      hi[k] = std::max(hi[k], b.hi[k]);
    }
  }
  float area() const {
    const float x = hi[0] - lo[0], y = hi[1] - lo[1], z = hi[2] - lo[2];
    return 2.0f * (x * y + y * z + z * x);
  }
  Aabb aabb() const { return {{lo[0], lo[1], lo[2]}, {hi[0], hi[1], hi[2]}}; }
};

// A cell of the tree being built and the bounds of the references it holds (inside the cell).
struct Cell {
  Box box;
  Box used;
};

// Cells of fewer references than this are split by exactSmallSplit (every bound tried, no bins):
// most cells of a tree are this small, and for them binning's fixed costs (clearing and sweeping
// the bins, the window) outweighed the few references.
constexpr std::size_t kSmallCell = 24;

// Most bins per axis. Counting costs the same for any number, and more bins put the planes closer
// to the exact sweep's; small cells take fewer (binsFor): sweeping the boundaries of 256 bins on
// three axes costs more than counting a few triangles.
constexpr int kMaxBins = 256;
constexpr int kMinBins = 16;

inline int binsFor(std::size_t refs) {
  return static_cast<int>(std::clamp<std::size_t>(refs / 4, kMinBins, kMaxBins));
}

// Where each axis's bins lie: bin = (x - lo) * scale, over the references' bounds.
struct BinGrid {
  int bins = kMinBins;
  float lo[3] = {0, 0, 0};
  float scale[3] = {0, 0, 0};

  BinGrid(const Cell& cell, std::size_t refs) : bins(binsFor(refs)) {
    for (int k = 0; k < 3; ++k) {
      const float width = cell.used.hi[k] - cell.used.lo[k];
      lo[k] = cell.used.lo[k];
      scale[k] = width > 0.0f ? float(bins) / width : 0.0f;
    }
  }
  // The one binning formula (BinCounts::count's vector code computes the same, to the bit).
  int binOf(int axis, float x) const {
    const int bin = static_cast<int>((x - lo[axis]) * scale[axis]);
    return std::clamp(bin, 0, bins - 1);
  }
};

// The counts one pass over a cell's references makes, `bins` to a row. Only 6 * bins counters are
// used and cleared (clearing all 256 for each of a million small cells would cost more than
// counting).
struct BinCounts {
  // Row j < 3: references whose lower bound on axis j falls in the bin; row 3 + j: whose upper does.
  int bins = 0;
  std::uint32_t counts[6 * kMaxBins];
  std::uint32_t planarAtLo[3];  // references lying flat in the cell's lower face
  std::uint32_t planarAtHi[3];  // ... in its upper face

  std::uint32_t* row(int j) { return counts + j * bins; }
  const std::uint32_t* row(int j) const { return counts + j * bins; }

  void clear(int binCount) {
    bins = binCount;
    std::fill_n(counts, 6 * bins, 0u);
    std::fill_n(planarAtLo, 3, 0u);
    std::fill_n(planarAtHi, 3, 0u);
  }
  void count(const Ref* refs, std::size_t n, const BinGrid& grid, const Box& cell);
  void add(const BinCounts& other) {
    for (int i = 0; i < 6 * bins; ++i) counts[i] += other.counts[i];
    for (int k = 0; k < 3; ++k) {
      planarAtLo[k] += other.planarAtLo[k];
      planarAtHi[k] += other.planarAtHi[k];
    }
  }
};

struct Split {
  int axis = -1;
  float pos = 0;
  bool planarLeft = true;  // where a reference lying in the plane goes
  float cost = std::numeric_limits<float>::infinity();
  int bin = -1;  // the bin boundary the plane is, if it is one (then refined by the window sweep)
};

// A bound in the two bins around the chosen boundary, for the exact sweep there.
struct WindowEvent {
  float pos;
  int type;  // 0 end, 1 planar, 2 start: the exact sweep's order at equal positions
  bool operator<(const WindowEvent& o) const { return pos < o.pos || (pos == o.pos && type < o.type); }
};

// The cheapest plane among the bin boundaries, the planes that cut empty space off the cell at the
// references' bounds, and the cell's faces where references lie flat in them (isolated in a flat
// cell, as the exact sweep does: on CAD parts this wraps big axis-aligned faces tightly).
Split bestBinnedSplit(const BinCounts& counts, const BinGrid& grid, const Cell& cell, std::uint32_t n,
                      const KdBuildOptions& options);

// The bounds of refs[0, n) on `axis` that fall in bins first..last, written to `events` (room for
// 2n); returns how many.
std::size_t collectWindow(const Ref* refs, std::size_t n, const BinGrid& grid, int axis, int first, int last,
                          WindowEvent* events);

// The best plane lies somewhere in the two bins around the chosen boundary: sweeps the window's
// bounds (sorted here) exactly, from the counts below the window, and keeps a cheaper plane.
void refineInWindow(Split& best, const BinCounts& counts, const Cell& cell, std::uint32_t n,
                    WindowEvent* events, std::size_t eventCount, const KdBuildOptions& options);

// Where findSplit's window events go: grown on demand, never zeroed (a window holds a small part of
// the cell's 2n bounds, so only the pages it writes come into memory).
class WindowRoom {
 public:
  WindowEvent* forRefs(std::size_t n) {
    if (room_ < 2 * n) {
      events_ = std::make_unique_for_overwrite<WindowEvent[]>(2 * n);
      room_ = 2 * n;
    }
    return events_.get();
  }

 private:
  std::unique_ptr<WindowEvent[]> events_;
  std::size_t room_ = 0;
};

// The split `counts` (of refs[0, n) on `grid`) choose: the best bin boundary or empty-space plane,
// refined by the exact sweep of the window around a boundary.
Split splitFromBins(const BinCounts& counts, const BinGrid& grid, const Ref* refs, std::size_t n,
                    const Cell& cell, const KdBuildOptions& options, WindowRoom& window);

// The split of the cell holding refs[0, n), on one thread: exact for a small cell (n < kSmallCell),
// else binned (into `counts`) and refined in the window.
Split findSplit(const Ref* refs, std::size_t n, const Cell& cell, const KdBuildOptions& options,
                BinCounts& counts, WindowRoom& window);

// The plane the exact event sweep (sah_build.cpp, Wald & Havran 2006 section 4.2) would choose for
// the n < kSmallCell references: every bound strictly inside the cell tried with the planar
// references on either side, the empty-space bonus for a real slab, flat cells at the cell's faces;
// the counts of each plane taken over all references at once (a few vector compares) instead of
// from sorted events.
Split exactSmallSplit(const Ref* refs, std::size_t n, const Box& cell, const KdBuildOptions& options);

}  // namespace lancer::binned
