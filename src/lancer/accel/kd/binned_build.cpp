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

#include "lancer/accel/kd/binned_split.hpp"
#include "lancer/accel/kd/build.hpp"
#include "lancer/accel/kd/clip.hpp"
#include "lancer/accel/kd_tree.hpp"
#include "lancer/util/parallel_for.hpp"
#include "lancer/util/stopwatch.hpp"

namespace lancer {

namespace {

using namespace binned;

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
        splitTriangleBounds(cornersOf(input.triangles[r.id]), k, p, below, above);
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
        const std::array<Vec3, 3> c = cornersOf(input_.triangles[t]);
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
