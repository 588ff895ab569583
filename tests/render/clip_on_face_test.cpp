// A cutting plane through a model's flat side (gmsh's t5, cut at x = 0.5 where its notch has a
// face): the face lies in the plane, and whether a ray meets it there is the rounding of two ways
// to the same t. Met from behind, it made a cap of no thickness; met by a shadow ray, a shadow of
// the part cut away: speckles either way. Both are checked on a box whose side lies in the plane,
// cut by the scene's plane ([[clip]]) and by the box's own ([[mesh.clip]]), which must do the same.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "lancer/scene/scene_loader.hpp"
#include "support/test_scenes.hpp"

namespace lancer {
namespace {

constexpr int kSize = 64;
constexpr float kPlaneX = 0.3f;  // not a power of two: the rounding varies from pixel to pixel

// A closed box, its quads wound outward (a solid: a ray leaving it through a cut would see a cap).
Mesh boxMesh(Vec3 lower, Vec3 upper) {
  Mesh mesh;
  for (int corner = 0; corner < 8; ++corner)
    mesh.positions.push_back(
        {corner & 1 ? upper.x : lower.x, corner & 2 ? upper.y : lower.y, corner & 4 ? upper.z : lower.z});
  mesh.faces = {MeshFace{{0, 4, 6, 2}}, MeshFace{{1, 3, 7, 5}}, MeshFace{{0, 1, 5, 4}},
                MeshFace{{2, 6, 7, 3}}, MeshFace{{0, 2, 3, 1}}, MeshFace{{4, 5, 7, 6}}};
  mesh.facePhysicalTag.assign(6, 1);
  mesh.faceEntityTag.assign(6, 1);
  mesh.faceEdgeMask.assign(6, kAllEdges);
  return mesh;
}

// Whose plane cuts the box (mesh 0): the scene's, or the box's own.
enum class Cut { Scene, Mesh };

SceneDescription litScene(SceneDescription view, int meshes, Cut cut) {
  SceneDescription d = test::flatLitOnBlue(view, Vec3d{1000, 300, 800});
  d.materials = {test::matteMaterial("solid", {0.5f, 0.4f, 0.0f}, {0.6f, 0.5f, 0.0f})};
  d.meshes.resize(static_cast<std::size_t>(meshes));
  // Removes x > 0.3, capped: the box lies wholly on the removed side, its -x side in the plane.
  const std::vector<ClipSettings> plane = {{Vec3d{kPlaneX, 0, 0}, Vec3d{1, 0, 0}, true}};
  (cut == Cut::Scene ? d.clips : d.meshes.front().clips) = plane;
  return d;
}

const char* nameOf(Cut cut) { return cut == Cut::Scene ? "the scene's plane" : "the mesh's own plane"; }

TEST(ClipOnFace, AFaceInThePlaneWithItsSolidCutAwayMakesNoCap) {
  // Seen obliquely from the removed side: every ray crosses the plane where the box's side lies
  // (933 of the 4096 pixels were a cap, orthographic; 131 in perspective).
  for (const Cut cut : {Cut::Scene, Cut::Mesh})
    for (const Projection projection : {Projection::Orthographic, Projection::Perspective}) {
      SceneDescription d = litScene(test::orthographicView(kSize, kSize, Vec3d{kPlaneX + 3, 1.7, 1.3},
                                                           Vec3d{kPlaneX, 0.5, 0.5}, 1.6, Vec3d{0, 0, 1}),
                                    1, cut);
      d.camera.projection = projection;
      for (const AccelKind accel : {kDefaultAccel, AccelKind::Naive}) {
        const Image image = test::renderScene(
            d, test::sceneFromMeshes(d, {boxMesh({kPlaneX, 0, 0}, {kPlaneX + 1, 1, 1})}), accel);
        int speckles = 0;
        for (int y = 0; y < kSize; ++y)
          for (int x = 0; x < kSize; ++x)
            if (image.at(x, y).b != 1.0f) ++speckles;
        EXPECT_EQ(speckles, 0) << "pixels of a cap of no thickness, of " << kSize * kSize << ", cut by "
                               << nameOf(cut);
      }
    }
}

TEST(ClipOnFace, AFaceInThePlaneCastsNoShadowFromThePartCutAway) {
  // A floor on the kept side, lit from the removed side over the box: seen from above, lit evenly.
  for (const Cut cut : {Cut::Scene, Cut::Mesh}) {
    const SceneDescription d = litScene(
        test::orthographicView(kSize, kSize, Vec3d{-0.5, 0.5, 5}, Vec3d{-0.5, 0.5, 0}, 1.5, Vec3d{0, 1, 0}),
        2, cut);
    const Image image =
        test::renderScene(d, test::sceneFromMeshes(d, {boxMesh({kPlaneX, 0, 0.1f}, {kPlaneX + 1, 1, 1.1f}),
                                                       test::squareMesh(-1.5f, -0.5f, kPlaneX, 1.5f, 0)}));
    const float lit = image.at(kSize / 2, kSize / 2).r;
    int shadowed = 0;
    for (int y = 0; y < kSize; ++y)
      for (int x = 0; x < kSize; ++x)
        if (image.at(x, y).b == 0.0f && image.at(x, y).r < lit - 1e-3f) ++shadowed;
    EXPECT_GT(lit, 0.2f * 0.5f + 1e-3f) << nameOf(cut);  // the centre is lit, not in shadow
    EXPECT_EQ(shadowed, 0) << "floor pixels in the shadow of the part cut away by " << nameOf(cut);
  }
}

}  // namespace
}  // namespace lancer
