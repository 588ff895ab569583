// Animations over the time steps of results (`[animation] over = "steps"`, `--over steps`): one frame
// per step in time order, or `frames` evenly spaced in time with the steps between blended linearly.
// Each frame's scene is the scene at its time (colours, warps) built from meshes read once; when a
// mesh is warped its geometry changes, so the accelerator is refitted (the BVH, when the faces are
// the same) or built again for the frame. The camera,
// the orbit's centre and the colour ranges stay fixed over the animation (a colour means the same
// value in every frame; the picture does not jump as the part deforms).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "lancer/accel/accelerator.hpp"
#include "lancer/render/animation.hpp"
#include "lancer/scene/scene_layout.hpp"
#include "lancer/util/stage_times.hpp"

namespace lancer {

// The frames' times and, for the label, the step each shows (the step at or before its time) and the
// time the file gives it. A view whose times do not increase with its steps (repeated or unsorted)
// is ordered by step index: its frames' `times` are step indices, one frame per step, and labels
// show each step's own time.
struct StepFrames {
  std::vector<double> times;
  std::vector<int> steps;          // 0-based position in the steps' time order
  std::vector<double> labelTimes;  // the time `{time}` shows in each frame's label
  std::string note;                // for the user when frames were not spread as asked; else empty
};

// The times of the steps of every view the scene uses (colours, isolines and arrows not pinned to a
// step, warps) and the frames over them. Throws InputError when no mesh uses a view with steps.
StepFrames planStepFrames(const SceneDescription& description, const std::vector<Mesh>& meshes,
                          const AnimationSettings& animation);

// The colour ranges an animation over steps holds fixed: every coloured mesh's per step with
// `perStepRange` (range = "step"); else a coloured isosurface's or field line's the colouring field's
// over every step in the whole volume, so that a colour means the same value in every frame as they
// move. StepScenes applies it; prepareRender (render_preparation.hpp) applies it first to a scene it
// prepares for steps, so that the legends it frames the model beside (and sizes tubes in pixels for)
// are the frames' own.
void holdStepColourRanges(SceneDescription& description, bool perStepRange);

// Draws `text` into a corner of the frame (DejaVu Sans, dark with a white halo, a twentieth of the
// frame's height).
void drawFrameLabel(Image& image, const std::string& text, LabelPosition position);

// The scenes of an animation over steps, one frame at a time (frames rendered in any order).
class StepScenes {
 public:
  // `description.when` is replaced per frame; `meshes` (as read, every step) must outlive this. The
  // meshes of isosurfaces and field lines that follow their field's steps (MeshInstance::volumeSource)
  // are made again in `meshes` at each frame's time.
  StepScenes(SceneDescription description, std::vector<Mesh>& meshes, const AnimationSettings& animation,
             AccelKind accel, int threads);

  const StepFrames& frames() const { return frames_; }
  int frameCount() const { return static_cast<int>(frames_.times.size()); }
  // The description every frame is rendered with (its camera fixed over the animation).
  const SceneDescription& description() const { return description_; }
  const AnimationSettings& animation() const { return animation_; }

  // Frame `frame`, with its label when the animation has one and the legends of the frame's own
  // scene (its colour ranges: per step with range = "step"). Builds the frame's scene and
  // accelerator unless the previous frame had the same time and nothing is warped.
  Image render(int frame, const RenderOptions& options, RenderStats* stats = nullptr);

  // Seconds spent building scenes and accelerators for frames after the first, and how many.
  double rebuildSeconds() const { return rebuildSeconds_; }
  double accelSeconds() const { return accelSeconds_; }
  double firstBuildSeconds() const { return firstBuildSeconds_; }  // the first frame's accelerator
  int rebuilds() const { return rebuilds_; }
  // The share of the rebuilt frames' own time (their rebuild and their render) the rebuilds took:
  // the "at most 20% of a frame's time".
  double rebuildShare() const {
    const double total = rebuildSeconds_ + rebuiltRenderSeconds_;
    return total > 0 ? rebuildSeconds_ / total : 0.0;
  }
  // Where the rebuilds' time went, stage by stage (in place: warp, normals, annotate; built:
  // buildSceneAt's stages; both: accelerator).
  const StageTimes& rebuildStages() const { return rebuildStages_; }
  int refits() const { return refits_; }  // of the rebuilds, those whose accelerator was refitted
  // Of the rebuilds, those that wrote the step over the previous frame's scene (updateSceneAt).
  int updatesInPlace() const { return updatesInPlace_; }
  // What the first frame's build warned about (collapsed faces, the readers' warnings).
  const std::vector<std::string>& warnings() const { return warnings_; }
  std::size_t faceCount() const { return scene_ ? scene_->geometry.faces.size() : 0; }
  // The scene of the frame rendered last (empty before the first render).
  const std::optional<Scene>& frameScene() const { return scene_; }

 private:
  void buildAt(double time);

  SceneDescription description_;
  std::vector<Mesh>& meshes_;  // isosurfaces and field lines that follow the steps are made again
  AnimationSettings animation_;
  AccelKind accel_;
  int threads_;
  StepFrames frames_;
  Aabbd framing_;  // world bounds of every frame's geometry
  std::optional<Scene> scene_;
  std::optional<SceneLayout> layout_;    // of the scene built last, when a mesh is warped
  CornerNormalsScratch normalsScratch_;  // kept from one update in place to the next
  std::optional<Accelerator> accelerator_;
  std::optional<double> builtTime_;
  std::pair<std::uint64_t, std::uint64_t> facesDigest_{};  // of the faces of the scene built last
  double rebuildSeconds_ = 0;
  double accelSeconds_ = 0;
  double firstBuildSeconds_ = 0;
  double rebuiltRenderSeconds_ = 0;  // the render of the frames that rebuilt their scene
  int rebuilds_ = 0;
  int refits_ = 0;
  int updatesInPlace_ = 0;
  StageTimes rebuildStages_;
  std::vector<std::string> warnings_;
};

}  // namespace lancer
