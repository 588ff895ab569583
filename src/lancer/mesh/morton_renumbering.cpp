#include "lancer/mesh/morton_renumbering.hpp"

#include <utility>

#include "lancer/util/check.hpp"
#include "lancer/util/huge_page_array.hpp"
#include "lancer/util/huge_pages.hpp"
#include "lancer/util/morton_order.hpp"
#include "lancer/util/parallel_for.hpp"
#include "lancer/util/prefetch.hpp"

namespace lancer {
namespace {

constexpr std::size_t kGrain = 1 << 15;
// Gathers in the new order read the old arrays all over: each loop asks for the item it needs this
// many items ahead, so that the misses overlap (the loops have nothing else to wait for).
constexpr std::size_t kAhead = 16;

using Order = std::vector<std::uint32_t>;

// The box of the positions (every vertex: one the faces do not use still gets a number).
void positionBox(const std::vector<Vec3>& positions, int threads, float lo[3], float hi[3]) {
  const ChunkPlan plan(positions.size(), kGrain);
  std::vector<std::pair<Vec3, Vec3>> boxes(plan.chunks);
  parallelChunks(plan, threads, [&](std::size_t chunk, std::size_t begin, std::size_t end) {
    Vec3 low = positions[begin], high = positions[begin];
    for (std::size_t v = begin; v < end; ++v) {
      const Vec3& p = positions[v];
      low = {std::min(low.x, p.x), std::min(low.y, p.y), std::min(low.z, p.z)};
      high = {std::max(high.x, p.x), std::max(high.y, p.y), std::max(high.z, p.z)};
    }
    boxes[chunk] = {low, high};
  });
  const auto& [firstLow, firstHigh] = boxes.front();
  lo[0] = firstLow.x, lo[1] = firstLow.y, lo[2] = firstLow.z;
  hi[0] = firstHigh.x, hi[1] = firstHigh.y, hi[2] = firstHigh.z;
  for (const auto& [low, high] : boxes) {
    lo[0] = std::min(lo[0], low.x), lo[1] = std::min(lo[1], low.y), lo[2] = std::min(lo[2], low.z);
    hi[0] = std::max(hi[0], high.x), hi[1] = std::max(hi[1], high.y), hi[2] = std::max(hi[2], high.z);
  }
}

// The order of the items whose codes code(i) gives: order[new] = old.
template <typename Code>
std::shared_ptr<Order> mortonOrder(std::size_t count, int threads, Code&& code) {
  // The keys and the sort's scratch are written whole before they are read: not initialised.
  HugePageArray<std::uint64_t> keys(count), scratch(count);
  parallelFor(count, threads, kGrain, [&](std::size_t i) { keys[i] = std::uint64_t(code(i)) << 32 | i; });
  const std::uint64_t* sorted = sortMortonKeys(keys.data(), scratch.data(), count, threads);
  auto order = std::make_shared<Order>(vectorOnHugePages<std::uint32_t>(count));
  parallelFor(count, threads, kGrain,
              [&](std::size_t i) { (*order)[i] = static_cast<std::uint32_t>(sorted[i]); });
  return order;
}

// items[new] = items[order[new]], `width` values an item; an array of another length (an empty
// optional one) is left as it is.
template <typename T>
void permute(std::vector<T>& items, const Order& order, std::size_t width, int threads) {
  if (items.size() != order.size() * width) return;
  std::vector<T> permuted = vectorOnHugePages<T>(items.size());
  parallelChunks(ChunkPlan(order.size(), kGrain), threads,
                 [&](std::size_t, std::size_t begin, std::size_t end) {
                   for (std::size_t i = begin; i < end; ++i) {
                     if (i + kAhead < end)
                       prefetchLine(items.data() + std::size_t(order[i + kAhead]) * width);
                     const T* from = items.data() + std::size_t(order[i]) * width;
                     std::copy(from, from + width, permuted.data() + i * width);
                   }
                 });
  items.swap(permuted);
}

// A face array to gather in the new order, when it holds one item a face (optional ones may be empty).
template <typename T>
struct FaceArray {
  std::vector<T>* items;
  std::vector<T> permuted;
  FaceArray(std::vector<T>& array, std::size_t faceCount)
      : items(array.size() == faceCount ? &array : nullptr) {
    if (items) permuted = vectorOnHugePages<T>(faceCount);
  }
  void prefetch(std::uint32_t from) const {
    if (items) prefetchLine(items->data() + from);
  }
  void gather(std::size_t to, std::uint32_t from) {
    if (items) permuted[to] = (*items)[from];
  }
  void finish() {
    if (items) items->swap(permuted);
  }
};

// The faces' tags, edge masks and volume sides in the new order, in one pass: the reads of all of
// them for one face overlap.
void permuteFaceArrays(Mesh& mesh, const Order& order, int threads) {
  const std::size_t n = order.size();
  FaceArray<std::int32_t> physical(mesh.facePhysicalTag, n), entity(mesh.faceEntityTag, n);
  FaceArray<std::uint8_t> edges(mesh.faceEdgeMask, n);
  FaceVolumeSides& sides = mesh.volumeSides;
  FaceArray<FaceSide> side(sides.side, n);
  FaceArray<std::int32_t> outerPhysical(sides.outerPhysicalTag, n), outerEntity(sides.outerEntityTag, n);
  parallelChunks(ChunkPlan(n, kGrain), threads, [&](std::size_t, std::size_t begin, std::size_t end) {
    for (std::size_t f = begin; f < end; ++f) {
      if (f + kAhead < end) {
        const std::uint32_t ahead = order[f + kAhead];
        physical.prefetch(ahead), entity.prefetch(ahead), edges.prefetch(ahead);
        side.prefetch(ahead), outerPhysical.prefetch(ahead), outerEntity.prefetch(ahead);
      }
      const std::uint32_t from = order[f];
      physical.gather(f, from), entity.gather(f, from), edges.gather(f, from);
      side.gather(f, from), outerPhysical.gather(f, from), outerEntity.gather(f, from);
    }
  });
  physical.finish(), entity.finish(), edges.finish(), side.finish(), outerPhysical.finish(),
      outerEntity.finish();
}

// Per corner slot of the renumbered faces, the slot of the faces before that holds its value: a
// corner's slot is its vertex's rank among the face's (cornerSlot), which the new numbers change.
std::shared_ptr<Order> cornerSlotOrder(const std::vector<MeshFace>& oldFaces,
                                       const std::vector<MeshFace>& newFaces, const Order& faceOrder,
                                       int threads) {
  auto order = std::make_shared<Order>(vectorOnHugePages<std::uint32_t>(faceOrder.size() * kCornerSlots));
  parallelFor(faceOrder.size(), threads, kGrain, [&](std::size_t f) {
    const std::uint32_t before = faceOrder[f];
    std::uint32_t* slots = order->data() + f * kCornerSlots;
    for (std::size_t s = 0; s < kCornerSlots; ++s)
      slots[s] = static_cast<std::uint32_t>(before * kCornerSlots + s);
    const MeshFace& face = newFaces[f];
    for (int c = 0; c < face.cornerCount(); ++c)
      slots[cornerSlot(face, c)] =
          static_cast<std::uint32_t>(before * kCornerSlots + cornerSlot(oldFaces[before], c));
  });
  return order;
}

void permuteField(MeshField& field, const std::shared_ptr<const Order>& order, int threads) {
  const auto width = static_cast<std::size_t>(field.components);
  LANCER_DCHECK(field.itemCount(), ==, order->size());  // the reader gives every item a value
  if (field.itemCount() != order->size()) return;
  if (field.isStored()) {
    // Read back later in the file's order: it is put in this one then (fieldValues).
    auto stored = std::make_shared<StoredFieldValues>(*field.stored);
    if (stored->order) {  // renumbered twice: compose the two orders
      auto both = std::make_shared<Order>(order->size());
      for (std::size_t i = 0; i < order->size(); ++i) (*both)[i] = (*stored->order)[(*order)[i]];
      stored->order = std::move(both);
    } else {
      stored->order = order;
    }
    field.stored = std::move(stored);
    return;
  }
  if (width > 0) permute(field.values, *order, width, threads);
}

}  // namespace

MeshRenumbering renumberInMortonOrder(Mesh& mesh, int threads) {
  const std::size_t vertexCount = mesh.positions.size();
  const std::size_t faceCount = mesh.faces.size();
  MeshRenumbering renumbering;
  if (vertexCount == 0) {
    renumbering.originalVertex = std::make_shared<Order>();
    renumbering.originalFace = std::make_shared<Order>(faceCount);
    return renumbering;
  }
  float lo[3], hi[3];
  positionBox(mesh.positions, threads, lo, hi);
  const MortonGrid grid(lo, hi);

  // Faces first, by their centroids at the old numbers; then the vertices, by their positions.
  const std::vector<Vec3>& positions = mesh.positions;
  const std::vector<MeshFace>& faces = mesh.faces;
  std::shared_ptr<Order> faceOrder = mortonOrder(faceCount, threads, [&](std::size_t f) {
    if (f + kAhead < faceCount)
      for (int c = 0; c < 3; ++c) prefetchLine(positions.data() + faces[f + kAhead].vertex[c]);
    const MeshFace& face = faces[f];
    Vec3 sum{};
    const int corners = face.cornerCount();
    for (int c = 0; c < corners; ++c) sum = sum + positions[face.vertex[c]];
    const float centroid[3] = {sum.x / corners, sum.y / corners, sum.z / corners};
    return grid.code(centroid);
  });
  std::shared_ptr<Order> vertexOrder = mortonOrder(vertexCount, threads, [&](std::size_t v) {
    const float p[3] = {positions[v].x, positions[v].y, positions[v].z};
    return grid.code(p);
  });
  HugePageArray<std::uint32_t> newVertex(vertexCount);  // every entry written below
  parallelFor(vertexCount, threads, kGrain,
              [&](std::size_t v) { newVertex[(*vertexOrder)[v]] = static_cast<std::uint32_t>(v); });

  std::vector<MeshFace> newFaces = vectorOnHugePages<MeshFace>(faceCount);
  const Order& faceFrom = *faceOrder;
  parallelChunks(ChunkPlan(faceCount, kGrain), threads, [&](std::size_t, std::size_t begin, std::size_t end) {
    for (std::size_t f = begin; f < end; ++f) {
      // Two steps ahead: the face, then (once it has come) its vertices' new numbers.
      if (f + 2 * kAhead < end) prefetchLine(faces.data() + faceFrom[f + 2 * kAhead]);
      if (f + kAhead < end) {
        const MeshFace& ahead = faces[faceFrom[f + kAhead]];
        for (int c = 0; c < 3; ++c) prefetchLine(newVertex.data() + ahead.vertex[c]);
      }
      const MeshFace& face = faces[faceFrom[f]];
      MeshFace& renumbered = newFaces[f];
      for (int c = 0; c < face.cornerCount(); ++c) renumbered.vertex[c] = newVertex[face.vertex[c]];
    }
  });
  std::shared_ptr<Order> cornerOrder;
  for (const MeshField& field : mesh.fields)
    if (field.at == FieldAt::kCorner) {
      cornerOrder = cornerSlotOrder(mesh.faces, newFaces, *faceOrder, threads);
      break;
    }
  mesh.faces.swap(newFaces);
  std::vector<MeshFace>().swap(newFaces);
  permute(mesh.positions, *vertexOrder, 1, threads);

  permuteFaceArrays(mesh, *faceOrder, threads);
  for (MeshField& field : mesh.fields) {
    switch (field.at) {
      case FieldAt::kNode:
        permuteField(field, vertexOrder, threads);
        break;
      case FieldAt::kElement:
        permuteField(field, faceOrder, threads);
        break;
      case FieldAt::kCorner:
        permuteField(field, cornerOrder, threads);
        break;
    }
  }
  renumbering.originalVertex = std::move(vertexOrder);
  renumbering.originalFace = std::move(faceOrder);
  return renumbering;
}

std::size_t renumberLargeMeshesInMortonOrder(std::vector<Mesh>& meshes, int threads) {
  std::size_t renumbered = 0;
  for (Mesh& mesh : meshes) {
    if (mesh.faceCount() < kMortonRenumberingMinFaces) continue;
    renumberInMortonOrder(mesh, threads);
    ++renumbered;
  }
  return renumbered;
}

}  // namespace lancer
