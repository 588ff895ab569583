// The exact SAH kd-tree build (--accel kdtree-sah-exact), the default's quality reference: in O(N log N),
// Wald & Havran 2006, "On building fast kd-trees for ray tracing, and on doing that in O(N log N)". Cells of
// more than KdBuildOptions::binnedAbove triangles are split by the default build's binning
// (binned_split.hpp); below, per-axis event lists are sorted once per subtree; every split sweeps them to
// find the best plane (section 4.2), classifies triangles as left, right or both, and splits the sorted lists
// in linear time, clipping only the straddlers (section 4.3).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <future>
#include <limits>
#include <memory>
#include <utility>

#include "lancer/accel/build_threads.hpp"
#include "lancer/accel/kd/binned_partition.hpp"
#include "lancer/accel/kd/binned_split.hpp"
#include "lancer/accel/kd/build.hpp"
#include "lancer/accel/kd/clip.hpp"
#include "lancer/accel/kd_tree.hpp"

namespace lancer {

namespace {

// Event types in sweep order: at equal positions, ends before planars before starts.
enum : std::uint32_t { kEnd = 0, kPlanar = 1, kStart = 2 };

struct Event {
  float pos;
  std::uint32_t code;  // triangle << 2 | type

  std::uint32_t triangle() const { return code >> 2; }
  std::uint32_t type() const { return code & 3u; }
};

bool eventBefore(const Event& a, const Event& b) {
  return a.pos < b.pos || (a.pos == b.pos && a.type() < b.type());
}

using EventLists = std::array<std::vector<Event>, 3>;

// Order-preserving map of a float (never -0, never NaN) and an event type to an integer key.
std::uint64_t sortKey(const Event& e) {
  const auto bits = std::bit_cast<std::uint32_t>(e.pos);
  const std::uint32_t ordered = (bits & 0x80000000u) ? ~bits : bits | 0x80000000u;
  return (std::uint64_t(ordered) << 2) | e.type();
}

// LSD radix sort on the 34-bit (position, type) key: the root's lists hold millions of events.
void radixSortEvents(std::vector<Event>& events) {
  constexpr int kBits = 12, kPasses = 3;  // 36 bits >= 34
  constexpr std::size_t kBuckets = std::size_t(1) << kBits;
  std::vector<Event> buffer(events.size());
  std::vector<std::size_t> count(kBuckets);
  for (int pass = 0; pass < kPasses; ++pass) {
    const int shift = pass * kBits;
    std::fill(count.begin(), count.end(), 0);
    for (const Event& e : events) ++count[(sortKey(e) >> shift) & (kBuckets - 1)];
    std::size_t sum = 0;
    for (std::size_t& c : count) sum += std::exchange(c, sum);
    for (const Event& e : events) buffer[count[(sortKey(e) >> shift) & (kBuckets - 1)]++] = e;
    events.swap(buffer);
  }
}

void sortEvents(std::vector<Event>& events) {
  if (events.size() > 4096) {
    radixSortEvents(events);
  } else {
    // A lambda, not the function pointer: the comparison is inlined (the pointer cost 4% of the build).
    std::sort(events.begin(), events.end(), [](const Event& a, const Event& b) { return eventBefore(a, b); });
  }
}

void addEvents(std::uint32_t triangle, const Aabb& box, EventLists& lists) {
  for (int axis = 0; axis < 3; ++axis) {
    // + 0.0f turns -0 into +0, so equal positions have equal sort keys.
    const float lo = box.lower[axis] + 0.0f, hi = box.upper[axis] + 0.0f;
    if (lo == hi) {
      lists[axis].push_back({lo, triangle << 2 | kPlanar});
    } else {
      lists[axis].push_back({lo, triangle << 2 | kStart});
      lists[axis].push_back({hi, triangle << 2 | kEnd});
    }
  }
}

struct SplitPlane {
  int axis = -1;
  float pos = 0;
  bool planarLeft = false;
  float cost = 0;
};

enum Side : std::uint8_t { kBoth = 0, kLeftOnly = 1, kRightOnly = 2 };

// One build task's working memory, reused by every node it splits: after the first few nodes the
// sweep allocates nothing (allocations were 6% of the build, then 7% with per-node child lists).
struct Scratch {
  // The triangles the sweep works on, by the ids its events carry. Below the binned top these are
  // the subtree's own triangles numbered from 0, so that `side` and the corners the clipper reads
  // stay in the cache instead of being scattered over arrays the size of the mesh.
  std::span<const std::array<Vec3, 3>> corners;
  std::vector<std::array<Vec3, 3>> localCorners;
  std::vector<std::uint32_t> globalIds;  // id -> build triangle id; empty: ids are global
  std::vector<std::uint8_t> side;        // per id, kBoth between splits
  std::vector<std::uint32_t> straddlers;
  std::vector<std::uint32_t> leafTriangles;
  EventLists fresh[2];  // clipped straddlers' events, left and right
  // The children's event lists of the node being split at depth d live in levels[d + 1]: the left
  // child's are consumed (its whole subtree built) before the right child's are read, and only
  // deeper levels are written meanwhile.
  std::vector<std::array<EventLists, 2>> levels;
  // The binned top's search (6 KiB of counts, so on the heap).
  std::unique_ptr<binned::BinCounts> counts = std::make_unique<binned::BinCounts>();
  binned::WindowRoom window;
};

class SahBuilder {
 public:
  SahBuilder(const KdBuildInput& input, const KdBuildOptions& options, BuildArenas& arenas)
      : input_(input),
        options_(options),
        arenas_(arenas),
        maxDepth_(resolveMaxDepth(options, input.triangles.size())),
        forks_(resolveThreads(options)) {
    // Only the top levels fork (each fork copies its parent's scratch), while a thread is free.
    const int threads = forks_.count();
    forkDepth_ = threads > 1 ? std::min(6, 2 + static_cast<int>(std::log2(double(threads)))) : 0;
  }

  BuildNode* buildRoot() {
    const std::size_t n = input_.triangles.size();
    if (options_.binnedAbove > 0 && n > options_.binnedAbove) {
      std::vector<binned::Ref> refs(n);
      binned::Cell root;
      for (int k = 0; k < 3; ++k) {
        root.box.lo[k] = input_.bounds.lower[k];
        root.box.hi[k] = input_.bounds.upper[k];
      }
      for (std::uint32_t t = 0; t < n; ++t) {
        const std::array<Vec3, 3>& c = input_.corners[t];
        for (int k = 0; k < 3; ++k) {
          // + 0.0f turns -0 into +0, so equal positions compare (and bin) alike.
          refs[t].lo[k] = std::min({c[0][k], c[1][k], c[2][k]}) + 0.0f;
          refs[t].hi[k] = std::max({c[0][k], c[1][k], c[2][k]}) + 0.0f;
        }
        refs[t].id = t;
        refs[t].unused = 0;
        root.used.extend(refs[t]);
      }
      return binnedTask(std::move(refs), root, 0);
    }
    EventLists events;
    auto makeAxis = [&](int axis) {
      std::vector<Event>& list = events[axis];
      list.reserve(2 * n);
      for (std::uint32_t t = 0; t < n; ++t) {
        const std::array<Vec3, 3>& c = input_.corners[t];
        const float lo = std::min({c[0][axis], c[1][axis], c[2][axis]}) + 0.0f;
        const float hi = std::max({c[0][axis], c[1][axis], c[2][axis]}) + 0.0f;
        if (lo == hi) {
          list.push_back({lo, t << 2 | kPlanar});
        } else {
          list.push_back({lo, t << 2 | kStart});
          list.push_back({hi, t << 2 | kEnd});
        }
      }
      sortEvents(list);
    };
    if (forkDepth_ > 0) {
      auto x = std::async(std::launch::async, makeAxis, 0);
      auto y = std::async(std::launch::async, makeAxis, 1);
      makeAxis(2);
      x.get();
      y.get();
    } else {
      for (int axis = 0; axis < 3; ++axis) makeAxis(axis);
    }
    return buildTask(std::move(events), static_cast<std::uint32_t>(n), input_.bounds, 0);
  }

 private:
  // The top of the tree: big cells split by the binned search of the default build
  // (binned_split.hpp), their triangles handed down as references clipped to each side
  // (binned_partition.hpp).
  BuildNode* binnedTask(std::vector<binned::Ref> refs, const binned::Cell& cell, int depth) {
    BuildArena& arena = arenas_.create();
    Scratch scratch;
    scratch.levels.resize(static_cast<std::size_t>(maxDepth_) + 2);
    return buildBinned(std::move(refs), cell, depth, arena, scratch);
  }

  BuildNode* buildBinned(std::vector<binned::Ref> refs, const binned::Cell& cell, int depth,
                         BuildArena& arena, Scratch& scratch) {
    const std::size_t n = refs.size();
    binned::Split split;
    if (n > options_.binnedAbove && depth < maxDepth_) {
      split = binned::findSplit(refs.data(), n, cell, options_, *scratch.counts, scratch.window);
    }
    if (split.axis < 0 || split.cost >= options_.intersectionCost * float(n)) {
      // Small enough (or nothing to gain by binning): the exact sweep from here on, over events
      // made from the references' clipped boxes.
      const auto count = static_cast<std::uint32_t>(n);
      scratch.globalIds.resize(count);
      scratch.localCorners.resize(count);
      EventLists& events = scratch.levels[static_cast<std::size_t>(depth)][0];
      for (std::vector<Event>& list : events) list.clear();
      for (std::uint32_t id = 0; id < count; ++id) {
        const binned::Ref& r = refs[id];
        scratch.globalIds[id] = r.id;
        scratch.localCorners[id] = input_.corners[r.id];
        addEvents(id, Aabb{{r.lo[0], r.lo[1], r.lo[2]}, {r.hi[0], r.hi[1], r.hi[2]}}, events);
      }
      scratch.corners = scratch.localCorners;
      scratch.side.assign(count, kBoth);
      std::vector<binned::Ref>().swap(refs);
      for (std::vector<Event>& list : events) sortEvents(list);
      return build(events, count, cell.box.aabb(), depth, arena, scratch);
    }
    // The right side is written over refs, the left into a buffer of its own.
    binned::Children children = binned::childCells(cell, split);
    std::vector<binned::Ref> left(n);
    const binned::Partitioner partition{input_, options_, split, cell.box};
    partition(refs.data(), n, refs.data(), left.data(), children);
    left.resize(children.leftCount);
    refs.resize(children.rightCount);
    left.shrink_to_fit();
    refs.shrink_to_fit();

    BuildNode *leftNode = nullptr, *rightNode = nullptr;
    std::future<void> task;
    if (depth < forkDepth_) {
      task = forks_.fork([&] { leftNode = binnedTask(std::move(left), children.left, depth + 1); });
    }
    if (task.valid()) {
      rightNode = buildBinned(std::move(refs), children.right, depth + 1, arena, scratch);
      forks_.join(task);
    } else {
      leftNode = buildBinned(std::move(left), children.left, depth + 1, arena, scratch);
      rightNode = buildBinned(std::move(refs), children.right, depth + 1, arena, scratch);
    }
    return arena.inner(split.axis, split.pos, leftNode, rightNode);
  }

  // A subtree built by one thread, with its own arena and classification scratch.
  // `parent`: the forking task's scratch, whose numbering of triangles the events use (nullptr: global
  // ids). The parent only reads it until this task is done.
  BuildNode* buildTask(EventLists events, std::uint32_t count, const Aabb& box, int depth,
                       const Scratch* parent = nullptr) {
    BuildArena& arena = arenas_.create();
    Scratch scratch;
    scratch.levels.resize(static_cast<std::size_t>(maxDepth_) + 2);
    if (parent != nullptr && !parent->globalIds.empty()) {
      scratch.globalIds = parent->globalIds;
      scratch.localCorners = parent->localCorners;
      scratch.corners = scratch.localCorners;
    } else {
      scratch.corners = input_.corners;
    }
    scratch.side.assign(scratch.corners.size(), kBoth);
    return build(events, count, box, depth, arena, scratch);
  }

  BuildNode* build(EventLists& events, std::uint32_t count, const Aabb& box, int depth, BuildArena& arena,
                   Scratch& scratch) {
    const SplitPlane plane = depth < maxDepth_ && count > 0 ? findPlane(events, count, box) : SplitPlane{};
    if (plane.axis < 0 || plane.cost >= options_.intersectionCost * float(count)) {
      return makeLeaf(events, arena, scratch);
    }
    Aabb leftBox = box, rightBox = box;
    leftBox.upper[plane.axis] = plane.pos;
    rightBox.lower[plane.axis] = plane.pos;
    std::array<EventLists, 2>& children = scratch.levels[static_cast<std::size_t>(depth) + 1];
    EventLists& left = children[0];
    EventLists& right = children[1];
    std::uint32_t leftCount = 0, rightCount = 0;
    splitEvents(events, plane, leftBox, rightBox, scratch, left, right, leftCount, rightCount);

    BuildNode *leftNode = nullptr, *rightNode = nullptr;
    std::future<void> task;
    if (depth < forkDepth_) {
      task = forks_.fork(
          [&] { leftNode = buildTask(std::move(left), leftCount, leftBox, depth + 1, &scratch); });
    }
    if (task.valid()) {
      rightNode = build(right, rightCount, rightBox, depth + 1, arena, scratch);
      forks_.join(task);
    } else {
      leftNode = build(left, leftCount, leftBox, depth + 1, arena, scratch);
      rightNode = build(right, rightCount, rightBox, depth + 1, arena, scratch);
    }
    return arena.inner(plane.axis, plane.pos, leftNode, rightNode);
  }

  static BuildNode* makeLeaf(const EventLists& events, BuildArena& arena, Scratch& scratch) {
    // Each triangle has exactly one start or planar event per axis.
    std::vector<std::uint32_t>& triangles = scratch.leafTriangles;
    triangles.clear();
    const bool local = !scratch.globalIds.empty();
    for (const Event& e : events[0]) {
      if (e.type() != kEnd) triangles.push_back(local ? scratch.globalIds[e.triangle()] : e.triangle());
    }
    std::sort(triangles.begin(), triangles.end());
    return arena.leaf(triangles);
  }

  // Section 4.2: one sweep per axis over the sorted events; planar triangles at the plane are
  // tried on each side.
  SplitPlane findPlane(const EventLists& events, std::uint32_t count, const Aabb& box) const {
    SplitPlane best;
    best.cost = std::numeric_limits<float>::infinity();
    const Vec3 extent = box.extent();
    const float area = box.surfaceArea();
    if (!(area > 0.0f)) return best;
    const float invArea = 1.0f / area;
    const float kt = options_.traversalCost, ki = options_.intersectionCost;
    for (int axis = 0; axis < 3; ++axis) {
      const float lo = box.lower[axis], hi = box.upper[axis];
      if (!(hi > lo)) continue;
      const float a = extent[(axis + 1) % 3], b = extent[(axis + 2) % 3];
      const float capArea = a * b, girth = a + b;
      const std::vector<Event>& list = events[axis];
      std::uint32_t nl = 0, nr = count;
      std::size_t i = 0;
      while (i < list.size()) {
        const float p = list[i].pos;
        std::uint32_t ends = 0, planars = 0, starts = 0;
        for (; i < list.size() && list[i].pos == p; ++i) {
          const std::uint32_t type = list[i].type();
          ends += type == kEnd;
          planars += type == kPlanar;
          starts += type == kStart;
        }
        nr -= planars + ends;
        if (planars > 0 && (p == lo || p == hi)) {
          // Triangles lying in a face of the cell: isolate them in a flat cell (section 4.1) so
          // that the rest of the cell, which keeps its volume, no longer holds them. On CAD
          // parts this wraps the big axis-aligned faces tightly.
          const float flat = 2.0f * capArea * invArea;
          const float c = p == lo ? kt + ki * (flat * float(planars) + float(nr))
                                  : kt + ki * (float(nl) + flat * float(planars));
          const bool rest = p == lo ? nr > 0 : nl > 0;
          const float cost = rest ? c : c * options_.emptySpaceFactor;
          if (cost < best.cost) best = {axis, p, p == lo, cost};
        } else if (p > lo && p < hi) {
          const float pl = 2.0f * (capArea + (p - lo) * girth) * invArea;
          const float pr = 2.0f * (capArea + (hi - p) * girth) * invArea;
          // The empty-space bonus only for a real slab of empty space: granted for any sliver, it
          // makes every cell of 3+ triangles shave thin slices off itself down to the depth limit.
          const bool wideLeft = p - lo >= options_.emptySpaceMinFraction * (hi - lo);
          const bool wideRight = hi - p >= options_.emptySpaceMinFraction * (hi - lo);
          auto cost = [&](std::uint32_t cl, std::uint32_t cr) {
            const float c = kt + ki * (pl * float(cl) + pr * float(cr));
            return ((cl == 0 && wideLeft) || (cr == 0 && wideRight)) ? c * options_.emptySpaceFactor : c;
          };
          const float planarLeftCost = cost(nl + planars, nr);
          const float planarRightCost = cost(nl, nr + planars);
          if (planarLeftCost < best.cost) best = {axis, p, true, planarLeftCost};
          if (planarRightCost < best.cost) best = {axis, p, false, planarRightCost};
        }
        nl += starts + planars;
      }
    }
    return best;
  }

  // Section 4.3: classify, keep the sorted order of one-sided events, clip the straddlers and
  // merge their fresh (sorted) events in.
  void splitEvents(const EventLists& events, const SplitPlane& plane, const Aabb& leftBox,
                   const Aabb& rightBox, Scratch& scratch, EventLists& left, EventLists& right,
                   std::uint32_t& leftCount, std::uint32_t& rightCount) const {
    std::vector<std::uint8_t>& side = scratch.side;
    const int k = plane.axis;
    const float p = plane.pos;
    for (const Event& e : events[k]) {
      const std::uint32_t type = e.type();
      if (type == kEnd && e.pos <= p) {
        side[e.triangle()] = kLeftOnly;
      } else if (type == kStart && e.pos >= p) {
        side[e.triangle()] = kRightOnly;
      } else if (type == kPlanar) {
        side[e.triangle()] = (e.pos < p || (e.pos == p && plane.planarLeft)) ? kLeftOnly : kRightOnly;
      }
    }
    std::vector<std::uint32_t>& straddlers = scratch.straddlers;
    straddlers.clear();
    leftCount = rightCount = 0;
    for (const Event& e : events[k]) {
      if (e.type() == kEnd) continue;
      const std::uint8_t s = side[e.triangle()];
      leftCount += s == kLeftOnly;
      rightCount += s == kRightOnly;
      if (s == kBoth) straddlers.push_back(e.triangle());
    }
    for (int axis = 0; axis < 3; ++axis) {
      left[axis].clear();
      right[axis].clear();
      for (const Event& e : events[axis]) {
        const std::uint8_t s = side[e.triangle()];
        if (s == kLeftOnly)
          left[axis].push_back(e);
        else if (s == kRightOnly)
          right[axis].push_back(e);
      }
    }
    EventLists& newLeft = scratch.fresh[0];
    EventLists& newRight = scratch.fresh[1];
    for (std::uint32_t t : straddlers) {
      const Aabb l = clippedTriangleBounds(scratch.corners[t], leftBox);
      if (!l.empty()) {
        addEvents(t, l, newLeft);
        ++leftCount;
      }
      const Aabb r = clippedTriangleBounds(scratch.corners[t], rightBox);
      if (!r.empty()) {
        addEvents(t, r, newRight);
        ++rightCount;
      }
    }
    for (const Event& e : events[k]) side[e.triangle()] = kBoth;  // scratch clean for the next node
    for (int axis = 0; axis < 3; ++axis) {
      mergeSorted(left[axis], newLeft[axis]);
      mergeSorted(right[axis], newRight[axis]);
    }
  }

  // Leaves `fresh` empty (its capacity kept for the next node).
  static void mergeSorted(std::vector<Event>& list, std::vector<Event>& fresh) {
    if (fresh.empty()) return;
    sortEvents(fresh);
    // Merge from the back into the grown list: no temporary buffer (std::inplace_merge allocates one
    // per call). The order among equal events does not matter to the sweeps.
    std::size_t i = list.size(), j = fresh.size();
    list.resize(i + j);
    for (std::size_t out = list.size(); j > 0;) {
      if (i > 0 && eventBefore(fresh[j - 1], list[i - 1])) {
        list[--out] = list[--i];
      } else {
        list[--out] = fresh[--j];
      }
    }
    fresh.clear();
  }

  const KdBuildInput& input_;
  const KdBuildOptions& options_;
  BuildArenas& arenas_;
  int maxDepth_;
  BuildThreads forks_;
  int forkDepth_ = 0;
};

}  // namespace

KdTree KdTree::buildSahExact(std::span<const Vec3> positions, std::span<const MeshFace> faces,
                             const KdBuildOptions& options) {
  return KdTreeAssembler::build<SahBuilder>(positions, faces, options, /*withCorners=*/true,
                                            "kdtree-sah-exact");
}

}  // namespace lancer
