// The accelerator's build alongside the scene's preparation. The build needs the scene's positions
// and faces only; a scene of one mesh knows both as soon as the positions are placed, before its
// shells are oriented and its normals computed, which take as long again on a large mesh. So
// buildScene starts the build there, on a thread of its own, and the two run at once.
//
// The faces handed over are as the file winds them. Orientation reverses the faces of a shell
// wound inward; when it reversed any, the build's tree holds triangles wound otherwise than the
// scene's (its leaves gather their corners), so it is not used: finish() says so, and the caller
// builds again over the scene's faces (what it did before, and what a scene of several meshes does).
#pragma once

#include <functional>
#include <future>
#include <span>
#include <vector>

#include "lancer/math/vec3.hpp"
#include "lancer/mesh/mesh.hpp"

namespace lancer {

class GeometryOverlap {
 public:
  using Task = std::function<void(std::span<const Vec3> positions, std::span<const MeshFace> faces)>;
  explicit GeometryOverlap(Task task) : task_(std::move(task)) {}
  // Waits for a task still running (its error, if any, is dropped: finish() is where it is raised).
  ~GeometryOverlap();
  GeometryOverlap(const GeometryOverlap&) = delete;
  GeometryOverlap& operator=(const GeometryOverlap&) = delete;

  // buildScene's side. start: the task begins on its own thread over `positions` and `faces`,
  // which the caller keeps alive and unchanged until the task is over (finish, abandon or the
  // destructor). At most once.
  void start(std::span<const Vec3> positions, std::span<const MeshFace> faces);
  // The scene's faces differ from those the task was given: `given` (the array they lie in) is
  // kept alive here until the task is over, and finish() says the result is not to be used.
  void facesChanged(std::vector<MeshFace> given);
  // Waits for the task, its result and error dropped (an error in the scene's preparation unwinds
  // past the arrays the task reads).
  void abandon() noexcept;

  // The caller's side, once the scene is built: waits for the task and rethrows its error. True
  // when the task ran over the scene's final positions and faces; false when it never started (a
  // scene of several meshes) or the faces changed after it did.
  bool finish();

 private:
  Task task_;
  std::future<void> running_;
  bool started_ = false;
  bool stale_ = false;
  std::vector<MeshFace> heldFaces_;
};

}  // namespace lancer
