// The options of `lancer render` and `lancer animate` that set up the scene (camera, look, quality,
// results) and its output, in the groups `--help` shows; scene_setup.cpp applies them.
#include "scene_setup.hpp"

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include <array>
#include <string>
#include <string_view>
#include <vector>

#include "lancer/image/color_map.hpp"
#include "lancer/render/renderer.hpp"
#include "lancer/scene/looks.hpp"
#include "lancer/scene/render_limits.hpp"
#include "lancer/scene/view_presets.hpp"
#include "volume_options.hpp"

namespace lancer::cli {
namespace {

// The command line checks its choices against the same tables (CLI11 wants strings).
template <std::size_t N>
std::vector<std::string> choices(const std::array<std::string_view, N>& names) {
  return {names.begin(), names.end()};
}

}  // namespace

void addSceneViewOptions(CLI::App& command, SceneOverrides& overrides) {
  // Camera.
  command
      .add_option("--up", overrides.up,
                  "Up axis of the automatic camera: x, y, z, -x, -y or -z (a bare mesh: guessed; a scene: "
                  "y); a 3/4 view, flat models too")
      ->group(kCameraGroup);
  command
      .add_option(
          "--gmsh-view", overrides.gmshView,
          "The view set up in gmsh, framed for the image as gmsh's own export at that size: its options "
          "file (File > Save Model Options; default: the mesh's MESH.msh.opt); before or after the input")
      ->expected(0, 1)
      ->group(kCameraGroup);
  command
      .add_option("--view", overrides.view,
                  "The automatic camera's side, named from the up axis (--up, or guessed): iso (the 3/4 "
                  "view, default), front, back, left, right, top or bottom; y up: front is +z (gmsh's "
                  "default view), z up: front is -y; see docs/rendering.md")
      ->check(CLI::IsMember(choices(kViewPresetNames)))
      ->group(kCameraGroup);
  command
      .add_option("--azimuth", overrides.azimuth,
                  "Turn the camera DEG degrees round the model's up axis, about its target (positive: the "
                  "camera moves to its right)")
      ->type_name("DEG")
      ->group(kCameraGroup);
  command
      .add_option("--elevation", overrides.elevation,
                  "Raise the camera DEG degrees over its target (-90 to 90; negative: from below)")
      ->type_name("DEG")
      ->group(kCameraGroup);
  command
      .add_option("--zoom", overrides.zoom,
                  fmt::format("Bring the camera F times closer to its target (F > 1 closer, < 1 farther; "
                              "{} to {})",
                              kMinZoom, kMaxZoom))
      ->type_name("F")
      ->group(kCameraGroup);

  // Look: how surfaces are lit and drawn.
  command
      .add_option("--look", overrides.look,
                  "A lit scene in one option (path tracing, soft light, sky, a floor catching shadows): "
                  "studio, sky or sun")
      ->check(CLI::IsMember(choices(kLookNames)))
      ->group(kLookGroup);
  command
      .add_option("--integrator", overrides.integrator,
                  "How light is carried: whitted (the default, the classic model), path (path tracing) or ao "
                  "(ambient occlusion); see docs/lighting.md")
      ->check(CLI::IsMember(choices(kIntegratorNames)))
      ->group(kLookGroup);
  command
      .add_option(
          "--shading", overrides.shading,
          "Shading for every mesh: flat, gouraud, phong or unlit (the colours as they are, no lights)")
      ->check(CLI::IsMember(choices(kShadingNames)))
      ->group(kLookGroup);
  CLI::Option* background =
      command
          .add_option("--background", overrides.background,
                      "The background's colour as the picture shows it: a CSS name (white, navy), #rrggbb, "
                      "#rgb or r,g,b in 0..1")
          ->type_name("COLOR")
          ->group(kLookGroup);
  command
      .add_flag("--transparent", overrides.transparent,
                "A transparent background: alpha 0 where nothing is hit (.png, .exr, .gif)")
      ->excludes(background)
      ->group(kLookGroup);
  command
      .add_flag("--edges", overrides.edges,
                "Draw element edges (1 pixel, black) on every mesh whose scene sets no edges")
      ->group(kLookGroup);
  command
      .add_option(
          "--clip", overrides.clips,
          "Cut away one side of a plane, on every mesh (any number): AXIS=VALUE removes the side AXIS "
          "points to (x=0.5 removes x > 0.5, -z=0 removes z < 0), or PX,PY,PZ,NX,NY,NZ a point and "
          "the normal of the removed side, as [[clip]]")
      ->group(kLookGroup);

  // Results: time steps, deformed shapes and annotations.
  command.add_option("--step", overrides.step, "Time step of the results shown (colours and warps)")
      ->check(CLI::Range(0, 1'000'000'000))
      ->group(kResultsGroup);
  command
      .add_option("--warp", overrides.warp,
                  "Deformed shape: FIELD[:FACTOR], every node moved by FACTOR (default 1) times its vector")
      ->group(kResultsGroup);
  command
      .add_option("--undeformed", overrides.undeformed, "With --warp, the shape before it: edges or ghost")
      ->check(CLI::IsMember({"none", "edges", "ghost"}))
      ->group(kResultsGroup);
  command
      .add_option("--color-by", overrides.colorBy,
                  "Colour by a field: FIELD[:COMPONENT], COMPONENT magnitude, x, y, z, 0-8 or von_mises")
      ->group(kResultsGroup);
  command
      .add_option(
          "--color-map", overrides.colorMap,
          "The colours' map: a matplotlib name (viridis, turbo, RdBu, jet, ...; NAME_r reversed), gmsh:N "
          "(gmsh's View.ColormapNumber) or colours \"#000080,white,#800000\"; see docs/fields.md")
      ->group(kResultsGroup);
  command
      .add_option("--range", overrides.range,
                  "The colours' range MIN:MAX (values outside are clamped); default: over every step")
      ->group(kResultsGroup);
  command
      .add_flag("--log", overrides.log,
                "The colours on a log scale, as scale = \"log\": the values must be > 0, or the range's "
                "low end (--range MIN:MAX, MIN > 0)")
      ->group(kResultsGroup);
  command
      .add_option("--legend", overrides.legend,
                  "The colours' legend in the picture: right, bottom or none (render: a FILE name writes it "
                  "to its own image, as --legend-file)")
      ->group(kResultsGroup);
  command
      .add_option("--isolines", overrides.isolines,
                  "N isolines of the --color-by field, in the middle of N equal parts of its range")
      ->group(kResultsGroup);
  command.add_option("--bands", overrides.bands, "Discrete colours: N equal bands of the range")
      ->group(kResultsGroup);
  command
      .add_option("--arrows", overrides.arrows,
                  "Arrows along a vector field (3 components; node, element or element-node data)")
      ->group(kResultsGroup);
  command
      .add_option("--arrow-grid", overrides.arrowGrid,
                  "NX,NY,NZ: the --arrows through the volume, one at each point of a regular grid over its "
                  "bounds that lies inside an element")
      ->group(kResultsGroup);

  addVolumeOptions(command, overrides);
}

void addSceneOutputOptions(CLI::App& command, SceneOverrides& overrides) {
  // Output: the picture's size and how it is written.
  command
      .add_option("--width", overrides.width, fmt::format("Image width in pixels (1 to {})", kMaxRenderSide))
      ->group(kOutputGroup);
  command
      .add_option("--height", overrides.height,
                  fmt::format("Image height in pixels (1 to {})", kMaxRenderSide))
      ->group(kOutputGroup);
  CLI::Option* srgb =
      command
          .add_flag("--srgb", overrides.srgb,
                    "Encode the output with the sRGB curve (the default; over a scene's linear encoding)")
          ->group(kOutputGroup);
  command
      .add_flag("--linear", overrides.linear,
                "Encode the output linearly, round(255 * I): the raw values of the lighting model, for tests")
      ->excludes(srgb)
      ->group(kOutputGroup);
  command
      .add_option("--tonemap", overrides.toneMap,
                  "Tone curve before the encoding: none (default, clip at 1), filmic (Hable) or aces")
      ->group(kOutputGroup);
  command
      .add_option("--exposure", overrides.exposure, "Exposure in stops: radiance x 2^STOPS before the curve")
      ->group(kOutputGroup);
  command.add_option("--bit-depth", overrides.bitDepth, "Bits per sample: 8 (default) or 16 (PNG only)")
      ->group(kOutputGroup);
  command
      .add_option(
          "--quality", overrides.quality,
          fmt::format("JPEG and WebP quality: 1 (smallest) to 100 (best), default {}", kDefaultImageQuality))
      ->group(kOutputGroup);
  command.add_flag("--lossless", overrides.lossless, "WebP: lossless instead of --quality")
      ->group(kOutputGroup);
  command
      .add_option("--dpi", overrides.dpi,
                  "Print resolution recorded in the file (PNG pHYs, JPEG density, WebP and EXR), e.g. 300")
      ->group(kOutputGroup);
  command
      .add_flag("--denoise", overrides.denoise,
                "Filter the noise with the edge-aware denoiser guided by albedo, normal and depth")
      ->group(kOutputGroup);
  command.add_flag("-q,--quiet", overrides.quiet, "No progress or summary on stderr")->group(kOutputGroup);
  command
      .add_flag("--timings", overrides.timings,
                "Print where the time before the first ray went: read, orient (shells, orientation, "
                "nesting), normals, scene, accel build")
      ->group(kOutputGroup);

  // Quality: how many rays, and how they are found.
  command
      .add_option(
          "--samples", overrides.samples,
          fmt::format("Samples per pixel, 1 to {} (a perfect square for the regular grid)", kMaxSamples))
      ->group(kQualityGroup);
  command.add_option("--sampler", overrides.sampler, "Anti-aliasing: regular, stratified or adaptive")
      ->check(CLI::IsMember(choices(kSamplerNames)))
      ->group(kQualityGroup);
  command
      .add_option("--max-depth", overrides.maxDepth,
                  fmt::format("Reflection/refraction depth (0 to {})", kMaxDepth))
      ->group(kQualityGroup);
  command
      .add_option("--noise", overrides.noise,
                  "path, ao: stop sampling a pixel once its relative error is below this (0 < noise < 1)")
      ->group(kQualityGroup);
  command
      .add_option(
          "--adaptive-noise", overrides.adaptiveNoise,
          "path, ao: sample in rounds, more where a pixel's displayed error is above this (a fraction "
          "of white, 0 < E < 1), up to --samples; replaces --noise")
      ->group(kQualityGroup);
  command
      .add_option(
          "--accel", overrides.accel,
          "Accelerator: bvh (default: the wide BVH), kdtree-sah (the kd-tree), kdtree-sah-exact (its slower "
          "build, the quality reference), kdtree-median or naive (brute force)")
      ->check(CLI::IsMember(choices(kAccelNames)))
      ->group(kQualityGroup);
  command
      .add_option("--threads", overrides.threads,
                  fmt::format("Worker threads, 0 to {} (default 0: one per usable CPU)", kMaxThreads))
      ->group(kQualityGroup);
  command
      .add_flag("--build-alongside", overrides.buildAlongside,
                "Build the accelerator of a scene of one mesh alongside its orientation and normals: the "
                "first ray sooner, for more memory at the peak")
      ->group(kQualityGroup);
}

}  // namespace lancer::cli
