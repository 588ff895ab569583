// The default SAH kd-tree build (--accel kdtree-sah): binned SAH from the root down to the leaves,
// over compact references (a triangle's bounds inside the cell and its id) partitioned in one
// growing buffer per thread, without event lists or per-node allocations. Each cell counts its
// references' bounds into bins (Shevtsov, Soupikov & Kapustin 2007, section 3), then sweeps the
// bounds that fall in the two bins around the best boundary exactly, as the event sweep of Wald &
// Havran 2006 would there. A straddler is split at the plane by clipping the triangle against that
// plane alone and intersecting with the bounds it had. The big cells at the top bin and partition
// on all build threads; below, whole subtrees are handed to the threads. Every split depends on the
// cell's references only, so the tree is the same for any thread count.
#include <algorithm>
#include <array>
#include <atomic>
#include <cstdint>
#include <future>
#include <limits>
#include <vector>

#include "lancer/accel/kd/build.hpp"
#include "lancer/accel/kd/clip.hpp"
#include "lancer/accel/kd_tree.hpp"
#include "lancer/util/parallel_for.hpp"
#include "lancer/util/stopwatch.hpp"

namespace lancer {

namespace {

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

int binsFor(std::size_t refs) {
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

// The cheapest plane among the bin boundaries, the planes that cut empty space off the cell at the
// references' bounds, and the cell's faces where references lie flat in them (those are isolated
// in a flat cell, as the exact sweep does: on CAD parts this wraps big axis-aligned faces tightly).
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

// A bound in the two bins around the chosen boundary, for the exact sweep there.
struct WindowEvent {
  float pos;
  int type;  // 0 end, 1 planar, 2 start: the exact sweep's order at equal positions
  bool operator<(const WindowEvent& o) const { return pos < o.pos || (pos == o.pos && type < o.type); }
};

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

// The best plane lies somewhere in the two bins around the chosen boundary: sweep the bounds that
// fall there (few: about 2/bins of them) exactly, from the counts below the window.
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
  for (std::size_t i = 0; i < events.size();) {
    const float p = events[i].pos;
    std::uint32_t ends = 0, planars = 0, starts = 0;
    for (; i < events.size() && events[i].pos == p; ++i) {
      ends += events[i].type == 0;
      planars += events[i].type == 1;
      starts += events[i].type == 2;
    }
    nr -= std::min(nr, planars + ends);
    if (p > planeCost.lo && p < planeCost.hi) {
      const float left = planeCost(p, nl + planars, nr), right = planeCost(p, nl, nr + planars);
      if (left < best.cost) best = {axis, p, true, left, -1};
      if (right < best.cost) best = {axis, p, false, right, -1};
    }
    nl += starts + planars;
  }
}

// The children's cells, and the bounds of what each side received.
struct Children {
  Cell left, right;
  std::size_t leftCount = 0, rightCount = 0;
};

// Sends each of refs[0, n) to the side(s) of the plane it lies on: right ones to right[], left ones
// to left[] (right may be refs itself: it is written no faster than refs is read). A reference
// crossing the plane goes to both sides with the bounds of the triangle's part there (one-plane
// clip, see splitTriangleBounds), or, below KdBuildOptions::clipAboveFraction, its box cut at the
// plane; a side where it has no part gets none.
struct Partitioner {
  const KdBuildInput& input;
  const KdBuildOptions& options;
  const Split& split;
  const Box& cell;

  bool clips(const Ref& r) const {
    if (options.clipAboveFraction <= 0.0f) return true;
    for (const int other : {(split.axis + 1) % 3, (split.axis + 2) % 3}) {
      if (r.hi[other] - r.lo[other] >= options.clipAboveFraction * (cell.hi[other] - cell.lo[other]))
        return true;
    }
    return false;
  }

  void operator()(const Ref* refs, std::size_t n, Ref* right, Ref* left, Children& out) const {
    const int k = split.axis;
    const float p = split.pos;
    // Local bounds: kept in registers (through `out` they would be reloaded after every store to
    // the reference arrays, which may alias them as far as the compiler knows).
    Box usedLeft = out.left.used, usedRight = out.right.used;
    std::size_t nl = 0, nr = 0;
    for (std::size_t i = 0; i < n; ++i) {
      const Ref r = refs[i];
      const float lo = r.lo[k], hi = r.hi[k];
      const bool planar = lo == hi && lo == p;
      const bool toLeft = planar ? split.planarLeft : hi <= p;
      const bool toRight = planar ? !split.planarLeft : lo >= p;
      if (toLeft || toRight) {
        // One side: written to both, kept by the count of one (a branch here mispredicts often).
        left[nl] = r;
        right[nr] = r;
        nl += toLeft;
        nr += toRight;
        (toLeft ? usedLeft : usedRight).extend(r);
        continue;
      }
      Ref l = r, rr = r;
      l.hi[k] = p;
      rr.lo[k] = p;
      bool keepLeft = true, keepRight = true;
      if (clips(r)) {
        Aabb below, above;
        splitTriangleBounds(input.corners[r.id], k, p, below, above);
        keepLeft = intersect(l, below);
        keepRight = intersect(rr, above);
      }
      if (keepLeft) {
        left[nl++] = l;
        usedLeft.extend(l);
      }
      if (keepRight) {
        right[nr++] = rr;
        usedRight.extend(rr);
      }
    }
    out.left.used = usedLeft;
    out.right.used = usedRight;
    out.leftCount += nl;
    out.rightCount += nr;
  }

  // r := r ∩ box; false when that is empty.
  static bool intersect(Ref& r, const Aabb& box) {
    const float blo[3] = {box.lower.x, box.lower.y, box.lower.z};
    const float bhi[3] = {box.upper.x, box.upper.y, box.upper.z};
    bool nonEmpty = true;
    for (int k = 0; k < 3; ++k) {
      r.lo[k] = std::max(r.lo[k], blo[k]);
      r.hi[k] = std::min(r.hi[k], bhi[k]);
      nonEmpty &= r.lo[k] <= r.hi[k];
    }
    return nonEmpty;
  }
};

Children childCells(const Cell& cell, const Split& split) {
  Children c;
  c.left.box = c.right.box = cell.box;
  c.left.box.hi[split.axis] = split.pos;
  c.right.box.lo[split.axis] = split.pos;
  return c;
}

// A subtree handed to one thread: its references, and where its root goes.
struct Subtree {
  std::vector<Ref> refs;
  Cell cell;
  int depth = 0;
  BuildNode* slot = nullptr;
};

class BinnedBuilder {
 public:
  BinnedBuilder(const KdBuildInput& input, const KdBuildOptions& options, BuildArenas& arenas)
      : input_(input),
        options_(options),
        arenas_(arenas),
        maxDepth_(resolveMaxDepth(options, input.triangles.size())),
        threads_(resolveThreads(options)),
        chunkGrain_(std::clamp<std::size_t>(options.parallelSplitAbove / 4, 1, 16384)) {}

  BuildNode* buildRoot() {
    const std::size_t n = input_.triangles.size();
    Cell root;
    const Aabb& bounds = input_.bounds;
    for (int k = 0; k < 3; ++k) {
      root.box.lo[k] = bounds.lower[k];
      root.box.hi[k] = bounds.upper[k];
    }
    std::vector<Ref> refs(n);
    const ChunkPlan plan(n, chunkGrain_);
    std::vector<Box> chunkUsed(plan.chunks);
    parallelChunks(plan, threads_, [&](std::size_t chunk, std::size_t begin, std::size_t end) {
      for (std::size_t t = begin; t < end; ++t) {
        const std::array<Vec3, 3>& c = input_.corners[t];
        Ref& r = refs[t];
        for (int k = 0; k < 3; ++k) {
          // + 0.0f turns -0 into +0, so equal positions compare (and bin) alike.
          r.lo[k] = std::min({c[0][k], c[1][k], c[2][k]}) + 0.0f;
          r.hi[k] = std::max({c[0][k], c[1][k], c[2][k]}) + 0.0f;
        }
        r.id = static_cast<std::uint32_t>(t);
        chunkUsed[chunk].extend(r);
      }
    });
    for (const Box& used : chunkUsed) root.used.extend(used);
    // One thread: the whole tree is one subtree. More: the top cells, down to a few subtrees per
    // thread, split with every thread, then the subtrees built side by side.
    topBelow_ =
        threads_ > 1 ? std::max<std::size_t>(options_.parallelSplitAbove, n / std::size_t(threads_)) : n;
    spareThreads_ = threads_ - 1;
    BuildArena& arena = arenas_.create();
    BuildNode* top = buildTop(std::move(refs), root, 0, arena);
    std::sort(subtrees_.begin(), subtrees_.end(),
              [](const Subtree& a, const Subtree& b) { return a.refs.size() > b.refs.size(); });
    std::vector<std::future<void>> running;
    for (Subtree& subtree : subtrees_) {
      if (&subtree != &subtrees_.back() && takeSpareThread()) {
        running.push_back(std::async(std::launch::async, [&] {
          *subtree.slot = *buildDetached(std::move(subtree.refs), subtree.cell, subtree.depth);
          ++spareThreads_;
        }));
      } else {
        *subtree.slot = *buildDetached(std::move(subtree.refs), subtree.cell, subtree.depth);
      }
    }
    for (std::future<void>& task : running) task.get();
    return top;
  }

 private:
  // The working memory of one thread's subtree: references of the cells on the current path, each
  // cell's right child written over it and its left child at the end (the stack grows by the
  // left children along the path only).
  struct Scratch {
    std::vector<Ref> stack;
    BinCounts counts;
    std::vector<WindowEvent> window;
    std::vector<std::uint32_t> leaf;
  };

  bool leafByCount(std::size_t n, int depth) const {
    // No split can cost less than kt * emptySpaceFactor, so cells this small stay leaves.
    const float cheapestSplit = options_.traversalCost * std::min(1.0f, options_.emptySpaceFactor);
    return n == 0 || depth >= maxDepth_ || options_.intersectionCost * float(n) <= cheapestSplit;
  }

  // Big cells: binning and partition run over chunks on every thread; their children are kept in
  // vectors of their own (few cells, so few allocations).
  BuildNode* buildTop(std::vector<Ref> refs, const Cell& cell, int depth, BuildArena& arena) {
    const std::size_t n = refs.size();
    if (n <= topBelow_ || leafByCount(n, depth)) {
      BuildNode* slot = arena.leaf({});
      subtrees_.push_back({std::move(refs), cell, depth, slot});
      return slot;
    }
    const BinGrid grid(cell, n);
    const ChunkPlan plan(n, chunkGrain_);
    std::vector<BinCounts> chunkCounts(plan.chunks);
    parallelChunks(plan, threads_, [&](std::size_t chunk, std::size_t begin, std::size_t end) {
      chunkCounts[chunk].clear(grid.bins);
      chunkCounts[chunk].count(refs.data() + begin, end - begin, grid, cell.box);
    });
    for (std::size_t c = 1; c < plan.chunks; ++c) chunkCounts[0].add(chunkCounts[c], grid.bins);
    const auto count = static_cast<std::uint32_t>(n);
    Split split = bestBinnedSplit(chunkCounts[0], grid, cell, count, options_);
    if (split.bin > 0) {
      std::vector<WindowEvent> window;
      collectWindow(refs.data(), n, grid, split.axis, split.bin - 1, split.bin, window);
      refineInWindow(split, chunkCounts[0], cell, count, window, options_);
    }
    if (split.axis < 0 || split.cost >= options_.intersectionCost * float(n)) {
      BuildNode* slot = arena.leaf({});
      subtrees_.push_back({std::move(refs), cell, depth, slot});  // its subtree makes it a leaf
      return slot;
    }
    Children children = childCells(cell, split);
    const Partitioner partition{input_, options_, split, cell.box};
    std::vector<Children> chunkChildren(plan.chunks);
    std::vector<std::vector<Ref>> chunkLeft(plan.chunks), chunkRight(plan.chunks);
    parallelChunks(plan, threads_, [&](std::size_t chunk, std::size_t begin, std::size_t end) {
      chunkLeft[chunk].resize(end - begin);
      chunkRight[chunk].resize(end - begin);
      partition(refs.data() + begin, end - begin, chunkRight[chunk].data(), chunkLeft[chunk].data(),
                chunkChildren[chunk]);
    });
    std::vector<Ref>().swap(refs);
    std::vector<std::size_t> leftAt(plan.chunks + 1, 0), rightAt(plan.chunks + 1, 0);
    for (std::size_t c = 0; c < plan.chunks; ++c) {
      const Children& part = chunkChildren[c];
      leftAt[c + 1] = leftAt[c] + part.leftCount;
      rightAt[c + 1] = rightAt[c] + part.rightCount;
      children.left.used.extend(part.left.used);
      children.right.used.extend(part.right.used);
    }
    std::vector<Ref> left(leftAt.back()), right(rightAt.back());
    parallelChunks(plan, threads_, [&](std::size_t chunk, std::size_t, std::size_t) {
      std::copy_n(chunkLeft[chunk].begin(), chunkChildren[chunk].leftCount, left.begin() + leftAt[chunk]);
      std::copy_n(chunkRight[chunk].begin(), chunkChildren[chunk].rightCount, right.begin() + rightAt[chunk]);
      std::vector<Ref>().swap(chunkLeft[chunk]);
      std::vector<Ref>().swap(chunkRight[chunk]);
    });
    BuildNode* leftNode = buildTop(std::move(left), children.left, depth + 1, arena);
    BuildNode* rightNode = buildTop(std::move(right), children.right, depth + 1, arena);
    return arena.inner(split.axis, split.pos, leftNode, rightNode);
  }

  // Whether a build thread is free to take a subtree; the caller gives it back when done. At most
  // `threads` run at once, however the subtrees fall.
  bool takeSpareThread() {
    int spare = spareThreads_.load();
    while (spare > 0 && !spareThreads_.compare_exchange_weak(spare, spare - 1)) {
    }
    return spare > 0;
  }

  // A subtree with its own working memory and arena, built by the calling thread.
  BuildNode* buildDetached(std::vector<Ref> refs, const Cell& cell, int depth) {
    Scratch scratch;
    const std::size_t n = refs.size();
    scratch.stack = std::move(refs);
    // Room for the left children along a path; grown when a deep path needs more.
    scratch.stack.resize(n + n + n / 2 + 64);
    return build(0, n, cell, depth, arenas_.create(), scratch);
  }

  // The cell whose references are scratch.stack[begin, begin + n); the stack past them is free.
  BuildNode* build(std::size_t begin, std::size_t n, const Cell& cell, int depth, BuildArena& arena,
                   Scratch& scratch) {
    if (leafByCount(n, depth)) return makeLeaf(scratch.stack.data() + begin, n, arena, scratch);
    const Ref* refs = scratch.stack.data() + begin;
    const BinGrid grid(cell, n);
    scratch.counts.clear(grid.bins);
    scratch.counts.count(refs, n, grid, cell.box);
    const auto count = static_cast<std::uint32_t>(n);
    Split split = bestBinnedSplit(scratch.counts, grid, cell, count, options_);
    if (split.bin > 0) {
      scratch.window.clear();
      collectWindow(refs, n, grid, split.axis, split.bin - 1, split.bin, scratch.window);
      refineInWindow(split, scratch.counts, cell, count, scratch.window, options_);
    }
    if (split.axis < 0 || split.cost >= options_.intersectionCost * float(n)) {
      return makeLeaf(refs, n, arena, scratch);
    }
    const std::size_t leftBegin = begin + n;
    if (scratch.stack.size() < leftBegin + n) scratch.stack.resize(2 * (leftBegin + n));
    Ref* base = scratch.stack.data();
    Children children = childCells(cell, split);
    const Partitioner partition{input_, options_, split, cell.box};
    partition(base + begin, n, base + begin, base + leftBegin, children);
    if (children.leftCount >= kForkAbove && takeSpareThread()) {
      // A thread is idle (its subtree done): it takes the left child, with a copy of its references.
      std::vector<Ref> leftRefs(base + leftBegin, base + leftBegin + children.leftCount);
      auto task = std::async(std::launch::async, [&] {
        BuildNode* node = buildDetached(std::move(leftRefs), children.left, depth + 1);
        ++spareThreads_;
        return node;
      });
      BuildNode* rightNode = build(begin, children.rightCount, children.right, depth + 1, arena, scratch);
      return arena.inner(split.axis, split.pos, task.get(), rightNode);
    }
    BuildNode* leftNode = build(leftBegin, children.leftCount, children.left, depth + 1, arena, scratch);
    BuildNode* rightNode = build(begin, children.rightCount, children.right, depth + 1, arena, scratch);
    return arena.inner(split.axis, split.pos, leftNode, rightNode);
  }

  static BuildNode* makeLeaf(const Ref* refs, std::size_t n, BuildArena& arena, Scratch& scratch) {
    scratch.leaf.resize(n);
    for (std::size_t i = 0; i < n; ++i) scratch.leaf[i] = refs[i].id;
    std::sort(scratch.leaf.begin(), scratch.leaf.end());
    return arena.leaf(scratch.leaf);
  }

  const KdBuildInput& input_;
  const KdBuildOptions& options_;
  BuildArenas& arenas_;
  int maxDepth_;
  int threads_;
  std::size_t chunkGrain_;  // references per chunk of the parallel top
  std::size_t topBelow_ = 0;
  std::atomic<int> spareThreads_{0};
  static constexpr std::size_t kForkAbove = 4096;  // smaller subtrees are not worth a thread
  std::vector<Subtree> subtrees_;
};

}  // namespace

KdTree KdTree::buildSah(std::span<const Vec3> positions, std::span<const MeshFace> faces,
                        const KdBuildOptions& options) {
  const Stopwatch stopwatch;
  KdBuildInput input = gatherTriangles(positions, faces);
  BuildArenas arenas;
  BinnedBuilder builder(input, options, arenas);
  const BuildNode* root = builder.buildRoot();
  // The layout pass is part of the build the user waits for, so it is inside the timing.
  KdTree tree = KdTreeAssembler::assemble(*root, std::move(input), options, "kdtree-sah", 0.0);
  tree.stats_.buildSeconds = stopwatch.seconds();
  return tree;
}

}  // namespace lancer
