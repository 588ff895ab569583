// A warped step written over the previous step's scene (updateSceneAt) is the scene a full build at
// that step gives: the same faces, the vertices and normals to float rounding (the two differ only
// in the origin they are placed about), the same colours, bands, legends, isolines and floor. What
// it cannot update (arrows, feature edges on a warped mesh) it leaves to a full build.
#include "lancer/scene/scene_update.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "support/files.hpp"
#include "support/test_scenes.hpp"

namespace lancer {
namespace {

// The gmsh-made cantilever twice: warped by its displacement and coloured by its element
// temperature with isolines of von Mises stress and a ghost of its undeformed shape; and a copy
// moved aside, warped more, coloured by stress in bands. A floor under both.
SceneDescription twoBeams() {
  SceneDescription d =
      test::flatLitOnBlue(test::orthographicView(160, 90, {5, 0, 20}, {5, 0, 0}, 12), {5, 5, 20});
  d.materials = {test::matteMaterial("beam", {0.8f, 0.8f, 0.2f}, {0.8f, 0.8f, 0.2f})};
  FieldComponent vonMises;
  vonMises.kind = FieldComponent::Kind::VonMises;
  MeshInstance beam;
  beam.file = test::dataFile("results/cantilever.msh");
  beam.warp = WarpSettings{};
  beam.warp->field = "displacement";
  beam.warp->factor = 1.0;
  beam.undeformed = UndeformedStyle::Ghost;
  beam.colorBy = ColorBy{};
  beam.colorBy->field = "temperature";
  beam.isolines = IsolineSpec{};
  beam.isolines->field = "stress";
  beam.isolines->component = vonMises;
  beam.isolines->count = 5;
  MeshInstance copy = beam;
  copy.undeformed = UndeformedStyle::None;
  copy.isolines.reset();
  copy.translate = {0, -4, 0};
  copy.warp->factor = 1.5;
  copy.colorBy->field = "stress";
  copy.colorBy->component = vonMises;
  copy.colorBy->bands = 6;
  d.meshes = {beam, copy};
  d.floor = FloorSettings{};
  return d;
}

SceneDescription at(SceneDescription d, double time) {
  d.when = StepSelection{std::nullopt, time, "the test"};
  return d;
}

void expectSameScene(const Scene& updated, const Scene& built) {
  const SceneGeometry& a = updated.geometry;
  const SceneGeometry& b = built.geometry;
  ASSERT_EQ(a.faces.size(), b.faces.size());
  for (std::size_t f = 0; f < a.faces.size(); ++f)
    for (int c = 0; c < 4; ++c) ASSERT_EQ(a.faces[f].vertex[c], b.faces[f].vertex[c]) << "face " << f;
  ASSERT_EQ(a.positions.size(), b.positions.size());
  for (std::size_t v = 0; v < a.positions.size(); ++v) {
    const Vec3d worldA = a.origin + toDouble(a.positions[v]), worldB = b.origin + toDouble(b.positions[v]);
    EXPECT_LT(length(worldA - worldB), 1e-5) << "vertex " << v;
  }
  ASSERT_EQ(a.faceNormals.size(), b.faceNormals.size());
  for (std::size_t f = 0; f < a.faceNormals.size(); ++f)
    EXPECT_GT(dot(a.faceNormals[f], b.faceNormals[f]), 1 - 1e-6f) << "face " << f;
  ASSERT_EQ(a.cornerNormals.normals.size(), b.cornerNormals.normals.size());
  for (std::size_t f = 0; f < a.faces.size(); ++f)
    for (int c = 0; c < a.faces[f].cornerCount(); ++c) {
      ASSERT_EQ(a.cornerNormals.faceCorner[f][c], b.cornerNormals.faceCorner[f][c]);
      EXPECT_GT(dot(a.cornerNormals.normals[a.cornerNormals.faceCorner[f][c]],
                    b.cornerNormals.normals[b.cornerNormals.faceCorner[f][c]]),
                1 - 1e-6f);
    }
  EXPECT_EQ(a.faceBoundsSolid, b.faceBoundsSolid);
  ASSERT_TRUE(updated.fieldColors && built.fieldColors);
  const FieldColors& fa = *updated.fieldColors;
  const FieldColors& fb = *built.fieldColors;
  EXPECT_EQ(fa.faceColorMap, fb.faceColorMap);
  EXPECT_EQ(fa.faceBands, fb.faceBands);
  auto sameOrNan = [](const std::vector<float>& x, const std::vector<float>& y) {
    if (x.size() != y.size()) return false;
    for (std::size_t i = 0; i < x.size(); ++i)
      if (!(x[i] == y[i] || (std::isnan(x[i]) && std::isnan(y[i])))) return false;
    return true;
  };
  EXPECT_TRUE(sameOrNan(fa.vertexFieldT, fb.vertexFieldT));
  EXPECT_TRUE(sameOrNan(fa.faceFieldT, fb.faceFieldT));
  ASSERT_EQ(fa.legends.size(), fb.legends.size());
  for (std::size_t k = 0; k < fa.legends.size(); ++k) {
    EXPECT_EQ(fa.legends[k].low, fb.legends[k].low);
    EXPECT_EQ(fa.legends[k].high, fb.legends[k].high);
    EXPECT_EQ(fa.legends[k].title, fb.legends[k].title);
  }
  ASSERT_TRUE(updated.isolines && built.isolines);
  EXPECT_EQ(updated.isolines->faceStyle, built.isolines->faceStyle);
  EXPECT_TRUE(sameOrNan(updated.isolines->vertexValue, built.isolines->vertexValue));
  ASSERT_EQ(updated.isolines->styles.size(), built.isolines->styles.size());
  for (std::size_t k = 0; k < updated.isolines->styles.size(); ++k)
    EXPECT_EQ(updated.isolines->styles[k].values, built.isolines->styles[k].values);
  ASSERT_TRUE(updated.shadowCatcher && built.shadowCatcher);
  EXPECT_NEAR(updated.shadowCatcher->offset + dot(toFloat(a.origin), updated.shadowCatcher->normal),
              built.shadowCatcher->offset + dot(toFloat(b.origin), built.shadowCatcher->normal), 1e-5);
}

TEST(SceneUpdate, AWarpedStepWrittenInPlaceIsTheStepsFullBuild) {
  const SceneDescription description = twoBeams();
  const std::vector<Mesh> meshes = readSceneMeshes(description);
  SceneLayout layout;
  Scene scene = buildSceneAt(at(description, 0.0), meshes, 2, nullptr, &layout);
  ASSERT_EQ(layout.entries.size(), 3u);  // the beam, its ghost, the copy
  EXPECT_TRUE(layout.entries[1].undeformedCopy);
  for (const double time : {0.5, 1.5, 0.75, 1.25}) {  // steps, and blends between them
    ASSERT_TRUE(updateSceneAt(scene, layout, at(description, time), meshes, 2)) << "t = " << time;
    expectSameScene(scene, buildSceneAt(at(description, time), meshes, 2));
  }
}

// A beam smoothed only below 2 degrees: as it bends, the faces along it turn past that from one
// another and its vertices split into creases, so its normals are computed afresh and spliced in
// (the ghost's and the copy's normals move along).
TEST(SceneUpdate, AMeshWhoseCreasesChangeGetsItsNormalsAfresh) {
  SceneDescription description = twoBeams();
  description.meshes[0].smoothAngleDegrees = 2;
  description.meshes[0].warp->factor = 3;
  const std::vector<Mesh> meshes = readSceneMeshes(description);
  SceneLayout layout;
  Scene scene = buildSceneAt(at(description, 0.0), meshes, 2, nullptr, &layout);
  const std::size_t flatNormals = scene.geometry.cornerNormals.normals.size();
  StageTimes times;
  ASSERT_TRUE(updateSceneAt(scene, layout, at(description, 1.5), meshes, 2, &times));
  const Scene built = buildSceneAt(at(description, 1.5), meshes, 2);
  EXPECT_NE(built.geometry.cornerNormals.normals.size(), flatNormals);  // the bent beam has more creases
  expectSameScene(scene, built);
  bool afresh = false;
  for (const StageTimes::Stage& stage : times.stages) afresh = afresh || stage.name == "normals again";
  EXPECT_TRUE(afresh);
  // And back: the layout followed the splice, so the next step updates from it.
  ASSERT_TRUE(updateSceneAt(scene, layout, at(description, 0.5), meshes, 2));
  expectSameScene(scene, buildSceneAt(at(description, 0.5), meshes, 2));
}

TEST(SceneUpdate, WhatChangesItsFacesOrIsBuiltPerStepIsLeftToAFullBuild) {
  SceneDescription description = twoBeams();
  const std::vector<Mesh> meshes = readSceneMeshes(description);
  {
    SceneDescription withEdges = description;
    withEdges.meshes[0].edges = EdgeSettings{};
    withEdges.meshes[0].edges->featuresOnly = true;  // feature edges follow the shape's angles
    SceneLayout layout;
    Scene scene = buildSceneAt(at(withEdges, 0.0), meshes, 1, nullptr, &layout);
    EXPECT_FALSE(updateSceneAt(scene, layout, at(withEdges, 1.0), meshes, 1));
  }
  {
    SceneDescription withArrows = description;
    ArrowSpec arrows;
    arrows.field = "displacement";
    withArrows.meshes[0].annotations.push_back(arrows);
    SceneLayout layout;
    Scene scene = buildSceneAt(at(withArrows, 0.5), meshes, 1, nullptr, &layout);
    EXPECT_FALSE(updateSceneAt(scene, layout, at(withArrows, 1.0), meshes, 1));
  }
}

}  // namespace
}  // namespace lancer
