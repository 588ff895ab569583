#include "lancer/scene/render_overrides.hpp"

#include <fmt/format.h>

#include <cmath>

#include "lancer/scene/quick_look.hpp"

namespace lancer {

void applyRenderOverrides(SceneDescription& description, const RenderOverrides& overrides,
                          const Mesh* quickLookMesh) {
  RenderSettings& settings = description.render;
  if (overrides.width) settings.width = *overrides.width;
  if (overrides.height) settings.height = *overrides.height;
  if (overrides.maxDepth) settings.maxDepth = *overrides.maxDepth;
  if (overrides.srgb) settings.srgb = *overrides.srgb;
  if (overrides.toneMap) settings.toneMap = *overrides.toneMap;
  if (overrides.exposure) settings.exposure = *overrides.exposure;
  if (overrides.bitDepth) settings.bitDepth = *overrides.bitDepth;
  if (overrides.denoise) settings.denoise = *overrides.denoise;
  if (overrides.transparentBackground) settings.transparentBackground = *overrides.transparentBackground;
  if (overrides.sampler) settings.sampler = *overrides.sampler;
  if (overrides.samples) settings.samples = *overrides.samples;
  // The quick look's fill sits at the automatic camera, whose distance depends on the image's aspect.
  if (quickLookMesh && (overrides.width || overrides.height))
    placeQuickLookLights(description, *quickLookMesh);
  if (overrides.integrator) settings.integrator = *overrides.integrator;
  if (overrides.noise) settings.noise = *overrides.noise;
  if (overrides.edges)
    for (MeshInstance& mesh : description.meshes)
      if (!mesh.edges) mesh.edges = EdgeSettings{};
  applyLookOverride(description, overrides);
  // The Whitted model's grids need a square count; path and AO take any.
  const int root = static_cast<int>(std::lround(std::sqrt(settings.samples)));
  if (settings.integrator == IntegratorKind::Whitted && settings.sampler != SamplerKind::Adaptive &&
      root * root != settings.samples)
    throw InputError(
        SourceLocation{overrides.samplesName},
        fmt::format("{} samples cannot form an n x n grid: use a perfect square (1, 4, 9, 16, ...)",
                    settings.samples));
  if (overrides.shading) {
    settings.shading = *overrides.shading;
    for (MeshInstance& mesh : description.meshes) mesh.shading.reset();
  }
}

void applyLookOverride(SceneDescription& description, const RenderOverrides& overrides) {
  if (!overrides.look) return;
  RenderSettings& settings = description.render;
  applyLook(description, *overrides.look);
  if (overrides.samples) settings.samples = *overrides.samples;
  if (overrides.noise) settings.noise = *overrides.noise;
  if (overrides.integrator) settings.integrator = *overrides.integrator;
}

}  // namespace lancer
