// Per-mesh cut views (`[[mesh.clip]]`): clip planes that remove only the faces of their own mesh.
// A ray may pass a removed face of one mesh and hit the next mesh behind it, so these cannot narrow
// the ray to one interval as scene planes do; the accelerators' clipped queries ask `keeps` instead.
#pragma once

#include <algorithm>
#include <cstdint>
#include <span>
#include <vector>

#include "lancer/scene/clip_planes.hpp"

namespace lancer {

// One mesh's own planes: its faces are a contiguous run of the scene's (meshes are appended whole).
struct FaceClipRange {
  std::uint32_t faceBegin = 0, faceEnd = 0;    // [faceBegin, faceEnd) in scene face numbering
  std::uint32_t planeBegin = 0, planeEnd = 0;  // [planeBegin, planeEnd) in FaceClipSets::planes
};

struct FaceClipSets {
  std::vector<FaceClipRange> ranges;  // sorted by face, disjoint; only meshes that have planes
  std::vector<ClipPlane> planes;      // scene space
  std::vector<std::uint8_t> caps;     // per plane: 1 when closed shells it cuts are capped

  bool empty() const { return ranges.empty(); }

  // The run holding `face`, or nullptr when its mesh has no planes of its own.
  const FaceClipRange* rangeOf(std::uint32_t face) const {
    const auto it = std::upper_bound(ranges.begin(), ranges.end(), face,
                                     [](std::uint32_t f, const FaceClipRange& r) { return f < r.faceEnd; });
    return it != ranges.end() && face >= it->faceBegin ? &*it : nullptr;
  }
  std::span<const ClipPlane> planesOf(const FaceClipRange& range) const {
    return {planes.data() + range.planeBegin, range.planeEnd - range.planeBegin};
  }

  // True when a hit on `face` at ray parameter t is on the kept side of its mesh's own planes. The
  // same interval test as scene planes (open at both ends), so a face is cut exactly as a scene
  // plane in the same place would cut it. Called only for candidate hits, never per face.
  bool keeps(const Ray& ray, std::uint32_t face, float t) const {
    const FaceClipRange* range = rangeOf(face);
    if (!range) return true;
    const ClipInterval kept = clipRay(ray, planesOf(*range));
    return t > kept.enter && t < kept.exit;
  }
};

}  // namespace lancer
