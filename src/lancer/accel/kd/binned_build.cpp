// The default SAH kd-tree build (--accel kdtree-sah): binned SAH from the root down to the leaves,
// over compact references (a triangle's bounds inside the cell and its id, 32 bytes) partitioned in
// one growing buffer per thread, without event lists or per-node allocations. Each cell counts its
// references' bounds into bins (Shevtsov, Soupikov & Kapustin 2007, section 3), then sweeps the
// bounds that fall in the two bins around the best boundary exactly, as the event sweep of Wald &
// Havran 2006 would there; cells of fewer than kSmallCell references (most cells of a tree) try
// every bound exactly instead (exactSmallSplit) and build their subtrees without bins or bounds
// (buildSmall). A straddler is split at the plane by clipping the triangle against that plane alone
// and intersecting with the bounds it had. Subtrees are handed to the build threads as they fall
// idle (a thread waiting for one lends its place), and the biggest cells can bin and partition on
// all threads. Every split depends on the cell's references only, so the tree is the same for any
// thread count. Each cell's node is allocated when the cell is entered, so the nodes lie in about
// the order the assembler walks them.
#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <future>
#include <limits>
#include <memory>
#include <thread>
#include <utility>
#include <vector>

#include "lancer/accel/build_threads.hpp"
#include "lancer/accel/kd/binned_partition.hpp"
#include "lancer/accel/kd/binned_split.hpp"
#include "lancer/accel/kd/build.hpp"
#include "lancer/accel/kd/clip.hpp"
#include "lancer/accel/kd_tree.hpp"
#include "lancer/util/huge_pages.hpp"
#include "lancer/util/parallel_for.hpp"

#if defined(__AVX2__)
#include <immintrin.h>
#endif
#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace lancer {

namespace {

using namespace binned;

// A growing array of references that leaves new room uninitialised (a vector would zero it: page
// faults and memory traffic for room most subtrees never reach), on huge pages when large (one
// fault per 2 MiB written), and gives back the memory of references that are done with (release).
class RefBuffer {
 public:
  RefBuffer() = default;
  explicit RefBuffer(std::size_t n) : data_(allocate(n)), size_(n) {}
  Ref* data() { return data_.get(); }
  const Ref* data() const { return data_.get(); }
  std::size_t size() const { return size_; }
  // Room for at least `n`, keeping the first `keep` references.
  void grow(std::size_t n, std::size_t keep) {
    if (n <= size_) return;
    std::unique_ptr<Ref[]> bigger(allocate(n));
    std::copy_n(data_.get(), std::min(keep, size_), bigger.get());
    data_ = std::move(bigger);
    size_ = n;
    written_ = std::min(keep, n);
  }
  // References [0, end) may have been written (their pages are in memory).
  void wrote(std::size_t end) { written_ = std::max(written_, end); }
  // Hands the whole huge pages past reference `from` back to the system (the next write there
  // gets fresh zeroed pages). A subtree's references are dead once it is built; kept, the buffer
  // would hold its deepest path's high-water mark (about twice the tree's references) until the
  // build ends, when the nodes and leaves are at their largest.
  void release(std::size_t from) {
#if defined(__linux__)
    if (written_ <= from) return;
    constexpr std::uintptr_t kPage = std::uintptr_t(2) << 20;
    auto pageUp = [](std::uintptr_t at) { return (at + kPage - 1) & ~(kPage - 1); };
    const std::uintptr_t begin = pageUp(reinterpret_cast<std::uintptr_t>(data_.get() + from));
    // Up to the page end past the last write: the rest of that page is room no one uses (but not
    // past the buffer), so that nothing written is left in memory once written_ comes down.
    const std::uintptr_t end = std::min(pageUp(reinterpret_cast<std::uintptr_t>(data_.get() + written_)),
                                        reinterpret_cast<std::uintptr_t>(data_.get() + size_) & ~(kPage - 1));
    if (end <= begin) return;
    // Failure leaves the memory in use, nothing else: the references there are dead either way.
    madvise(reinterpret_cast<void*>(begin), end - begin, MADV_DONTNEED);
    written_ = from;
#else
    (void)from;
#endif
  }

 private:
  static Ref* allocate(std::size_t n) {
    Ref* data = new Ref[n];
    if (n * sizeof(Ref) >= kHugeAbove) adviseHugePages(data, n * sizeof(Ref));
    return data;
  }
  static constexpr std::size_t kHugeAbove = std::size_t(4) << 20;
  std::unique_ptr<Ref[]> data_;
  std::size_t size_ = 0;
  std::size_t written_ = 0;
};

// A subtree handed to one thread: its references, and where its root goes.
struct Subtree {
  RefBuffer refs;
  std::size_t count = 0;
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
        chunkGrain_(std::clamp<std::size_t>(options.parallelSplitAbove / 4, 1, 16384)),
        forks_(threads_) {}

  BuildNode* buildRoot() {
    const std::size_t n = input_.triangles.size();
    Cell root;
    const Aabb& bounds = input_.bounds;
    for (int k = 0; k < 3; ++k) {
      root.box.lo[k] = bounds.lower[k];
      root.box.hi[k] = bounds.upper[k];
    }
    // One thread: the whole tree is one subtree, whose buffer has room for the left children
    // along a path. More: the top cells, down to a few subtrees per thread, split with every
    // thread, then the subtrees built side by side.
    topBelow_ =
        threads_ > 1 ? std::max<std::size_t>(options_.parallelSplitAbove, n / std::size_t(threads_)) : n;
    RefBuffer refs(n <= topBelow_ ? stackSize(n) : n);
    const ChunkPlan plan(n, chunkGrain_);
    std::vector<Box> chunkUsed(plan.chunks);
    parallelChunks(plan, threads_, [&](std::size_t chunk, std::size_t begin, std::size_t end) {
      Ref* out = refs.data();
      for (std::size_t t = begin; t < end; ++t) {
        const std::array<Vec3, 3> c = cornersOf(input_.triangles[t]);
        Ref& r = out[t];
        for (int k = 0; k < 3; ++k) {
          // + 0.0f turns -0 into +0, so equal positions compare (and bin) alike.
          r.lo[k] = std::min({c[0][k], c[1][k], c[2][k]}) + 0.0f;
          r.hi[k] = std::max({c[0][k], c[1][k], c[2][k]}) + 0.0f;
        }
        r.id = static_cast<std::uint32_t>(t);
        r.unused = 0;
        chunkUsed[chunk].extend(r);
      }
    });
    refs.wrote(n);
    for (const Box& used : chunkUsed) root.used.extend(used);
    BuildArena& arena = arenas_.create();
    BuildNode* top = buildTop(std::move(refs), n, root, 0, arena);
    std::sort(subtrees_.begin(), subtrees_.end(),
              [](const Subtree& a, const Subtree& b) { return a.count > b.count; });
    forks_.runEach(std::span<Subtree>(subtrees_), [&](Subtree& subtree) {
      buildDetached(std::move(subtree.refs), subtree.count, subtree.cell, subtree.depth, *subtree.slot);
    });
    return top;
  }

 private:
  // The working memory of one thread's subtree: references of the cells on the current path, each
  // cell's right child written over it and its left child at the end (the stack grows by the
  // left children along the path only).
  struct Scratch {
    RefBuffer stack;
    BinCounts counts;
    WindowRoom window;
    std::vector<std::uint32_t> leaf;
  };

  // Room for a subtree of n references: the left children along a path (grown when a deep path
  // needs more).
  static std::size_t stackSize(std::size_t n) { return n + n + n / 2 + 64; }

  bool leafByCount(std::size_t n, int depth) const {
    // No split can cost less than kt * emptySpaceFactor, so cells this small stay leaves.
    const float cheapestSplit = options_.traversalCost * std::min(1.0f, options_.emptySpaceFactor);
    return n == 0 || depth >= maxDepth_ || options_.intersectionCost * float(n) <= cheapestSplit;
  }

  // Big cells: binning and partition run over chunks on every thread; their children are kept in
  // buffers of their own (few cells, so few allocations).
  BuildNode* buildTop(RefBuffer refs, std::size_t n, const Cell& cell, int depth, BuildArena& arena) {
    if (n <= topBelow_ || leafByCount(n, depth)) {
      BuildNode* slot = arena.leaf({});
      subtrees_.push_back({std::move(refs), n, cell, depth, slot});
      return slot;
    }
    const BinGrid grid(cell, n);
    const ChunkPlan plan(n, chunkGrain_);
    std::vector<BinCounts> chunkCounts(plan.chunks);
    parallelChunks(plan, threads_, [&](std::size_t chunk, std::size_t begin, std::size_t end) {
      chunkCounts[chunk].clear(grid.bins);
      chunkCounts[chunk].count(refs.data() + begin, end - begin, grid, cell.box);
    });
    for (std::size_t c = 1; c < plan.chunks; ++c) chunkCounts[0].add(chunkCounts[c]);
    WindowRoom window;
    const Split split = splitFromBins(chunkCounts[0], grid, refs.data(), n, cell, options_, window);
    if (split.axis < 0 || split.cost >= options_.intersectionCost * float(n)) {
      BuildNode* slot = arena.leaf({});
      subtrees_.push_back({std::move(refs), n, cell, depth, slot});  // its subtree makes it a leaf
      return slot;
    }
    Children children = childCells(cell, split);
    const Partitioner partition{input_, options_, split, cell.box};
    std::vector<Children> chunkChildren(plan.chunks);
    std::vector<RefBuffer> chunkLeft(plan.chunks), chunkRight(plan.chunks);
    parallelChunks(plan, threads_, [&](std::size_t chunk, std::size_t begin, std::size_t end) {
      chunkLeft[chunk] = RefBuffer(end - begin);
      chunkRight[chunk] = RefBuffer(end - begin);
      partition(refs.data() + begin, end - begin, chunkRight[chunk].data(), chunkLeft[chunk].data(),
                chunkChildren[chunk]);
    });
    refs = RefBuffer();
    std::vector<std::size_t> leftAt(plan.chunks + 1, 0), rightAt(plan.chunks + 1, 0);
    for (std::size_t c = 0; c < plan.chunks; ++c) {
      const Children& part = chunkChildren[c];
      leftAt[c + 1] = leftAt[c] + part.leftCount;
      rightAt[c + 1] = rightAt[c] + part.rightCount;
      children.left.used.extend(part.left.used);
      children.right.used.extend(part.right.used);
    }
    const std::size_t nl = leftAt.back(), nr = rightAt.back();
    RefBuffer left(nl <= topBelow_ ? stackSize(nl) : nl), right(nr <= topBelow_ ? stackSize(nr) : nr);
    parallelChunks(plan, threads_, [&](std::size_t chunk, std::size_t, std::size_t) {
      std::copy_n(chunkLeft[chunk].data(), chunkChildren[chunk].leftCount, left.data() + leftAt[chunk]);
      std::copy_n(chunkRight[chunk].data(), chunkChildren[chunk].rightCount, right.data() + rightAt[chunk]);
      chunkLeft[chunk] = RefBuffer();
      chunkRight[chunk] = RefBuffer();
    });
    left.wrote(nl);
    right.wrote(nr);
    BuildNode* leftNode = buildTop(std::move(left), nl, children.left, depth + 1, arena);
    BuildNode* rightNode = buildTop(std::move(right), nr, children.right, depth + 1, arena);
    return arena.inner(split.axis, split.pos, leftNode, rightNode);
  }

  // A subtree with its own working memory and arena, built by the calling thread into `node`.
  void buildDetached(RefBuffer refs, std::size_t n, const Cell& cell, int depth, BuildNode& node) {
    Scratch scratch;
    scratch.stack = std::move(refs);
    scratch.stack.grow(stackSize(n), n);
    build(0, n, cell, depth, arenas_.create(), scratch, node);
  }

  // A cell of fewer than kSmallCell references, and its subtree: split exactly, children
  // smaller still (each gets at most the cell's references), so only their boxes are needed.
  void buildSmall(std::size_t begin, std::size_t n, const Box& box, int depth, BuildArena& arena,
                  Scratch& scratch, BuildNode& node) {
    if (leafByCount(n, depth)) return makeLeaf(scratch.stack.data() + begin, n, arena, scratch, node);
    const Split split = exactSmallSplit(scratch.stack.data() + begin, n, box, options_);
    if (split.axis < 0 || split.cost >= options_.intersectionCost * float(n)) {
      return makeLeaf(scratch.stack.data() + begin, n, arena, scratch, node);
    }
    const std::size_t leftBegin = begin + n;
    if (scratch.stack.size() < leftBegin + n) scratch.stack.grow(2 * (leftBegin + n), leftBegin);
    Ref* base = scratch.stack.data();
    const Partitioner partition{input_, options_, split, box};
    const auto [nl, nr] = partition.small(base + begin, n, base + begin, base + leftBegin);
    scratch.stack.wrote(leftBegin + nl);
    Box leftBox = box, rightBox = box;
    leftBox.hi[split.axis] = split.pos;
    rightBox.lo[split.axis] = split.pos;
    BuildNode* left = setInner(node, split, arena);
    buildSmall(leftBegin, nl, leftBox, depth + 1, arena, scratch, *left);
    buildSmall(begin, nr, rightBox, depth + 1, arena, scratch, *node.child[1]);
  }

  // Makes `node` the inner node of the split, with its two children allocated (next to each other,
  // before their subtrees); returns the left one.
  static BuildNode* setInner(BuildNode& node, const Split& split, BuildArena& arena) {
    node.axis = static_cast<std::int8_t>(split.axis);
    node.split = split.pos;
    node.child[0] = arena.node();
    node.child[1] = arena.node();
    return node.child[0];
  }

  // The cell whose references are scratch.stack[begin, begin + n) (the stack past them is free),
  // its subtree made in `node`.
  void build(std::size_t begin, std::size_t n, const Cell& cell, int depth, BuildArena& arena,
             Scratch& scratch, BuildNode& node) {
    if (n < kSmallCell) return buildSmall(begin, n, cell.box, depth, arena, scratch, node);
    if (leafByCount(n, depth)) return makeLeaf(scratch.stack.data() + begin, n, arena, scratch, node);
    const Split split =
        findSplit(scratch.stack.data() + begin, n, cell, options_, scratch.counts, scratch.window);
    if (split.axis < 0 || split.cost >= options_.intersectionCost * float(n)) {
      return makeLeaf(scratch.stack.data() + begin, n, arena, scratch, node);
    }
    const std::size_t leftBegin = begin + n;
    if (scratch.stack.size() < leftBegin + n) scratch.stack.grow(2 * (leftBegin + n), leftBegin);
    Ref* base = scratch.stack.data();
    Children children = childCells(cell, split);
    const Partitioner partition{input_, options_, split, cell.box};
    partition(base + begin, n, base + begin, base + leftBegin, children);
    scratch.stack.wrote(leftBegin + children.leftCount);
    BuildNode* left = setInner(node, split, arena);
    if (children.leftCount >= kForkAbove && forks_.spare()) {
      // A thread is idle (its subtree done): it takes the left child, with a copy of its references.
      RefBuffer leftRefs(stackSize(children.leftCount));
      std::copy_n(base + leftBegin, children.leftCount, leftRefs.data());
      leftRefs.wrote(children.leftCount);
      std::future<void> task = forks_.fork([&, refs = std::move(leftRefs)]() mutable {
        buildDetached(std::move(refs), children.leftCount, children.left, depth + 1, *left);
      });
      if (task.valid()) {
        scratch.stack.release(begin + children.rightCount);
        build(begin, children.rightCount, children.right, depth + 1, arena, scratch, *node.child[1]);
        forks_.join(task);
        return;
      }
    }
    build(leftBegin, children.leftCount, children.left, depth + 1, arena, scratch, *left);
    scratch.stack.release(begin + children.rightCount);  // the left subtree's references are done
    build(begin, children.rightCount, children.right, depth + 1, arena, scratch, *node.child[1]);
  }

  static void makeLeaf(const Ref* refs, std::size_t n, BuildArena& arena, Scratch& scratch, BuildNode& node) {
    scratch.leaf.resize(n);
    for (std::size_t i = 0; i < n; ++i) scratch.leaf[i] = refs[i].id;
    std::sort(scratch.leaf.begin(), scratch.leaf.end());
    arena.setLeaf(node, scratch.leaf);
  }

  const KdBuildInput& input_;
  const KdBuildOptions& options_;
  BuildArenas& arenas_;
  int maxDepth_;
  int threads_;
  std::size_t chunkGrain_;  // references per chunk of the parallel top
  std::size_t topBelow_ = 0;
  BuildThreads forks_;
  static constexpr std::size_t kForkAbove = 4096;  // smaller subtrees are not worth a thread
  std::vector<Subtree> subtrees_;
};

}  // namespace

KdTree KdTree::buildSah(std::span<const Vec3> positions, std::span<const MeshFace> faces,
                        const KdBuildOptions& options) {
  return KdTreeAssembler::build<BinnedBuilder>(positions, faces, options, /*withCorners=*/false,
                                               "kdtree-sah");
}

}  // namespace lancer
