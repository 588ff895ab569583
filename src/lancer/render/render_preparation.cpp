#include "lancer/render/render_preparation.hpp"

#include <algorithm>
#include <optional>
#include <type_traits>

#include <fmt/format.h>

#include <utility>
#include <vector>

#include "lancer/image/legend.hpp"
#include "lancer/mesh/morton_renumbering.hpp"
#include "lancer/render/step_animation.hpp"
#include "lancer/scene/flat_scene.hpp"
#include "lancer/scene/geometry_overlap.hpp"
#include "lancer/scene/results/annotation_builder.hpp"
#include "lancer/scene/results/step_files.hpp"
#include "lancer/scene/results/volume_views.hpp"
#include "lancer/util/memory_budget.hpp"
#include "lancer/util/stopwatch.hpp"

namespace lancer {

std::uint64_t imageMemoryBytes(const RenderSettings& settings, int threads, ImageBuffer buffer) {
  // libpng's and zlib's state, and the GIF and BMP writers' own, stay well under this.
  constexpr std::uint64_t kWriterStateBytes = 1 << 20;
  const std::uint64_t pixels =
      static_cast<std::uint64_t>(settings.width) * static_cast<std::uint64_t>(settings.height);
  // The denoiser holds the whole image, its feature buffers, its guides and two work images.
  constexpr std::uint64_t kDenoiseBytesPerPixel = 160;
  if (settings.denoise) return saturatingProduct(pixels, kDenoiseBytesPerPixel);
  if (buffer == ImageBuffer::Whole) return saturatingProduct(pixels, sizeof(Rgba) + 4);
  return bandMemoryBytes(settings.width, settings.height, threads) +
         static_cast<std::uint64_t>(settings.width) * 4 + kWriterStateBytes;
}

void requireImageMemory(const RenderSettings& settings, int threads, ImageBuffer buffer,
                        const std::string& source) {
  const std::string what =
      settings.denoise
          ? fmt::format("a {}x{} image with the denoiser's buffers", settings.width, settings.height)
      : buffer == ImageBuffer::Whole ? fmt::format("a {}x{} image", settings.width, settings.height)
                                     : fmt::format("a {}x{} image rendered in bands of {} rows",
                                                   settings.width, settings.height, kTileSize);
  requireMemory(imageMemoryBytes(settings, threads, buffer), SourceLocation{source}, what);
}

Accelerator buildAccelerator(const Scene& scene, AccelKind kind, int threads) {
  KdBuildOptions options;
  options.threads = threads;  // the caller's thread count bounds the build too, not only the trace
  return Accelerator::build(scene.geometry.positions, scene.geometry.faces, kind, options);
}

namespace {

// Legends drawn into the picture take their side of it: the automatic camera frames the scene in the
// rest, so that they never cover it (a camera the scene places keeps its view: they overlay it).
void frameBesideLegends(SceneDescription& description, const Scene& scene) {
  CameraSettings& camera = description.camera;
  if (!scene.fieldColors || camera.position || camera.gmshView) return;
  const FieldColors& fields = *scene.fieldColors;
  const RenderSettings& settings = description.render;
  const int breadth = legendsBreadth(fields.legends, fields.legendPlacement, settings.width, settings.height);
  constexpr double kMostShare = 0.6;  // a picture too small for its legends still shows the model
  if (fields.legendPlacement == LegendPlacement::Right)
    camera.legendShareRight = std::min(kMostShare, static_cast<double>(breadth) / settings.width);
  else if (fields.legendPlacement == LegendPlacement::Bottom)
    camera.legendShareBottom = std::min(kMostShare, static_cast<double>(breadth) / settings.height);
}

}  // namespace

PreparedRender prepareRender(RenderRequest request) {
  const Stopwatch load;
  StageTimes stages = std::move(request.stages);
  const double secondsBefore = stages.totalSeconds();
  SceneDescription& description = request.description;
  const Mesh* quickLookMesh = request.quickLookMesh ? &*request.quickLookMesh : nullptr;
  applyRenderOverrides(description, request.overrides, quickLookMesh, request.threads);
  const ImageBuffer buffer =
      request.imageBuffer ? request.imageBuffer(description.render) : ImageBuffer::Whole;
  requireImageMemory(description.render, request.threads, buffer, description.path);
  // A quick look's lights placed again for the image's size pass over every face.
  stages.add("setup", load.seconds());

  std::vector<Mesh> meshes;
  std::vector<std::shared_ptr<const VolumeMesh>> volumes;
  if (request.quickLookMesh) {
    meshes.push_back(std::move(*request.quickLookMesh));
    volumes.push_back(request.quickLookVolume);
  } else {
    meshes = readSceneMeshes(description, request.threads, &stages, &volumes, request.givenMeshes,
                             request.givenVolumes);
  }
  {
    const Stopwatch renumber;  // locality for every pass that follows (mesh/morton_renumbering.hpp)
    if (renumberLargeMeshesInMortonOrder(meshes, request.threads) > 0)
      stages.add("renumber", renumber.seconds());
  }
  if (request.withMeshes) request.withMeshes(description, meshes);
  attachAnnotationVolumes(description, volumes);
  // Field lines' tubes sized in pixels are sized for the camera that frames the model beside its
  // legends, which the built scene's legends decide (the tubes' radius changes no legend): when the
  // legends take a side, the scene is built again from the meshes as read, that side known.
  std::optional<std::pair<SceneDescription, std::vector<Mesh>>> unbuilt;
  if (std::any_of(description.meshes.begin(), description.meshes.end(), [](const MeshInstance& mesh) {
        return mesh.volume.streamlines && mesh.volume.streamlines->radiusPixels;
      }))
    unbuilt.emplace(description, meshes);
  Scene scene;
  std::vector<Mesh> kept;
  // A scene of one mesh has its accelerator built alongside its orientation and normals
  // (scene/geometry_overlap.hpp) when asked; declared after `scene`, whose arrays it reads, so that
  // it is waited for before they go. Not with a second build below (its first scene is dropped).
  std::optional<Accelerator> early;
  double earlySeconds = 0;
  GeometryOverlap overlap([&](std::span<const Vec3> positions, std::span<const MeshFace> faces) {
    const Stopwatch build;
    KdBuildOptions options;
    options.threads = request.threads;
    early = Accelerator::build(positions, faces, request.accel, options);
    earlySeconds = build.seconds();
  });
  const auto build = [&](bool alongside) {
    addVolumeViews(description, meshes, volumes);
    // For an animation over steps, the frames' colour ranges: the legends that frame the model
    // beside them below, and size its tubes in pixels, are then the frames' own.
    if (request.keepMeshes)
      holdStepColourRanges(description, description.animation && description.animation->perStepRange);
    // A flat scene nobody chose a view for: straight on; a look then lights it from that view.
    const FlatSceneChoices choices{request.overrides.look.has_value(), request.overrides.shading.has_value()};
    if (applyFlatSceneDefaults(description, meshes, choices) && request.overrides.look)
      applyLookOverride(description, request.overrides);
    if (request.keepMeshes) {
      scene = buildSceneAt(description, meshes, request.threads, &stages);
      kept = std::move(meshes);
    } else {
      scene = buildScene(description, std::move(meshes), request.threads, &stages,
                         alongside ? &overlap : nullptr);
    }
    frameBesideLegends(description, scene);
  };
  build(request.buildAlongside && !unbuilt);
  const CameraSettings& framed = description.camera;
  if (unbuilt && (framed.legendShareRight != 0 || framed.legendShareBottom != 0)) {
    const double right = framed.legendShareRight, bottom = framed.legendShareBottom;
    description = std::move(unbuilt->first);
    meshes = std::move(unbuilt->second);
    unbuilt.reset();
    description.camera.legendShareRight = right;
    description.camera.legendShareBottom = bottom;
    build(false);
  }
  const double loadSeconds = secondsBefore + load.seconds();

  // buildSeconds: what the build adds to the load, the time to the first ray after the scene is
  // ready; the "accel build" stage: the build's own time (alongside the load when it was early).
  const Stopwatch accelBuild;
  const bool builtEarly = overlap.finish();
  Accelerator accelerator = request.keepMeshes ? Accelerator::build({}, {}, request.accel)
                            : builtEarly       ? std::move(*early)
                                               : buildAccelerator(scene, request.accel, request.threads);
  early.reset();
  const double buildSeconds = accelBuild.seconds();
  stages.add("accel build", builtEarly ? earlySeconds : buildSeconds);

  Camera camera = makeCamera(description.camera, scene, description.render);
  return PreparedRender{std::move(description), std::move(scene), std::move(accelerator), camera,
                        std::move(stages),      loadSeconds,      buildSeconds,           std::move(kept)};
}

void releaseSceneForSteps(PreparedRender& prepared) {
  // Swapped with empty ones: `v = {}` would clear the vectors and keep their memory.
  const auto release = [](auto& vector) { std::remove_reference_t<decltype(vector)>().swap(vector); };
  Scene& scene = prepared.scene;
  scene.geometry = SceneGeometry{};
  release(scene.appearance.faceMaterial);
  release(scene.appearance.faceOuterMaterial);
  release(scene.appearance.faceShading);
  scene.edges.reset();
  scene.isolines.reset();
  if (scene.fieldColors) {
    release(scene.fieldColors->vertexFieldT);
    release(scene.fieldColors->faceFieldT);
    release(scene.fieldColors->cornerFieldT);
    release(scene.fieldColors->faceColorMap);
    release(scene.fieldColors->faceBands);
  }
  prepared.accelerator = Accelerator::build({}, {}, prepared.accelerator.kind());
}

}  // namespace lancer
