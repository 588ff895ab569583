// Reflection and refraction against closed forms: the interface laws themselves, a glass slab's
// parallel exit and lateral shift, total internal reflection in a right-angle prism on either side
// of the critical angle, coloured and absorbed shadows, depth 0 equal to the local model, and energy
// that recursion cannot create.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "lancer/mesh/msh_reader.hpp"
#include "lancer/render/optics.hpp"
#include "lancer/render/tracer.hpp"
#include "support/test_scenes.hpp"

namespace lancer {
namespace {

constexpr double kDegree = std::numbers::pi / 180.0;

Mesh meshOf(std::vector<Vec3> positions, std::vector<MeshFace> faces) {
  Mesh mesh;
  mesh.positions = std::move(positions);
  mesh.faces = std::move(faces);
  mesh.facePhysicalTag.assign(mesh.faces.size(), 1);
  mesh.faceEntityTag.assign(mesh.faces.size(), 1);
  mesh.faceEdgeMask.assign(mesh.faces.size(), kAllEdges);
  return mesh;
}

// Box [-a, a] x [-b, b] x [-c, c] with every quad wound inward: lancer must orient it itself.
Mesh inwardBox(float a, float b, float c) {
  std::vector<Vec3> p;
  for (int i = 0; i < 8; ++i) p.push_back({i & 1 ? a : -a, i & 2 ? b : -b, i & 4 ? c : -c});
  return meshOf(
      p, {{{0, 1, 3, 2}}, {{4, 6, 7, 5}}, {{0, 4, 5, 1}}, {{2, 3, 7, 6}}, {{0, 2, 6, 4}}, {{1, 5, 7, 3}}});
}

// Right-angle prism along y in [-1, 1], cross-section (x, z): (0, 1), (2, 1), (0, -1). Its top face
// z = 1 and its side x = 0 are the legs, the hypotenuse runs from (2, 1) to (0, -1). Mixed winding.
Mesh rightAnglePrism() {
  const std::vector<Vec3> p = {{0, -1, 1}, {2, -1, 1}, {0, -1, -1}, {0, 1, 1}, {2, 1, 1}, {0, 1, -1}};
  return meshOf(
      p, {{{0, 1, 2, kNoVertex}}, {{3, 4, 5, kNoVertex}}, {{0, 1, 4, 3}}, {{0, 3, 5, 2}}, {{1, 2, 5, 4}}});
}

// A material that only shows ambient light: local colour = ambient * ka exactly.
Material emitter(const char* name, Vec3 ka) { return test::ambientOnlyMaterial(name, ka); }

Material clearGlass(float ior) {
  Material m = emitter("glass", {0, 0, 0});
  m.transparency = 1;
  m.ior = ior;
  return m;
}

SceneDescription ambientOnly(std::vector<Material> materials) {
  SceneDescription d;
  d.ambient = {1, 1, 1};
  d.render.background = {0, 0, 0};
  d.render.maxDepth = 10;
  d.materials = std::move(materials);
  return d;
}

// Traces single rays given in world coordinates.
class RayProbe {
 public:
  RayProbe(const SceneDescription& d, std::vector<Mesh> meshes, AccelKind accel = AccelKind::KdTreeSah)
      : scene_(test::sceneFromMeshes(d, std::move(meshes))),
        accelerator_(Accelerator::build(scene_.geometry.positions, scene_.geometry.faces, accel)),
        tracer_(scene_, accelerator_, d.render) {}

  Vec3 trace(const Vec3d& origin, const Vec3d& direction) const {
    TraceCounters counters;
    return tracer_.tracePrimary(Ray(scene_.geometry.toSceneSpace(origin), toFloat(direction)), true, counters)
        .color;
  }
  const Scene& scene() const { return scene_; }

 private:
  Scene scene_;
  Accelerator accelerator_;
  Tracer tracer_;
};

// ---- the interface laws -------------------------------------------------------------------------

TEST(Optics, SnellsLawAndTotalInternalReflection) {
  const Vec3 normal{0, 0, 1};
  for (float eta : {1.0f / 1.5f, 1.5f, 1.33f}) {
    for (double degrees = 0; degrees < 90; degrees += 0.5) {
      const double theta = degrees * kDegree;
      const Vec3 direction{float(std::sin(theta)), 0, float(-std::cos(theta))};
      Vec3 t;
      const bool transmits = refract(direction, normal, eta, t);
      const double sinTransmitted = eta * std::sin(theta);
      ASSERT_EQ(transmits, sinTransmitted <= 1.0) << "eta " << eta << " at " << degrees << " degrees";
      if (!transmits) {
        EXPECT_FLOAT_EQ(dielectricFresnel(float(std::cos(theta)), eta), 1.0f);
        continue;
      }
      EXPECT_NEAR(length(t), 1.0, 1e-6);
      EXPECT_NEAR(t.x, sinTransmitted, 1e-5);  // tangential component: n1 sin t1 = n2 sin t2
      EXPECT_LT(t.z, 0);                       // continues through the surface
      EXPECT_NEAR(t.y, 0, 1e-7);
    }
  }
  // Critical angle of glass to air: asin(1/1.5) = 41.81 degrees.
  Vec3 t;
  const double critical = std::asin(1.0 / 1.5);
  EXPECT_TRUE(
      refract({float(std::sin(critical - 1e-3)), 0, float(-std::cos(critical - 1e-3))}, normal, 1.5f, t));
  EXPECT_FALSE(
      refract({float(std::sin(critical + 1e-3)), 0, float(-std::cos(critical + 1e-3))}, normal, 1.5f, t));
}

TEST(Optics, FresnelAtNormalIncidenceAndReciprocity) {
  EXPECT_NEAR(dielectricFresnel(1.0f, 1.0f / 1.5f), 0.04f, 1e-6f);  // ((n - 1) / (n + 1))^2
  EXPECT_NEAR(dielectricFresnel(1.0f, 1.0f), 0.0f, 1e-7f);
  EXPECT_NEAR(dielectricFresnel(0.0f, 1.0f / 1.5f), 1.0f, 1e-6f);  // grazing
  // The same interface seen from either side reflects the same fraction (Stokes relations).
  for (double degrees = 1; degrees < 41; degrees += 2) {
    const double inside = degrees * kDegree;
    const double outside = std::asin(1.5 * std::sin(inside));
    EXPECT_NEAR(dielectricFresnel(float(std::cos(inside)), 1.5f),
                dielectricFresnel(float(std::cos(outside)), 1 / 1.5f), 1e-5);
  }
}

// ---- a glass slab: parallel exit, lateral shift t sin(theta - theta_t) / cos(theta_t) ----------------

// x where the floor's edge appears, seen straight down (-z) through the scene: bisection on the
// ray's x for the switch from background (0) to the floor (1).
double apparentEdge(const RayProbe& probe, double low, double high) {
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (low + high);
    (probe.trace({mid, 0.1, 20}, {0, 0, -1}).x > 0.5 ? high : low) = mid;
  }
  return 0.5 * (low + high);
}

TEST(OpticsAnalytic, GlassSlabExitsParallelDisplacedByTheAnalyticAmount) {
  constexpr float kThickness = 1.2f, kEdge = 0.3f, kIor = 1.5f;
  for (double tiltDegrees : {0.0, 20.0, 35.0, 50.0}) {
    double edgeSeen[2];
    const float floorDepth[2] = {-4.0f, -9.0f};
    for (int k = 0; k < 2; ++k) {
      SceneDescription d = ambientOnly({emitter("floor", {1, 1, 1}), clearGlass(kIor)});
      d.meshes.resize(2);
      d.meshes[1].material = 1;
      d.meshes[1].rotateDegrees = {0, tiltDegrees, 0};
      // The floor is white where x > kEdge; the slab's faces are wound inward on purpose.
      const RayProbe probe(
          d, {test::squareMesh(kEdge, -6, 6, 6, floorDepth[k]), inwardBox(6, 6, kThickness / 2)});
      edgeSeen[k] = apparentEdge(probe, kEdge - 2.0, kEdge + 2.0);
    }
    const double theta = tiltDegrees * kDegree;
    const double thetaT = std::asin(std::sin(theta) / kIor);
    const double shift = kThickness * std::sin(theta - thetaT) / std::cos(thetaT);
    // The slab moves each ray by -shift in x; the edge at kEdge is seen at kEdge + shift. Tolerance:
    // secondary rays start 256 ulps off the surface (ray_offset.hpp), a few 1e-5 at these coordinates.
    EXPECT_NEAR(edgeSeen[0], kEdge + shift, 5e-5) << "tilt " << tiltDegrees;
    // Same apparent edge for a floor 5 units further down: the ray leaves parallel to its entry.
    EXPECT_NEAR(edgeSeen[1], edgeSeen[0], 2e-5) << "tilt " << tiltDegrees;
  }
}

// ---- total internal reflection in a right-angle prism ---------------------------------------------

// A ray down through the prism's top face meets the hypotenuse at 45 degrees: past the critical
// angle asin(1/n) when n > sqrt(2), it is reflected towards -x onto a green wall at x = -3;
// otherwise it leaves through the hypotenuse and lands on the red floor at z = -3.
Vec3 prismRay(float ior) {
  SceneDescription d =
      ambientOnly({emitter("floor", {1, 0, 0}), clearGlass(ior), emitter("wall", {0, 1, 0})});
  d.meshes.resize(3);
  d.meshes[1].material = 1;
  d.meshes[2].material = 2;
  d.meshes[2].rotateDegrees = {0, -90, 0};  // the square's +z normal turned to +x
  d.meshes[2].translate = {-3, 0, 0};
  const RayProbe probe(
      d, {test::squareMesh(-2.9f, -5, 6, 5, -3), rightAnglePrism(), test::squareMesh(-5, -5, 2.9f, 5, 0)});
  return probe.trace({0.5, 0.2, 10}, {0, 0, -1});
}

TEST(OpticsAnalytic, TotalInternalReflectionPastTheCriticalAngle) {
  // sqrt(2) = 1.41421: the 45 degree incidence is past the critical angle for n = 1.43, 1.5, 2.4.
  for (float ior : {1.43f, 1.5f, 2.4f}) {
    const Vec3 seen = prismRay(ior);
    EXPECT_FLOAT_EQ(seen.y, 1.0f) << "n = " << ior << ": expected total internal reflection onto the wall";
    EXPECT_FLOAT_EQ(seen.x, 0.0f);
  }
  for (float ior : {1.1f, 1.33f, 1.40f}) {
    const Vec3 seen = prismRay(ior);
    EXPECT_FLOAT_EQ(seen.x, 1.0f) << "n = " << ior << ": expected refraction through the hypotenuse";
    EXPECT_FLOAT_EQ(seen.y, 0.0f);
  }
}

// ---- coloured shadows -------------------------------------------------------------------------------

// The floor's value at (0.53, 0, 0) under a light at (0, 0, 10), seen straight down: white, diffuse
// only, so the value is cos(theta) times what the shadow ray lets through. The shadow ray crosses
// the occluder near x = 0.48, while the camera ray at x = 0.53 misses it.
Vec3 floorUnder(const Material& occluder, Mesh occluderMesh, AccelKind accel = AccelKind::KdTreeSah) {
  Material floor = emitter("floor", {0, 0, 0});
  floor.kd = {1, 1, 1};
  SceneDescription d = ambientOnly({floor, occluder});
  d.ambient = {0, 0, 0};
  d.render.maxDepth = 0;
  d.lights = {{{0, 0, 10}, {1, 1, 1}, {1, 0, 0}}};
  d.meshes.resize(2);
  d.meshes[1].material = 1;
  const RayProbe probe(d, {test::squareMesh(-3, -3, 3, 3, 0), std::move(occluderMesh)}, accel);
  return probe.trace({0.53, 0, 5}, {0, 0, -1});
}

TEST(OpticsAnalytic, ShadowsThroughTransparentFacesAreColouredAndAbsorbed) {
  const double cosTheta = 10 / std::sqrt(100 + 0.53 * 0.53);
  // An open transparent sheet: transparency times its colour scaled to the brightest channel.
  Material sheet = clearGlass(1.5f);
  sheet.transparency = 0.5f;
  sheet.kd = {0.2f, 0.4f, 0.8f};
  const Vec3 tinted = floorUnder(sheet, test::squareMesh(-0.5f, -0.5f, 0.5f, 0.5f, 1));
  EXPECT_NEAR(tinted.x, cosTheta * 0.5 * 0.25, 1e-5);
  EXPECT_NEAR(tinted.y, cosTheta * 0.5 * 0.5, 1e-5);
  EXPECT_NEAR(tinted.z, cosTheta * 0.5 * 1.0, 1e-5);
  // A clear slab 0.4 thick (z in [0.8, 1.2]) that absorbs: exp(-absorption * path inside).
  Material slab = clearGlass(1.5f);
  slab.kd = {1, 1, 1};
  slab.absorption = {1.0f, 2.0f, 0.5f};
  Mesh box = inwardBox(0.5f, 0.5f, 0.2f);
  for (Vec3& p : box.positions) p.z += 1.0f;
  const Vec3 absorbed = floorUnder(slab, box);
  const double inside = 0.4 / cosTheta;
  EXPECT_NEAR(absorbed.x, cosTheta * std::exp(-1.0 * inside), 1e-4);
  EXPECT_NEAR(absorbed.y, cosTheta * std::exp(-2.0 * inside), 1e-4);
  EXPECT_NEAR(absorbed.z, cosTheta * std::exp(-0.5 * inside), 1e-4);
  // An opaque occluder blocks the light.
  EXPECT_EQ(floorUnder(emitter("opaque", {0, 0, 0}), test::squareMesh(-0.5f, -0.5f, 0.5f, 0.5f, 1)).x, 0.0f);
}

// Squares [-0.5, 0.5]^2 at each of `heights`, one mesh, listed in the order given.
Mesh stackedSheets(const std::vector<float>& heights) {
  Mesh sheets = meshOf({}, {});
  for (const float h : heights) {
    const auto first = static_cast<std::uint32_t>(sheets.positions.size());
    for (const Vec3 corner :
         {Vec3{-0.5f, -0.5f, h}, Vec3{0.5f, -0.5f, h}, Vec3{0.5f, 0.5f, h}, Vec3{-0.5f, 0.5f, h}})
      sheets.positions.push_back(corner);
    sheets.faces.push_back(MeshFace{{first, first + 1, first + 2, first + 3}});
  }
  sheets.facePhysicalTag.assign(sheets.faces.size(), 1);
  sheets.faceEntityTag.assign(sheets.faces.size(), 1);
  sheets.faceEdgeMask.assign(sheets.faces.size(), kAllEdges);
  return sheets;
}

// A shadow ray meets all its transparent faces in one walk, which must cross them in order along
// the ray, each once, and give up as the step-by-step crossing did: at an opaque face wherever it
// lies on the way, or past the crossing budget.
TEST(OpticsAnalytic, ShadowRaysCrossEachTransparentFaceOnceInOrderAndStopAtAnOpaqueOne) {
  const double cosTheta = 10 / std::sqrt(100 + 0.53 * 0.53);
  Material clear = clearGlass(1.0f);
  clear.kd = {1, 1, 1};
  // Clear sheets let everything through, up to the budget of crossings; listed top first.
  std::vector<float> heights;
  for (int i = 0; i < kMaxShadowCrossings; ++i) heights.push_back(2.5f - 0.1f * static_cast<float>(i));
  EXPECT_NEAR(floorUnder(clear, stackedSheets({heights.begin(), heights.end() - 1})).y, cosTheta, 1e-5);
  EXPECT_EQ(floorUnder(clear, stackedSheets(heights)).y, 0.0f);
  // Half-transparent sheets: 0.5 each, whatever the order of the faces in the mesh.
  Material half = clear;
  half.transparency = 0.5f;
  EXPECT_NEAR(floorUnder(half, stackedSheets({1.2f, 2.0f, 1.6f})).y, cosTheta * 0.125, 1e-5);
  // An opaque sheet blocks the light above, below or between transparent ones.
  SceneDescription d = ambientOnly({emitter("floor", {0, 0, 0}), half, emitter("opaque", {0, 0, 0})});
  d.materials[0].kd = {1, 1, 1};
  d.ambient = {0, 0, 0};
  d.render.maxDepth = 0;
  d.lights = {{{0, 0, 10}, {1, 1, 1}, {1, 0, 0}}};
  d.meshes.resize(3);
  d.meshes[1].material = 1;
  d.meshes[2].material = 2;
  for (const float opaqueAt : {1.0f, 1.5f, 2.5f}) {
    const RayProbe probe(
        d, {test::squareMesh(-3, -3, 3, 3, 0), stackedSheets({1.2f, 2.0f}), stackedSheets({opaqueAt})});
    EXPECT_EQ(probe.trace({0.53, 0, 5}, {0, 0, -1}).y, 0.0f) << "opaque sheet at " << opaqueAt;
  }
  // Two absorbing slabs, their faces listed from the lower slab's top down to the upper slab's
  // bottom: each stretch is absorbed in the medium it runs in, so the crossings must be taken in
  // order along the ray. The brute-force loop meets the faces in the mesh's order, the kd-tree
  // walk roughly along the ray.
  Material slab = clear;
  slab.absorption = {1.0f, 2.0f, 0.5f};
  Mesh slabs = inwardBox(0.5f, 0.5f, 0.1f);
  for (Vec3& p : slabs.positions) p.z += 2.0f;
  Mesh lower = inwardBox(0.5f, 0.5f, 0.1f);
  for (Vec3& p : lower.positions) p.z += 1.0f;
  const auto lowerFirst = static_cast<std::uint32_t>(slabs.positions.size());
  slabs.positions.insert(slabs.positions.end(), lower.positions.begin(), lower.positions.end());
  for (MeshFace face : lower.faces) {
    for (std::uint32_t& v : face.vertex) v += lowerFirst;
    slabs.faces.push_back(face);
  }
  std::reverse(slabs.faces.begin(), slabs.faces.end());  // each slab's top face before its bottom one
  slabs.facePhysicalTag.assign(slabs.faces.size(), 1);
  slabs.faceEntityTag.assign(slabs.faces.size(), 1);
  slabs.faceEdgeMask.assign(slabs.faces.size(), kAllEdges);
  for (const AccelKind accel : {AccelKind::KdTreeSah, AccelKind::Naive}) {
    EXPECT_NEAR(floorUnder(slab, slabs, accel).y, cosTheta * std::exp(-2.0 * 0.4 / cosTheta), 1e-4)
        << accelKindName(accel);
  }
  // A sheet of two triangles whose shared edge the shadow ray runs through (y = 0): both compute
  // the same hit, and the light crosses the sheet once.
  const Mesh twoTriangles = meshOf({{-0.5f, 0, 1}, {0.5f, 0, 1}, {0, 0.5f, 1}, {0, -0.5f, 1}},
                                   {{{0, 1, 2, kNoVertex}}, {{1, 0, 3, kNoVertex}}});
  EXPECT_NEAR(floorUnder(half, twoTriangles).y, cosTheta * 0.5, 1e-5);
}

// ---- depth 0 and energy -----------------------------------------------------------------------------

Mesh unitSphere() { return readMsh(LANCER_TEST_DATA_DIR "/msh/sphere_v41_ascii.msh"); }

// Light reaching a point at depth h inside an absorbing solid, from straight above, is exp(-a h)
// times what the surface lets through, whether the shadow ray starts inside the solid (a floor sunk
// into a clear glass block, or through a glass ball) or outside it (a floor under the block). Seen
// from above through the same h of glass, the pixel is exp(-2 a h). Shadow rays that started inside
// were not absorbed before (exp(-a h) only, from the camera's half of the path).
TEST(OpticsAnalytic, LightIsAbsorbedAlongTheShadowRayAlsoWhenItStartsInsideTheSolid) {
  Material floor = emitter("floor", {0, 0, 0});
  floor.kd = {1, 1, 1};
  Material glass = clearGlass(1.0f);  // no bending, no Fresnel: only absorption changes the light
  glass.absorption = {1.0f, 2.0f, 0.5f};
  SceneDescription d = ambientOnly({floor, glass});
  d.ambient = {0, 0, 0};
  d.lights = {{{0, 0, 1000}, {1, 1, 1}, {1, 0, 0}}};
  d.meshes.resize(2);
  d.meshes[1].material = 1;
  auto expectAbsorbed = [](const Vec3& seen, double glassPath, const char* what) {
    EXPECT_NEAR(seen.x, std::exp(-1.0 * glassPath), 2e-4) << what;
    EXPECT_NEAR(seen.y, std::exp(-2.0 * glassPath), 2e-4) << what;
    EXPECT_NEAR(seen.z, std::exp(-0.5 * glassPath), 2e-4) << what;
  };
  for (const float depth : {0.5f, 0.25f}) {  // the block is z in [-0.5, 0.5]; the floor at 0.5 - depth
    const RayProbe probe(d, {test::squareMesh(-2, -2, 2, 2, 0.5f - depth), inwardBox(0.5f, 0.5f, 0.5f)});
    expectAbsorbed(probe.trace({0.1, 0.2, 5}, {0, 0, -1}), 2.0 * depth, "floor sunk into the block");
    expectAbsorbed(probe.trace({1.5, 0.2, 5}, {0, 0, -1}), 0.0, "floor beside the block");
  }
  const RayProbe under(d, {test::squareMesh(-2, -2, 2, 2, -0.75f), inwardBox(0.5f, 0.5f, 0.5f)});
  expectAbsorbed(under.trace({0.1, 0.2, 5}, {0, 0, -1}), 2.0, "floor under the block");
  // Through the centre of a glass ball of radius 1 (gmsh's sphere: faceted, so a looser tolerance).
  const RayProbe ball(d, {test::squareMesh(-2, -2, 2, 2, 0), unitSphere()});
  const Vec3 seen = ball.trace({0.01, 0.02, 5}, {0, 0, -1});
  EXPECT_NEAR(seen.x, std::exp(-2.0), 2e-3);
  EXPECT_NEAR(seen.y, std::exp(-4.0), 2e-3);
}

// A mirror ball and a glass ball side by side, seen in perspective.
SceneDescription twoBalls(std::vector<Material> materials) {
  SceneDescription d;
  d.render.width = 64;
  d.render.height = 48;
  d.render.background = {0.1f, 0.2f, 0.3f};
  d.camera.position = Vec3d{0.5, 1.5, 7};
  d.camera.lookAt = Vec3d{0, 0, 0};
  d.ambient = {0.2f, 0.2f, 0.2f};
  d.materials = std::move(materials);
  d.meshes.resize(3);
  for (int i = 0; i < 3; ++i) d.meshes[i].material = i;
  d.meshes[0].translate = {-1.2, 0, 0};
  d.meshes[1].translate = {1.2, 0, 0};
  d.meshes[2].translate = {0, 0, -3};
  d.meshes[2].scale = {2, 2, 2};
  return d;
}

std::vector<Material> opticalMaterials() {
  Material mirror;
  mirror.name = "mirror";
  mirror.reflectivity = {0.8f, 0.7f, 0.6f};
  Material glass;
  glass.name = "glass";
  glass.kd = {0.2f, 0.4f, 0.3f};
  glass.transparency = 0.85f;
  glass.reflectivity = {0.05f, 0.05f, 0.05f};
  glass.fresnel = true;
  glass.absorption = {0.1f, 0.05f, 0.2f};
  Material backdrop;
  backdrop.name = "backdrop";
  backdrop.kd = {0.8f, 0.5f, 0.3f};
  backdrop.reflectivity = {0.3f, 0.3f, 0.3f};
  return {mirror, glass, backdrop};
}

TEST(OpticsAnalytic, DepthZeroRendersExactlyTheLocalModel) {
  SceneDescription optical = twoBalls(opticalMaterials());
  optical.render.maxDepth = 0;
  // The light sits at the camera, so no shadow ray can cross another object (the transparent ball
  // would tint it): what is left is the local model alone.
  optical.lights = {{*optical.camera.position, {0.9f, 0.9f, 0.8f}, {1, 0, 0}}};
  SceneDescription local = optical;
  for (Material& m : local.materials) {
    m.reflectivity = {0, 0, 0};
    m.transparency = 0;
  }
  local.render.maxDepth = 5;
  const std::vector<Mesh> meshes = {unitSphere(), unitSphere(), unitSphere()};
  const Image depthZero = test::renderMeshes(optical, meshes);
  const Image reference = test::renderMeshes(local, meshes);
  EXPECT_TRUE(depthZero == reference);
  // And the optics do change the picture once the depth allows it (the test can fail).
  optical.render.maxDepth = 1;
  EXPECT_FALSE(test::renderMeshes(optical, meshes) == reference);
}

TEST(OpticsAnalytic, FurnaceKeepsEnergyAtEveryDepth) {
  // Everything, background included, shows the same radiance L: since the weights at every node
  // sum to 1, every pixel must be L at every depth (more would be energy created, less lost);
  // with absorption inside the glass it can only be less.
  const Vec3 kRadiance{0.5f, 0.5f, 0.5f};
  for (bool absorb : {false, true}) {
    std::vector<Material> materials = opticalMaterials();
    for (Material& m : materials) {
      m.ka = {1, 1, 1};
      m.kd = m.ks = {0, 0, 0};
      if (!absorb) m.absorption = {0, 0, 0};
    }
    SceneDescription d = twoBalls(materials);
    d.ambient = kRadiance;
    d.render.background = kRadiance;
    const std::vector<Mesh> meshes = {unitSphere(), unitSphere(), unitSphere()};
    const Scene scene = test::sceneFromMeshes(d, meshes);
    for (int depth : {0, 1, 2, 5, 10}) {
      d.render.maxDepth = depth;
      const Image image = test::renderScene(d, scene);
      float lowest = 1, highest = 0;
      for (int y = 0; y < d.render.height; ++y)
        for (int x = 0; x < d.render.width; ++x) {
          const Rgba p = image.at(x, y);
          lowest = std::min({lowest, p.r, p.g, p.b});
          highest = std::max({highest, p.r, p.g, p.b});
        }
      EXPECT_LE(highest, 0.5f + 1e-5f) << "depth " << depth << (absorb ? " with absorption" : "");
      if (!absorb) {
        EXPECT_GE(lowest, 0.5f - 1e-5f) << "depth " << depth;
      } else if (depth > 0) {
        EXPECT_LT(lowest, 0.49f) << "absorption should darken the glass at depth " << depth;
      }
    }
  }
}

TEST(OpticsAnalytic, LitScenesNeverExceedTheBrightestLocalColour) {
  // With lights, each pixel is a weighted mean (weights summing to at most 1) of local colours and
  // the background, so at any depth it stays below the brightest local colour any point can have:
  // ambient ka + sum over lights of I (kd + ks).
  std::vector<Material> materials = opticalMaterials();
  SceneDescription d = twoBalls(materials);
  d.lights = {{{4, 6, 5}, {0.6f, 0.6f, 0.6f}, {1, 0, 0}}, {{-5, 3, 4}, {0.4f, 0.3f, 0.3f}, {1, 0, 0}}};
  Vec3 bound = d.render.background;
  for (const Material& m : materials) {
    Vec3 brightest = d.ambient * m.ka;
    for (const PointLight& light : d.lights) brightest += light.intensity * (m.kd + m.ks);
    bound = max(bound, brightest);
  }
  const Scene scene = test::sceneFromMeshes(d, {unitSphere(), unitSphere(), unitSphere()});
  double previousChange = 1e9;
  Image previous(1, 1);
  for (int depth = 0; depth <= 8; ++depth) {
    d.render.maxDepth = depth;
    const Image image = test::renderScene(d, scene);
    double change = 0;
    for (int y = 0; y < d.render.height; ++y)
      for (int x = 0; x < d.render.width; ++x) {
        const Rgba p = image.at(x, y);
        ASSERT_LE(p.r, bound.x + 1e-5f) << x << "," << y << " depth " << depth;
        ASSERT_LE(p.g, bound.y + 1e-5f);
        ASSERT_LE(p.b, bound.z + 1e-5f);
        if (depth > 0) change += std::abs(p.r - previous.at(x, y).r) + std::abs(p.b - previous.at(x, y).b);
      }
    // Deeper bounces carry less and less weight: the image settles.
    if (depth > 1) {
      EXPECT_LE(change, previousChange + 1e-3) << "depth " << depth;
    }
    if (depth > 0) previousChange = change;
    previous = image;
  }
  EXPECT_LT(previousChange, 0.5);
}

}  // namespace
}  // namespace lancer
