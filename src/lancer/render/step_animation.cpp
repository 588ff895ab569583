#include "lancer/render/step_animation.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>

#include "lancer/image/legend.hpp"
#include "lancer/image/text.hpp"
#include "lancer/mesh/field_steps.hpp"
#include "lancer/scene/instance_transform.hpp"
#include "lancer/scene/results/annotation_builder.hpp"
#include "lancer/scene/results/result_keys.hpp"
#include "lancer/scene/results/volume_views.hpp"
#include "lancer/scene/results/warp.hpp"
#include "lancer/scene/scene_update.hpp"
#include "lancer/util/stopwatch.hpp"

namespace lancer {
namespace {

// Two 64-bit digests of the faces' corners by unrelated mixes (FNV-1a and a multiply-rotate): frames
// whose faces differ would have to collide in both to be taken for the same, which faces that drop
// or turn a few of their own do not do by accident. It spares holding a copy of the previous
// frame's faces (16 bytes a face) while the next is built.
std::pair<std::uint64_t, std::uint64_t> facesDigest(const std::vector<MeshFace>& faces) {
  std::uint64_t a = 0x9E3779B97F4A7C15ull ^ faces.size(), b = 0xC2B2AE3D27D4EB4Full + faces.size();
  for (const MeshFace& face : faces)
    for (const std::uint32_t v : face.vertex) {
      a = (a ^ v) * 0x100000001B3ull;                                            // FNV-1a's prime
      b = std::rotl(b + v * 0xD6E8FEB86659FD93ull, 29) * 0x9FB21C651E98DF25ull;  // a multiply-rotate mix
    }
  return {a, b};
}

bool anyWarp(const SceneDescription& description) {
  return std::any_of(description.meshes.begin(), description.meshes.end(),
                     [](const MeshInstance& mesh) { return mesh.warp.has_value(); });
}

// Whether isosurfaces or field lines are made again per frame: their geometry changes as a warp's.
bool anyVolumeViewMoves(const SceneDescription& description) {
  return std::any_of(description.meshes.begin(), description.meshes.end(),
                     [](const MeshInstance& mesh) { return mesh.volumeSource != nullptr; });
}

// The least and greatest value a coloured isosurface or field line can take over the animation: the
// colouring field's over every step in the whole volume (its magnitude for a vector), so that a
// colour means the same value in every frame as the surfaces move. Empty when the field is not in the
// volume or a component other than the magnitude is asked for.
std::optional<std::pair<double, double>> volumeColourRange(const VolumeViewSource& source,
                                                           const ColorBy& colorBy) {
  if (colorBy.component != FieldComponent{}) return std::nullopt;
  double low = std::numeric_limits<double>::infinity(), high = -low;
  for (const VolumeField* step : source.volume->fieldSteps(colorBy.field)) {
    const auto components = static_cast<std::size_t>(step->components);
    for (std::size_t k = 0; k + components <= step->values.size(); k += components) {
      double value = step->values[k];
      if (components > 1) {
        double sum = 0;
        for (std::size_t c = 0; c < components; ++c) sum += double(step->values[k + c]) * step->values[k + c];
        value = std::sqrt(sum);
      }
      if (!std::isfinite(value)) continue;
      low = std::min(low, value);
      high = std::max(high, value);
    }
  }
  if (!(low <= high)) return std::nullopt;
  return std::pair{low, high};
}

}  // namespace

StepFrames planStepFrames(const SceneDescription& description, const std::vector<Mesh>& meshes,
                          const AnimationSettings& animation) {
  std::vector<double> times;
  // Each step's place on the timeline and the time its file gives it (the same for a view whose
  // times increase with its steps); the first view that does not says so in the note.
  std::vector<std::pair<double, double>> storedTimes;
  std::string untimed;
  for (std::size_t i = 0; i < meshes.size(); ++i) {
    const MeshInstance& instance = description.meshes[i];
    std::vector<std::string> views;
    if (instance.colorBy && !instance.colorBy->step) views.push_back(instance.colorBy->field);
    if (instance.warp) views.push_back(instance.warp->field);
    if (instance.isolines && !instance.isolines->step) views.push_back(instance.isolines->field);
    for (const AnnotationSpec& annotation : instance.annotations)
      if (!annotationStep(annotation)) views.push_back(annotationField(annotation));
    const std::vector<double> own = stepTimes(meshes[i], views);
    times.insert(times.end(), own.begin(), own.end());
    if (instance.volumeSource) {
      const std::vector<double> inside = volumeViewTimes(*instance.volumeSource);
      times.insert(times.end(), inside.begin(), inside.end());
    }
    for (const std::string& view : views) {
      const std::vector<const MeshField*> steps = viewSteps(meshes[i], view);
      if (untimed.empty() && steps.size() > 1 && !timedByTags(steps)) untimed = view;
      for (std::size_t k = 0; k < steps.size(); ++k)
        storedTimes.emplace_back(stepTime(steps, k), steps[k]->time);
    }
  }
  std::sort(times.begin(), times.end());
  times.erase(std::unique(times.begin(), times.end()), times.end());
  if (times.empty())
    throw InputError(
        SourceLocation{description.path},
        "an animation over steps needs a mesh coloured (color_by), warped (warp), with isolines or arrows "
        "by a view of its file; add color_by = { field = \"...\" } or warp = { field = \"...\" } to a "
        "[[mesh]]");
  StepFrames frames;
  if (!animation.framesGiven || !untimed.empty()) {
    frames.times = times;
    if (animation.framesGiven && animation.frames != static_cast<int>(times.size()))
      frames.note = fmt::format(
          "lancer: the times of view \"{}\" do not increase with its steps (repeated or unsorted, as "
          "a Newmark scheme's t = 0 or eigenmodes' frequencies are): {} frames, one per step, instead of "
          "{} spread over its times",
          untimed, times.size(), animation.frames);
  } else {
    const int count = animation.frames;
    for (int k = 0; k < count; ++k)
      frames.times.push_back(count == 1 ? times.front()
                                        : times.front() + (times.back() - times.front()) * k / (count - 1));
    frames.times.back() = times.back();  // exactly the last step, not a rounding before it
  }
  std::stable_sort(storedTimes.begin(), storedTimes.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  for (const double t : frames.times) {
    const auto after = std::upper_bound(times.begin(), times.end(), t);
    frames.steps.push_back(static_cast<int>(std::max<std::ptrdiff_t>(after - times.begin() - 1, 0)));
    // Timed views: the frame's own time, between steps too; else the time of the step it shows.
    double label = t;
    if (!untimed.empty()) {
      const auto at = std::lower_bound(storedTimes.begin(), storedTimes.end(), t,
                                       [](const auto& entry, double value) { return entry.first < value; });
      if (at != storedTimes.end() && at->first == t) label = at->second;
    }
    frames.labelTimes.push_back(label);
  }
  return frames;
}

void holdStepColourRanges(SceneDescription& description, bool perStepRange) {
  for (MeshInstance& mesh : description.meshes) {
    if (mesh.colorBy && perStepRange) mesh.colorBy->perStepRange = true;
    if (mesh.volumeSource && mesh.colorBy && !mesh.colorBy->range && !mesh.colorBy->perStepRange)
      mesh.colorBy->range = volumeColourRange(*mesh.volumeSource, *mesh.colorBy);
  }
}

StepScenes::StepScenes(SceneDescription description, std::vector<Mesh>& meshes,
                       const AnimationSettings& animation, AccelKind accel, int threads)
    : description_(std::move(description)),
      meshes_(meshes),
      animation_(animation),
      accel_(accel),
      threads_(threads) {
  frames_ = planStepFrames(description_, meshes_, animation_);
  animation_.frames = frameCount();
  if (!animation_.degreesGiven) animation_.degrees = 0;  // the steps move; the camera stays unless asked
  holdStepColourRanges(description_, animation_.perStepRange);
  // The camera frames every frame's shape: the union of the deformed bounds over the frames.
  const bool warped = anyWarp(description_);
  for (std::size_t k = 0; k < (warped ? frames_.times.size() : 1); ++k) {
    description_.when = StepSelection{std::nullopt, frames_.times[k], "the animation over steps"};
    framing_.extend(warpedWorldBounds(description_, meshes_));
  }
  // Isosurfaces and field lines move inside their volume: its box frames them in every frame.
  for (const MeshInstance& mesh : description_.meshes) {
    if (!mesh.volumeSource) continue;
    const VolumeMesh& volume = *mesh.volumeSource->volume;
    const InstanceTransform transform(mesh.volumeSource->parent);
    Aabbd box;
    for (const Vec3& node : volume.nodes) box.extend(toDouble(node));
    for (int corner = 0; corner < 8; ++corner)
      framing_.extend(transform.apply(volume.origin + Vec3d{corner & 1 ? box.upper.x : box.lower.x,
                                                            corner & 2 ? box.upper.y : box.lower.y,
                                                            corner & 4 ? box.upper.z : box.lower.z}));
  }
}

void StepScenes::buildAt(double time) {
  const Stopwatch stopwatch;
  description_.when = StepSelection{std::nullopt, time, "the animation over steps"};
  const bool first = !scene_.has_value();
  // Isosurfaces and field lines that follow the steps, made again at this time: new faces, as a warp
  // that collapsed some (the scene and the accelerator are built again).
  const bool remade = anyVolumeViewMoves(description_);
  if (remade) {
    const Stopwatch remaking;
    for (std::size_t i = 0; i < description_.meshes.size(); ++i)
      if (const std::shared_ptr<const VolumeViewSource>& source = description_.meshes[i].volumeSource)
        meshes_[i] = remakeVolumeView(*source, time);
    rebuildStages_.add("volume views", remaking.seconds());
  }
  const bool warped = anyWarp(description_) || remade;
  KdBuildOptions options;
  options.threads = threads_;
  // A build is the frame's peak of memory: the steps a stored file keeps go before it (the next
  // frame reads its steps again, which only the first frame and the rare rebuilds pay).
  const auto forgetKeptSteps = [this] {
    for (const Mesh& mesh : meshes_)
      for (const MeshField& field : mesh.fields) lancer::forgetKeptSteps(field);
  };
  // A warped step with the same faces: its vertices, normals and colours are written over the
  // previous frame's scene and the tree is refitted (nothing as large as the scene is allocated).
  if (!first && warped && !remade && layout_ && accelerator_) {
    builtTime_.reset();
    bool updated = false;
    try {
      updated = updateSceneAt(*scene_, *layout_, description_, meshes_, threads_, &rebuildStages_,
                              &normalsScratch_);
    } catch (...) {
      layout_.reset();  // the scene is half written: whatever comes next builds it again
      throw;
    }
    if (updated) {
      const Stopwatch refit;
      const SceneGeometry& geometry = scene_->geometry;
      if (accelerator_->update(geometry.positions, geometry.faces, options, forgetKeptSteps)) ++refits_;
      accelSeconds_ += refit.seconds();
      rebuildStages_.add("accelerator", refit.seconds());
      rebuildSeconds_ += stopwatch.seconds();
      ++rebuilds_;
      ++updatesInPlace_;
      builtTime_ = time;
      return;
    }
  }
  // The previous frame's scene goes before the next one is built (two scenes of a 1M-face mesh at
  // once would raise the peak by one scene); the digest of its faces stays, to tell whether the
  // next has the same.
  scene_.reset();
  layout_.reset();
  normalsScratch_.release();
  builtTime_.reset();
  SceneLayout layout;
  // Arrows are built per step; remade meshes change their faces.
  const bool keepLayout = warped && !remade && !hasAnnotationMeshes(description_);
  StageTimes unused;
  Scene next = buildSceneAt(description_, meshes_, threads_, first ? &unused : &rebuildStages_,
                            keepLayout ? &layout : nullptr);
  if (keepLayout) layout_ = std::move(layout);
  // Every frame is framed alike: the camera and the orbit see the bounds of the whole animation.
  SceneGeometry& geometry = next.geometry;
  geometry.bounds = Aabb{};
  if (!framing_.empty()) {
    geometry.bounds.extend(geometry.toSceneSpace(framing_.lower));
    geometry.bounds.extend(geometry.toSceneSpace(framing_.upper));
  }
  // So are the lights placed against the bounds (a sun's point, an area light's aim), the same in
  // the frames written over this one.
  next.appearance.lights = sceneLights(description_, geometry);
  // Colours alone change when nothing is warped: the geometry, so the accelerator, stays. A warped
  // mesh with the same faces (none collapsed, none turned) moved its vertices only: the accelerator
  // is refitted where it can be (the BVH), else built again.
  const std::pair<std::uint64_t, std::uint64_t> digest = facesDigest(geometry.faces);
  const bool sameFaces = !first && digest == facesDigest_;
  facesDigest_ = digest;
  scene_.emplace(std::move(next));
  const SceneGeometry& built = scene_->geometry;  // `geometry` was moved with `next`
  if (first || warped) {
    const Stopwatch build;
    if (sameFaces && accelerator_) {
      if (accelerator_->update(built.positions, built.faces, options, forgetKeptSteps)) ++refits_;
    } else {
      accelerator_.reset();  // the old one goes first: one accelerator at a time
      forgetKeptSteps();
      accelerator_.emplace(Accelerator::build(built.positions, built.faces, accel_, options));
    }
    (first ? firstBuildSeconds_ : accelSeconds_) += build.seconds();
    if (!first) rebuildStages_.add("accelerator", build.seconds());
  }
  if (first) {
    warnings_ = scene_->warnings;
  } else {
    rebuildSeconds_ += stopwatch.seconds();
    ++rebuilds_;
  }
  builtTime_ = time;
}

Image StepScenes::render(int frame, const RenderOptions& options, RenderStats* stats) {
  const double time = frames_.times[static_cast<std::size_t>(frame)];
  const int rebuildsBefore = rebuilds_;
  if (!builtTime_ || *builtTime_ != time) buildAt(time);
  const Stopwatch rendering;
  Image image = renderAnimationFrame(*scene_, *accelerator_, description_, animation_, frame, options, stats);
  if (rebuilds_ > rebuildsBefore) rebuiltRenderSeconds_ += rendering.seconds();
  if (!animation_.label.empty()) {
    const std::string text =
        formatStepLabel(animation_.label, frames_.labelTimes[static_cast<std::size_t>(frame)],
                        frames_.steps[static_cast<std::size_t>(frame)], SourceLocation{description_.path});
    drawFrameLabel(image, text, animation_.labelPosition);
  }
  // The frame's own legends: with range = "step" each frame's colour range is its step's, so a
  // legend made once for the animation would show the first step's range on every frame.
  if (const std::optional<FieldColors>& fields = scene_->fieldColors)
    drawLegends(image, fields->legends, fields->legendPlacement, description_.render.srgb);
  return image;
}

void drawFrameLabel(Image& image, const std::string& text, LabelPosition position) {
  const Font& font = defaultFont();
  // A twentieth of the height, at least legible: 14 px in a 240-pixel frame, 36 px in 720.
  const float size = std::max(12.0f, static_cast<float>(image.height()) / 20.0f);
  const TextMetrics metrics = font.measure(text, size);
  const int margin = static_cast<int>(std::lround(0.6f * size));
  const bool right = position == LabelPosition::TopRight || position == LabelPosition::BottomRight;
  const bool bottom = position == LabelPosition::BottomLeft || position == LabelPosition::BottomRight;
  const int x = right ? image.width() - margin - metrics.inkRight : margin - metrics.inkLeft;
  const int baseline = bottom ? image.height() - margin - metrics.inkBottom : margin - metrics.inkTop;
  TextStyle style(Vec3{0.02f, 0.02f, 0.02f});
  style.halo = Vec3{1, 1, 1};  // legible over any background and any colour map
  font.draw(image, x, baseline, text, size, style);
}

}  // namespace lancer
