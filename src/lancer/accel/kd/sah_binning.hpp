// Binned SAH for the top of the kd-tree: a big cell is split after counting its triangles' bounds
// into a fixed number of bins per axis, instead of sweeping sorted event lists, and its triangles
// are handed down as (triangle, clipped box) references, so no event list is sorted for the
// millions of triangles at the root. Below a size the exact sweep of Wald & Havran takes over.
// The idea and its cost model: Shevtsov, Soupikov & Kapustin 2007, "Highly parallel fast kd-tree
// construction for interactive ray tracing of dynamic scenes", section 3 (min-max binning).
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "lancer/accel/kd_tree.hpp"
#include "lancer/math/aabb.hpp"

namespace lancer {

// A triangle as a cell of the top levels holds it: the bounds of its part inside the cell.
struct BuildRef {
  std::uint32_t triangle;
  Aabb box;
};

// A split plane chosen by binning; axis < 0 when no split beats making the cell a leaf.
struct BinnedSplit {
  int axis = -1;
  float pos = 0;
  bool planarLeft = true;  // where a triangle lying in the plane goes
  float cost = 0;
};

// The cheapest plane among each axis's bin boundaries and the planes that cut empty space off the
// cell at its references' bounds, by the same cost model as the exact sweep (options' constants).
BinnedSplit findBinnedSplit(std::span<const BuildRef> refs, const Aabb& cell, const KdBuildOptions& options);

// Sends each reference to the side(s) of the plane it lies on. A triangle that crosses the plane is
// clipped to each child cell ("perfect splits") and dropped from a side it only touches at a point
// outside the cell, when it is big enough for that to pay (KdBuildOptions::clipAboveFraction);
// a smaller one goes to both sides with its box cut at the plane. Appends to `left` and `right`.
void partitionRefs(std::span<const BuildRef> refs, std::span<const std::array<Vec3, 3>> corners,
                   const BinnedSplit& split, const Aabb& leftCell, const Aabb& rightCell,
                   float clipAboveFraction, std::vector<BuildRef>& left, std::vector<BuildRef>& right);

}  // namespace lancer
