// The split search of the binned kd-tree build (binned_build.cpp): a cell's references, the bins
// one pass over them fills, and the plane those bins and an exact sweep of their window choose.
#pragma once

#include <algorithm>
#include <cstdint>
#include <limits>
#include <vector>

#include "lancer/accel/kd_tree.hpp"
#include "lancer/math/aabb.hpp"

namespace lancer::binned {

// A triangle as a cell holds it: the bounds of its part inside the cell, and its build id.
struct Ref {
  float lo[3];
  float hi[3];
  std::uint32_t id;
};

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
  int binOf(int axis, float x) const {
    const int bin = static_cast<int>((x - lo[axis]) * scale[axis]);
    return std::clamp(bin, 0, bins - 1);
  }
};

// The counts one pass over a cell's references makes. Only the first `bins` of each row are used
// and cleared (clearing all 256 for each of a million small cells would cost more than counting).
struct BinCounts {
  // Rows 0-2: references whose lower bound on axis 0-2 falls in the bin; rows 3-5: whose upper does.
  std::uint32_t rows[6][kMaxBins];
  std::uint32_t planarAtLo[3];  // references lying flat in the cell's lower face
  std::uint32_t planarAtHi[3];  // ... in its upper face

  void clear(int bins) {
    for (int k = 0; k < 3; ++k) {
      std::fill_n(rows[k], bins, 0u);
      std::fill_n(rows[k + 3], bins, 0u);
      planarAtLo[k] = planarAtHi[k] = 0;
    }
  }
  void count(const Ref* refs, std::size_t n, const BinGrid& grid, const Box& cell) {
    // The six bounds of a reference are six contiguous floats: one vectorisable loop bins them.
    float lo[6], scale[6];
    for (int k = 0; k < 3; ++k) {
      lo[k] = lo[k + 3] = grid.lo[k];
      scale[k] = scale[k + 3] = grid.scale[k];
    }
    const int top = grid.bins - 1;
    for (std::size_t i = 0; i < n; ++i) {
      const Ref& r = refs[i];
      const float* bound = r.lo;  // lo[3] then hi[3]
      int bin[6];
      for (int j = 0; j < 6; ++j)
        bin[j] = std::min(std::max(static_cast<int>((bound[j] - lo[j]) * scale[j]), 0), top);
      for (int j = 0; j < 6; ++j) ++rows[j][bin[j]];
      if (r.lo[0] == r.hi[0] || r.lo[1] == r.hi[1] || r.lo[2] == r.hi[2]) {
        for (int k = 0; k < 3; ++k) {
          if (r.lo[k] == r.hi[k]) {
            planarAtLo[k] += r.lo[k] == cell.lo[k];
            planarAtHi[k] += r.hi[k] == cell.hi[k];
          }
        }
      }
    }
  }
  void add(const BinCounts& other, int bins) {
    for (int k = 0; k < 3; ++k) {
      for (int b = 0; b < bins; ++b) {
        rows[k][b] += other.rows[k][b];
        rows[k + 3][b] += other.rows[k + 3][b];
      }
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

// The bounds of refs[0, n) on `axis` that fall in bins first..last, appended to `events`.
void collectWindow(const Ref* refs, std::size_t n, const BinGrid& grid, int axis, int first, int last,
                   std::vector<WindowEvent>& events);

// The best plane lies somewhere in the two bins around the chosen boundary: sweeps the window's
// bounds (sorted here) exactly, from the counts below the window, and keeps a cheaper plane.
void refineInWindow(Split& best, const BinCounts& counts, const Cell& cell, std::uint32_t n,
                    std::vector<WindowEvent>& events, const KdBuildOptions& options);

}  // namespace lancer::binned
