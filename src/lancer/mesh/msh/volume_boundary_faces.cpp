// The volume elements' boundary (volume_skin.hpp): every face's key is put in the bucket of its
// smallest node, each bucket is sorted on its own (it fits in cache), and a face whose key no other
// face shares is skin. A radix partition by the key's first digit, then a comparison sort of small
// ranges: both cores stream the elements' nodes once per pass, and nothing is grown by copies.
#include <algorithm>
#include <bit>
#include <memory>

#include "lancer/mesh/msh/volume_skin.hpp"
#include "lancer/util/huge_pages.hpp"
#include "lancer/util/parallel_for.hpp"

namespace lancer {
namespace {

// A face's sorted corners in two words, so that comparing keys is two integer comparisons: hi holds
// the smallest and second smallest node, lo the third and the fourth (kNoVertex for a triangle).
struct BucketedFace {
  std::uint64_t hi;
  std::uint64_t lo;
  std::uint32_t face;
  std::uint32_t group;
};

constexpr std::size_t kElementGrain = 16384;   // elements per chunk of the counting and scatter passes
constexpr std::size_t kFacesPerBucket = 2048;  // about 48 KiB of keys: a bucket sorts in L2

// Sorting networks for the corners of a face (the comparisons the compiler turns into min/max).
inline void order(std::uint32_t& a, std::uint32_t& b) {
  const std::uint32_t low = std::min(a, b);
  b = std::max(a, b);
  a = low;
}

inline BucketedFace bucketedFace(const int (*table)[4], int local, const std::uint32_t* nodes) {
  const int* corners = table[local];
  std::uint32_t a = nodes[corners[0]], b = nodes[corners[1]], c = nodes[corners[2]];
  std::uint32_t d = kNoVertex;
  if (corners[3] >= 0) {
    d = nodes[corners[3]];
    order(a, b), order(c, d), order(a, c), order(b, d), order(b, c);
  } else {
    order(a, b), order(b, c), order(a, b);
  }
  return {(std::uint64_t{a} << 32) | b, (std::uint64_t{c} << 32) | d, 0, 0};
}

// The smallest node of face `local`: all the counting pass needs, and what tells the scatter whether
// a face is in the slice at hand before its key is made.
inline std::uint32_t smallestCorner(const int (*table)[4], int local, const std::uint32_t* nodes) {
  const int* corners = table[local];
  const std::uint32_t least = std::min({nodes[corners[0]], nodes[corners[1]], nodes[corners[2]]});
  return corners[3] >= 0 ? std::min(least, nodes[corners[3]]) : least;
}

// For the faces of elements [begin, end), in face order: wants(smallest node) says whether the face
// is wanted, and visit(bucketedFace, faceIndex, group) gets those that are.
template <typename Wants, typename Visit>
void forEachFace(const MshVolumeElements& elements, std::uint64_t begin, std::uint64_t end, Wants&& wants,
                 Visit&& visit) {
  for (const MshVolumeElements::Run& run : elements.runs()) {
    const std::uint64_t runEnd = run.firstElement + elements.elementsIn(run);
    const std::uint64_t from = std::max(begin, run.firstElement), to = std::min(end, runEnd);
    if (from >= to) continue;
    const int(*table)[4] = volumeFaceCornerTable(run.type);
    const auto faces = static_cast<std::uint64_t>(run.faceCount);
    std::uint64_t face = run.firstFace + (from - run.firstElement) * faces;
    for (std::uint64_t e = from; e < to; ++e) {
      const std::uint32_t* nodes = elements.elementNodes(run, e);
      for (int local = 0; local < run.faceCount; ++local, ++face)
        if (wants(smallestCorner(table, local, nodes)))
          visit(bucketedFace(table, local, nodes), face, run.group);
    }
  }
}

}  // namespace

std::vector<VolumeBoundaryFace> findVolumeBoundary(const MshVolumeElements& elements, std::size_t nodeCount,
                                                   std::span<const std::uint64_t> volumeOfGroup,
                                                   bool severalVolumes, int threads, std::size_t sliceBytes) {
  const std::uint64_t faceCount = elements.faceCount();
  if (faceCount == 0) return {};
  // Buckets by the smallest node's high bits: about kFacesPerBucket faces each, at most 2^16.
  const int nodeBits = std::max(1, static_cast<int>(std::bit_width(std::max<std::size_t>(nodeCount, 1) - 1)));
  const int bucketBits =
      std::clamp(static_cast<int>(std::bit_width(faceCount / kFacesPerBucket)), 0, std::min(16, nodeBits));
  const int shift = 32 + nodeBits - bucketBits;  // of hi
  const std::size_t buckets = std::size_t{1} << bucketBits;
  const auto bucketOf = [&](std::uint32_t smallest) {
    return static_cast<std::size_t>(std::min<std::uint64_t>(smallest >> (shift - 32), buckets - 1));
  };

  // Counting pass: how many faces each chunk of elements puts in each bucket.
  const ChunkPlan chunks(elements.elementCount(), kElementGrain);
  std::vector<std::uint64_t> at(chunks.chunks * buckets, 0);  // counts, then each chunk's next slot
  parallelChunks(chunks, threads, [&](std::size_t k, std::size_t begin, std::size_t end) {
    std::uint64_t* count = at.data() + k * buckets;
    forEachFace(
        elements, begin, end,
        [&](std::uint32_t smallest) {
          ++count[bucketOf(smallest)];
          return false;
        },
        [](const BucketedFace&, std::uint64_t, std::uint32_t) {});
  });
  // Bucket by bucket, chunk by chunk: each bucket holds its faces in face order.
  std::vector<std::uint64_t> bucketStart(buckets + 1, 0);
  std::uint64_t next = 0;
  for (std::size_t b = 0; b < buckets; ++b) {
    bucketStart[b] = next;
    for (std::size_t k = 0; k < chunks.chunks; ++k) {
      const std::uint64_t count = at[k * buckets + b];
      at[k * buckets + b] = next;
      next += count;
    }
  }
  bucketStart[buckets] = next;

  // Scatter and sort, a slice of the buckets at a time: the keys of a slice fill one buffer, at most
  // sliceBytes, that every slice reuses (fresh memory costs more to fault in on first touch than the
  // extra passes over the elements take). In a slice's buckets, each sorted on its own, a face alone
  // with its key is skin (marked 1), the kept side of an interface is marked 2 and its outer face
  // listed; every other face is interior.
  const std::uint64_t sliceFaces = std::max<std::uint64_t>(sliceBytes / sizeof(BucketedFace), 1);
  const std::uint64_t bufferFaces = std::min(faceCount, sliceFaces);
  const std::unique_ptr<BucketedFace[]> keyed(new BucketedFace[bufferFaces]);
  adviseHugePages(keyed.get(), bufferFaces * sizeof(BucketedFace));
  std::vector<std::uint8_t> mark = vectorOnHugePages<std::uint8_t>(faceCount, 0);
  std::vector<VolumeBoundaryFace> outer;
  for (std::size_t sliceBegin = 0; sliceBegin < buckets;) {
    std::size_t sliceEnd = sliceBegin + 1;  // whole buckets, as many as the buffer holds (one at least)
    while (sliceEnd < buckets && bucketStart[sliceEnd + 1] - bucketStart[sliceBegin] <= bufferFaces)
      ++sliceEnd;
    const std::uint64_t base = bucketStart[sliceBegin];
    // A bucket larger than the buffer (a node in a huge number of faces) gets memory of its own.
    std::unique_ptr<BucketedFace[]> large;
    BucketedFace* buffer = keyed.get();
    if (bucketStart[sliceEnd] - base > bufferFaces) {
      large.reset(new BucketedFace[bucketStart[sliceEnd] - base]);
      buffer = large.get();
    }
    parallelChunks(chunks, threads, [&](std::size_t k, std::size_t begin, std::size_t end) {
      std::uint64_t* slot = at.data() + k * buckets;
      forEachFace(
          elements, begin, end,
          [&](std::uint32_t smallest) {
            const std::size_t bucket = bucketOf(smallest);
            return bucket >= sliceBegin && bucket < sliceEnd;
          },
          [&](BucketedFace key, std::uint64_t face, std::uint32_t group) {
            key.face = static_cast<std::uint32_t>(face);
            key.group = group;
            buffer[slot[bucketOf(static_cast<std::uint32_t>(key.hi >> 32))]++ - base] = key;
          });
    });
    const ChunkPlan bucketChunks(sliceEnd - sliceBegin, 1);
    std::vector<std::vector<VolumeBoundaryFace>> interfaces(bucketChunks.chunks);
    parallelChunks(bucketChunks, threads, [&](std::size_t k, std::size_t begin, std::size_t end) {
      for (std::size_t b = sliceBegin + begin; b < sliceBegin + end; ++b) {
        BucketedFace* from = buffer + (bucketStart[b] - base);
        BucketedFace* to = buffer + (bucketStart[b + 1] - base);
        std::sort(from, to, [](const BucketedFace& x, const BucketedFace& y) {
          return x.hi != y.hi ? x.hi < y.hi : x.lo < y.lo;
        });
        for (BucketedFace* i = from; i < to;) {
          BucketedFace* j = i + 1;
          while (j < to && j->hi == i->hi && j->lo == i->lo) ++j;
          if (j == i + 1) {
            mark[i->face] = 1;
          } else if (severalVolumes && j == i + 2 && i->group != (i + 1)->group) {
            const std::uint64_t volumeA = volumeOfGroup[i->group], volumeB = volumeOfGroup[(i + 1)->group];
            if (volumeA != volumeB) {
              const BucketedFace& kept = volumeA < volumeB ? *i : *(i + 1);
              const BucketedFace& other = volumeA < volumeB ? *(i + 1) : *i;
              mark[kept.face] = 2;
              interfaces[k].push_back({kept.face, other.face});
            }
          }
          i = j;
        }
      }
    });
    for (const auto& list : interfaces) outer.insert(outer.end(), list.begin(), list.end());
    sliceBegin = sliceEnd;
  }
  at = std::vector<std::uint64_t>();

  // The interfaces by face, then every marked face in face order (chunks count, then write).
  std::sort(outer.begin(), outer.end(),
            [](const VolumeBoundaryFace& x, const VolumeBoundaryFace& y) { return x.face < y.face; });
  const ChunkPlan faceChunks(faceCount, 65536);
  std::vector<std::uint64_t> marked(faceChunks.chunks + 1, 0), interfacesBefore(faceChunks.chunks + 1, 0);
  parallelChunks(faceChunks, threads, [&](std::size_t k, std::size_t begin, std::size_t end) {
    for (std::size_t f = begin; f < end; ++f) {
      marked[k + 1] += mark[f] != 0;
      interfacesBefore[k + 1] += mark[f] == 2;
    }
  });
  for (std::size_t k = 0; k < faceChunks.chunks; ++k) {
    marked[k + 1] += marked[k];
    interfacesBefore[k + 1] += interfacesBefore[k];
  }
  std::vector<VolumeBoundaryFace> boundary(marked.back());
  parallelChunks(faceChunks, threads, [&](std::size_t k, std::size_t begin, std::size_t end) {
    std::uint64_t out = marked[k], nextInterface = interfacesBefore[k];
    for (std::size_t f = begin; f < end; ++f) {
      if (mark[f] == 1) boundary[out++] = {static_cast<std::uint32_t>(f), kNoVertex};
      if (mark[f] == 2) boundary[out++] = outer[nextInterface++];
    }
  });
  return boundary;
}

}  // namespace lancer
