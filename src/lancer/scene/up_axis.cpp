#include "lancer/scene/up_axis.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "lancer/mesh/face_geometry.hpp"
#include "lancer/util/parallel_for.hpp"

namespace lancer {
namespace {

constexpr Vec3d kAxes[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
// The 3/4 view in a frame's own terms: right, above, in front (camera.cpp's historical y-up view).
constexpr double kViewRight = 0.9, kViewUp = 0.65, kViewFront = 1.3;
constexpr double kPlanarExtent = 1e-6;  // of the largest extent
constexpr double kFlatCosine = 0.9962;  // cos 5 degrees
constexpr double kOnSide = 0.05;  // of the largest extent: a face on (or near: feet, bolt heads) a box side
constexpr double kNearTie = 0.02;
// A base is at least this share of the surface: a sphere's flat pole facets are not a base.
constexpr double kMinBaseShare = 0.02;
// Faces per chunk of the passes over a mesh's faces.
constexpr std::size_t kFacesPerChunk = 16384;
// Preference on near ties: z, then y, then x.
constexpr int kPreference[3] = {2, 1, 0};

// The face's area, and its unit normal in `normal` (zero for a degenerate face).
double areaAndNormal(const Mesh& mesh, const MeshFace& face, Vec3d& normal) {
  const Vec3d twice = twiceVectorArea(mesh.positions, face);
  const double area2 = length(twice);
  normal = area2 > 0 ? twice * (1.0 / area2) : Vec3d{};
  return 0.5 * area2;
}

// The axis with the largest (or smallest) score; a later axis in kPreference must beat the best so
// far by more than kNearTie. With `largest`, axes scoring 0 never win (-1 when all do).
int bestAxis(const double score[3], bool largest) {
  int best = -1;
  for (int axis : kPreference) {
    if (largest && !(score[axis] > 0)) continue;
    const bool better = best < 0 || (largest ? score[axis] > score[best] * (1 + kNearTie)
                                             : score[axis] < score[best] * (1 - kNearTie));
    if (better) best = axis;
  }
  return best;
}

}  // namespace

std::optional<UpAxis> parseUpAxis(std::string_view name) {
  for (std::size_t i = 0; i < kUpAxisNames.size(); ++i)
    if (kUpAxisNames[i] == name) return static_cast<UpAxis>(i);
  return std::nullopt;
}

Vec3d upVector(UpAxis axis) {
  const int index = static_cast<int>(axis);
  return kAxes[index % 3] * (index < 3 ? 1.0 : -1.0);
}

ViewFrame threeQuarterFrame(UpAxis axis) {
  const Vec3d up = upVector(axis);
  // Right is +x unless x is the up axis (then +y); the front follows from the right-handed frame.
  const Vec3d right = std::abs(up.x) > 0 ? kAxes[1] : kAxes[0];
  const Vec3d front = cross(right, up);
  return {right, up, right * kViewRight + up * kViewUp + front * kViewFront};
}

void applyUpAxis(CameraSettings& camera, UpAxis axis) {
  const ViewFrame frame = threeQuarterFrame(axis);
  camera.up = frame.up;
  camera.viewFrom = frame.toViewer;
  camera.viewChosen = true;
}

std::optional<PlanarView> planarView(const Vec3d& extent) {
  const double largest = std::max({extent.x, extent.y, extent.z});
  if (!(largest > 0)) return std::nullopt;
  const double extents[3] = {extent.x, extent.y, extent.z};
  for (int axis : kPreference) {
    if (extents[axis] > kPlanarExtent * largest) continue;
    static constexpr UpAxis kScreenUp[3] = {UpAxis::Z, UpAxis::MinusZ, UpAxis::Y};
    PlanarView view;
    view.up = kScreenUp[axis];
    view.axis = axis;
    view.frame.up = upVector(view.up);
    view.frame.toViewer = kAxes[axis];
    view.frame.right = cross(-view.frame.toViewer, view.frame.up);
    return view;
  }
  return std::nullopt;
}

Aabb faceBoundsOnThreads(const Mesh& mesh, int threads) {
  const ChunkPlan plan(mesh.faces.size(), kFacesPerChunk);
  std::vector<Aabb> boxes(plan.chunks);
  parallelChunks(plan, threads, [&](std::size_t chunk, std::size_t begin, std::size_t end) {
    Aabb box;
    for (std::size_t f = begin; f < end; ++f) {
      const MeshFace& face = mesh.faces[f];
      for (int c = 0; c < face.cornerCount(); ++c) box.extend(mesh.positions[face.vertex[c]]);
    }
    boxes[chunk] = box;
  });
  Aabb bounds;
  for (const Aabb& box : boxes) bounds.extend(box);
  return bounds;
}

UpGuess guessUpAxis(const Mesh& mesh, int threads) {
  return guessUpAxis(mesh, faceBoundsOnThreads(mesh, threads), threads);
}

UpGuess guessUpAxis(const Mesh& mesh, const Aabb& bounds, int threads) {
  const Vec3d extent = toDouble(bounds.extent());
  const double largest = std::max({extent.x, extent.y, extent.z});
  UpGuess guess;
  auto choose = [&](UpAxis up, const char* reason) {
    guess.up = up;
    guess.frame = threeQuarterFrame(up);
    guess.reason = reason;
  };
  if (!(largest > 0)) {
    choose(UpAxis::Y, "empty");
    return guess;
  }
  // 1. Planar: straight on, from the + side of the plane's axis.
  const double extents[3] = {extent.x, extent.y, extent.z};
  if (const std::optional<PlanarView> view = planarView(extent)) {
    guess.up = view->up;
    guess.frame = view->frame;
    guess.planar = true;
    guess.reason = view->axis == 0 ? "planar in x" : (view->axis == 1 ? "planar in y" : "planar in z");
    return guess;
  }
  // 2. Base area: faces lying flat on the box's sides across each axis.
  // Summed chunk by chunk, the chunks' sums added in order: the same areas on any number of threads.
  struct Areas {
    double base[3] = {0, 0, 0};
    double total = 0;
  };
  const double onSide = kOnSide * largest;
  const ChunkPlan plan(mesh.faces.size(), kFacesPerChunk);
  std::vector<Areas> chunkAreas(plan.chunks);
  parallelChunks(plan, threads, [&](std::size_t chunk, std::size_t begin, std::size_t end) {
    Areas areas;
    for (std::size_t f = begin; f < end; ++f) {
      const MeshFace& face = mesh.faces[f];
      Vec3d normal;
      const double area = areaAndNormal(mesh, face, normal);
      areas.total += area;
      for (int axis = 0; axis < 3; ++axis) {
        if (std::abs(normal[axis]) < kFlatCosine) continue;
        const double position = mesh.positions[face.vertex[0]][axis];
        if (std::abs(position - bounds.lower[axis]) <= onSide ||
            std::abs(position - bounds.upper[axis]) <= onSide)
          areas.base[axis] += area;
      }
    }
    chunkAreas[chunk] = areas;
  });
  double base[3] = {0, 0, 0};
  double total = 0;
  for (const Areas& areas : chunkAreas) {
    for (int axis = 0; axis < 3; ++axis) base[axis] += areas.base[axis];
    total += areas.total;
  }
  for (double& area : base)
    if (area < kMinBaseShare * total) area = 0;
  static constexpr UpAxis kUp[3] = {UpAxis::X, UpAxis::Y, UpAxis::Z};
  if (const int axis = bestAxis(base, true); axis >= 0) {
    choose(kUp[axis], "base area");
    return guess;
  }
  // 3. No flat side: the thinnest direction is the height.
  choose(kUp[bestAxis(extents, false)], "smallest extent");
  return guess;
}

}  // namespace lancer
