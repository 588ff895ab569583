// Settings a caller puts over a scene's own (the CLI's --width, --samples, --shading, ...; the Python
// module's keyword arguments): one function applies them, so both give the same image.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "lancer/mesh/mesh.hpp"
#include "lancer/scene/looks.hpp"
#include "lancer/scene/scene_description.hpp"
#include "lancer/scene/up_axis.hpp"

namespace lancer {

// Unset members keep the scene's value.
struct RenderOverrides {
  std::optional<int> width, height, samples, maxDepth;
  std::optional<ShadingMode> shading;  // for every mesh (their own shading keys are dropped)
  std::optional<SamplerKind> sampler;
  std::optional<bool> srgb;  // false: the linear encoding (--linear)
  std::optional<ToneMap> toneMap;
  std::optional<float> exposure;
  std::optional<int> bitDepth;
  std::optional<bool> denoise;
  std::optional<int> quality;  // checked here: 1 to 100
  std::optional<bool> lossless;
  std::optional<double> dpi;  // checked here: above 0
  std::optional<IntegratorKind> integrator;
  std::optional<float> noise;          // checked by the caller: in (0, 1)
  std::optional<float> adaptiveNoise;  // checked by the caller: in (0, 1)
  std::optional<Look> look;            // applied last (applyLook); the overrides above win over its defaults
  std::optional<bool> transparentBackground;
  // The background as the picture shows it (--background: a display colour in [0, 1]); decoded with the
  // output's curve, so that an sRGB picture without tone curve or exposure shows exactly this colour.
  std::optional<Vec3> backgroundDisplay;
  bool edges = false;  // draw element edges on every mesh that does not set its own
  // Annotations (docs/annotations.md) for every mesh, checked here whoever set them: the colour
  // range and legend, isolines and bands of each field-coloured mesh (the lines follow its own
  // field), arrows of a vector field, and cut planes after the scene's own. The scale is set before
  // the range is checked (a log scale's range starts above 0).
  std::optional<ColorMap> colorMap;  // the map of every field-coloured mesh (Python's color_map=)
  std::optional<ColorScale> scale;   // --log: the colours' scale of every field-coloured mesh
  std::optional<std::pair<double, double>> range;
  std::optional<LegendPlacement> legend;
  std::optional<int> isolines, bands;
  std::vector<AnnotationSpec> annotations;  // arrows, in place of each mesh's own of the kind
  std::vector<ClipSettings> clips;
  // Inside the volume (docs/volume.md), for every mesh: slices after its own, its skin style, and
  // isosurfaces for a mesh that has none of its own.
  std::vector<SliceSpec> slices;
  std::optional<SkinStyle> skin;
  std::optional<IsosurfaceSpec> isosurfaces;
  std::optional<StreamlineSpec> streamlines;
  // How the front end spells its options before their names ("--range"), for messages.
  std::string optionPrefix = "--";
  // Names the samples check's messages give the value (the CLI's "--samples", Python's "samples").
  std::string samplesName = "--samples";
};

// Applies `overrides` to `description`. `quickLookMesh`: the mesh of a quick-look scene
// (quickLookScene), whose lights are placed again when the image size changes (on `threads` threads,
// 0: every core). Throws InputError for a sample count the sampler cannot use, and for an annotation
// that is out of range or has no field-coloured mesh to go on, at the option's name.
void applyRenderOverrides(SceneDescription& description, const RenderOverrides& overrides,
                          const Mesh* quickLookMesh = nullptr, int threads = 0);

// The look of `overrides` (if any) over the description, with the samples, noise and integrator the
// caller gave winning over its defaults: applied again when the automatic camera turns after the
// meshes are read (a flat scene seen straight on), since the look's lights follow the camera.
void applyLookOverride(SceneDescription& description, const RenderOverrides& overrides);

}  // namespace lancer
