// A warped step's scene written over the previous step's, for an animation over steps: when every
// warped mesh keeps its faces (none collapses, no closed shell turns inside out), its vertices and
// normals and every mesh's colours, legends and isolines are rewritten in the scene's own arrays
// (the normals in place while no vertex changes how it is smoothed, else computed afresh). No
// second scene is built beside the accelerator, whose tree is then refitted to the same faces.
// Otherwise the caller builds the scene again (buildSceneAt).
#pragma once

#include <vector>

#include "lancer/mesh/mesh.hpp"
#include "lancer/scene/scene.hpp"
#include "lancer/scene/scene_layout.hpp"
#include "lancer/util/stage_times.hpp"

namespace lancer {

// `scene` and `layout` come from buildSceneAt(description, meshes, ..., &layout) at another step
// (description.when); the scene takes the step description.when now names, and the layout follows
// it. A mesh whose smoothing changed (a crease formed or went) gets its normals computed afresh.
// False when the scene cannot be updated (arrows, which are built per step; a face the warp
// collapses; a shell turned inside out; feature edges on a warped mesh): the scene is then partly
// written and must be built again, which also reports the problem. The colours' InputErrors are
// buildSceneAt's. `times` gets the stages' wall seconds (warp, normals, normals again, annotate).
// `scratch`, when given, keeps the normals' working memory for the next call.
bool updateSceneAt(Scene& scene, SceneLayout& layout, const SceneDescription& description,
                   const std::vector<Mesh>& meshes, int threads = 0, StageTimes* times = nullptr,
                   CornerNormalsScratch* scratch = nullptr);

}  // namespace lancer
