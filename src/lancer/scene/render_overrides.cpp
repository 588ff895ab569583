#include "lancer/scene/render_overrides.hpp"

#include <fmt/format.h>

#include <cmath>

#include "lancer/image/pixel_encoding.hpp"
#include "lancer/scene/quick_look.hpp"
#include "lancer/scene/render_limits.hpp"
#include "lancer/scene/results/annotation_kinds.hpp"
#include "lancer/scene/results/color_by.hpp"
#include "lancer/scene/setting_checks.hpp"

namespace lancer {
namespace {

// The meshes coloured by a field, which `option` (a colour range, legend, isolines, bands) goes on;
// an error at the option when there is none.
std::vector<MeshInstance*> colouredMeshes(SceneDescription& description, const std::string& option) {
  std::vector<MeshInstance*> coloured;
  for (MeshInstance& mesh : description.meshes)
    if (mesh.colorBy) coloured.push_back(&mesh);
  if (coloured.empty())
    throw InputError(
        SourceLocation{option},
        fmt::format("{} goes with a field's colours, and no mesh is coloured: {} (or color_by = {{ field "
                    "= \"...\" }} in the scene's [[mesh]])",
                    option,
                    option.starts_with("--") ? "add --color-by FIELD"
                                             : "colour it with Scene.quick_look(mesh, color_by=FIELD)"));
  return coloured;
}

std::string vectorText(const Vec3d& v) { return fmt::format("[{}, {}, {}]", v.x, v.y, v.z); }

// A count of `option` in [1, most].
int checkedCount(int count, int most, const std::string& option, const char* what) {
  if (count < 1 || count > most)
    throw InputError(SourceLocation{option},
                     fmt::format("{} {} is not a number of {} from 1 to {}", option, count, what, most));
  return count;
}

void applyAnnotationOverrides(SceneDescription& description, const RenderOverrides& overrides) {
  const auto name = [&](const char* option) { return overrides.optionPrefix + option; };
  // First what is drawn inside the volume, whose colours the options below may set.
  for (SliceSpec slice : overrides.slices) {
    // The option that gave it, when its reader said (Python's slices=), else --slice.
    if (slice.where.file.empty()) slice.where = SourceLocation{name("slice")};
    if ((slice.point && !isFinite(*slice.point)) || !isFinite(slice.normal) || length(slice.normal) == 0)
      throw InputError(
          slice.where,
          fmt::format("a slice needs a finite point and a normal other than [0, 0, 0], found normal {}",
                      vectorText(slice.normal)));
    slice.normal = normalize(slice.normal);
    for (MeshInstance& mesh : description.meshes) mesh.volume.slices.push_back(slice);
  }
  for (MeshInstance& mesh : description.meshes) {
    if (overrides.skin) mesh.volume.skin = overrides.skin;
    if (overrides.isosurfaces && !mesh.volume.isosurfaces) {
      mesh.volume.isosurfaces = overrides.isosurfaces;
      mesh.volume.isosurfaces->where = SourceLocation{name("isosurfaces")};
    }
    if (overrides.streamlines && !mesh.volume.streamlines) {
      mesh.volume.streamlines = overrides.streamlines;
      mesh.volume.streamlines->where = SourceLocation{name("streamlines")};
    }
  }
  for (const AnnotationSpec& annotation : overrides.annotations)
    for (MeshInstance& mesh : description.meshes) setAnnotation(mesh, annotation);
  // Isosurfaces, field lines and arrows in a field's colours on a mesh that is not coloured itself:
  // the field's range and legend are the mesh's (not painted on it), so that --range, --legend,
  // --bands and --isolines reach them. Arrows alone draw their legend over their own range.
  for (MeshInstance& mesh : description.meshes) {
    if (mesh.colorBy) continue;
    std::optional<std::string> field;
    if (const auto& iso = mesh.volume.isosurfaces; iso && !iso->color)
      field = iso->colorBy.value_or(iso->field);
    if (const auto& lines = mesh.volume.streamlines; !field && lines && !lines->color)
      field = lines->colorBy.value_or(lines->field);
    ColorBy colors;
    if (!field) {
      for (const AnnotationSpec& annotation : mesh.annotations)
        if (const ArrowSpec* arrows = std::get_if<ArrowSpec>(&annotation); arrows && !arrows->color) {
          field = arrows->field;
          colors.ownLegend = false;
          break;
        }
    }
    if (!field) continue;
    colors.field = *field;
    colors.paintsSurface = false;
    mesh.colorBy = colors;
  }
  if (overrides.colorMap)
    for (MeshInstance* mesh : colouredMeshes(description, name("color_map")))
      mesh->colorBy->map = *overrides.colorMap;
  if (overrides.scale)
    for (MeshInstance* mesh : colouredMeshes(description, name("log"))) {
      mesh->colorBy->scale = *overrides.scale;
      mesh->colorBy->logOption = *overrides.scale == ColorScale::Log ? name("log") : std::string();
    }
  if (overrides.range) {
    const auto [low, high] = *overrides.range;
    for (MeshInstance* mesh : colouredMeshes(description, name("range"))) {
      if (const std::string problem = colorRangeProblem(name("range"), low, high, mesh->colorBy->scale);
          !problem.empty())
        throw InputError(SourceLocation{name("range")}, problem);
      mesh->colorBy->range = *overrides.range;
      mesh->colorBy->perStepRange = false;
    }
  }
  if (overrides.legend) {
    if (*overrides.legend == LegendPlacement::None) {
      for (MeshInstance& mesh : description.meshes)
        if (mesh.colorBy) mesh.colorBy->legend = LegendPlacement::None;
    } else {
      for (MeshInstance* mesh : colouredMeshes(description, name("legend")))
        mesh->colorBy->legend = overrides.legend;
    }
  }
  if (overrides.bands) {
    const int bands = checkedCount(*overrides.bands, kMaxBands, name("bands"), "colour bands");
    for (MeshInstance* mesh : colouredMeshes(description, name("bands"))) mesh->colorBy->bands = bands;
  }
  if (overrides.isolines) {
    const int count = checkedCount(*overrides.isolines, kMaxIsolineCount, name("isolines"), "isolines");
    for (MeshInstance* mesh : colouredMeshes(description, name("isolines"))) {
      // The lines of the field the mesh is coloured by, as gmsh's iso-values of a view.
      IsolineSpec lines;
      lines.field = mesh->colorBy->field;
      lines.component = mesh->colorBy->component;
      lines.step = mesh->colorBy->step;
      lines.count = count;
      lines.where = SourceLocation{name("isolines")};
      mesh->isolines = lines;
    }
  }
  for (ClipSettings clip : overrides.clips) {
    if (!isFinite(clip.point) || !isFinite(clip.normal) || length(clip.normal) == 0)
      throw InputError(SourceLocation{name("clip")},
                       fmt::format("a cutting plane needs a finite point and a normal other than [0, 0, 0], "
                                   "found point {} normal {}",
                                   vectorText(clip.point), vectorText(clip.normal)));
    clip.normal = normalize(clip.normal);
    description.clips.push_back(clip);
  }
}

}  // namespace

void applyRenderOverrides(SceneDescription& description, const RenderOverrides& overrides,
                          const Mesh* quickLookMesh, int threads) {
  RenderSettings& settings = description.render;
  if (overrides.width) settings.width = *overrides.width;
  if (overrides.height) settings.height = *overrides.height;
  if (overrides.maxDepth) settings.maxDepth = *overrides.maxDepth;
  if (overrides.srgb) settings.srgb = *overrides.srgb;
  if (overrides.toneMap) settings.toneMap = *overrides.toneMap;
  if (overrides.exposure) settings.exposure = *overrides.exposure;
  if (overrides.bitDepth) settings.bitDepth = *overrides.bitDepth;
  if (overrides.denoise) settings.denoise = *overrides.denoise;
  if (overrides.quality) {
    requireImageQuality(*overrides.quality, SourceLocation{overrides.optionPrefix + "quality"});
    settings.quality = *overrides.quality;
  }
  if (overrides.lossless) settings.lossless = *overrides.lossless;
  if (overrides.dpi) {
    requireDpi(*overrides.dpi, SourceLocation{overrides.optionPrefix + "dpi"});
    settings.dpi = *overrides.dpi;
  }
  if (overrides.transparentBackground) settings.transparentBackground = *overrides.transparentBackground;
  if (overrides.backgroundDisplay) {
    const Vec3 shown = *overrides.backgroundDisplay;
    settings.background =
        settings.srgb ? Vec3{linearFromSrgb(shown.x), linearFromSrgb(shown.y), linearFromSrgb(shown.z)}
                      : shown;
  }
  if (overrides.sampler) settings.sampler = *overrides.sampler;
  if (overrides.samples) settings.samples = *overrides.samples;
  // The quick look's fill sits at the automatic camera, whose distance depends on the image's aspect.
  if (quickLookMesh && (overrides.width || overrides.height))
    placeQuickLookLights(description, *quickLookMesh, threads);
  if (overrides.integrator) settings.integrator = *overrides.integrator;
  if (overrides.noise) settings.noise = *overrides.noise;
  if (overrides.adaptiveNoise) settings.adaptiveNoise = *overrides.adaptiveNoise;
  if (overrides.edges)
    for (MeshInstance& mesh : description.meshes)
      if (!mesh.edges) mesh.edges = EdgeSettings{};
  applyLookOverride(description, overrides);
  // The Whitted model's grids need a square count; path and AO take any.
  checkSampleGrid(settings.samples, settings.sampler, settings.integrator,
                  SettingName{SourceLocation{overrides.samplesName}, overrides.samplesName});
  applyAnnotationOverrides(description, overrides);
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
  if (overrides.adaptiveNoise) settings.adaptiveNoise = *overrides.adaptiveNoise;
  if (overrides.integrator) settings.integrator = *overrides.integrator;
}

}  // namespace lancer
