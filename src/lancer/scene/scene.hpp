// The scene ready to render: every mesh instance transformed into one scene space (float, relative
// to a double-precision origin), with per-face material and shading, smooth normals and lights.
// Map: docs/architecture.md (the path of a ray through the modules).
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "lancer/image/legend.hpp"
#include "lancer/math/aabb.hpp"
#include "lancer/mesh/mesh.hpp"
#include "lancer/mesh/vertex_normals.hpp"
#include "lancer/mesh/volume/volume_mesh.hpp"
#include "lancer/scene/clip_planes.hpp"
#include "lancer/scene/face_clip_sets.hpp"
#include "lancer/scene/scene_description.hpp"
#include "lancer/util/stage_times.hpp"

namespace lancer {

struct SceneLayout;
class GeometryOverlap;

// A light in scene space. Every light has a `position` the Whitted model lights with (a point light's
// own, an area light's centre, a point far towards the sun); the path tracer samples its shape.
struct SceneLight {
  Vec3 position;  // scene space
  Vec3 intensity;
  Vec3 attenuation;  // constant, linear, quadratic
  LightType type = LightType::Point;
  Vec3 direction{0, 1, 0};              // sun: unit, towards it; rect, disk: the unit normal of the lit side
  float cosHalfAngle = 1;               // sun: cosine of its angular radius
  float radius = 0;                     // sphere, disk
  Vec3 axisU{0, 0, 0}, axisV{0, 0, 0};  // rect: half its sides; disk: unit axes of its plane
  float area = 0;                       // sphere: its cross-section pi r^2; rect, disk: the lit side's
  Vec3 radiance{0, 0, 0};               // sun and area lights: what the path tracer sees on the light
};

// The environment in scene space (EnvironmentSettings), the map decoded to linear RGB.
struct SceneEnvironment {
  EnvironmentSettings::Kind kind = EnvironmentSettings::Kind::Uniform;
  Vec3 color{1, 1, 1};
  Vec3 zenith, horizon, ground;
  Vec3 up{0, 1, 0};           // the camera's up: the sky's zenith and the map's pole
  Vec3 front{0, 0, 1};        // the map's centre column (u = 0.5) at rotation 0, across `up`
  float rotationRadians = 0;  // the map turned about `up`
  float strength = 1;
  bool visible = false;
  int mapWidth = 0, mapHeight = 0;
  std::vector<Vec3> map;  // row 0 at the zenith, radiance
};

// How a mesh's element edges are drawn (EdgeOverlay::styles[0] means "not drawn").
struct EdgeStyle {
  float widthPixels = 0;
  Vec3 color{0, 0, 0};
};

// Element or feature edges painted on the meshes that draw theirs (edge_overlay.hpp).
struct EdgeOverlay {
  std::vector<std::uint8_t> faceEdgeMask;     // per face: its edges to draw (element or feature edges)
  std::vector<std::uint16_t> faceEdgeStyle;   // per face: index into styles; 0: its mesh draws none
  std::vector<std::uint8_t> faceLineCorners;  // per face: bit c, corner c ends a drawn edge of some face
  std::vector<EdgeStyle> styles{EdgeStyle{}};
};

// A map the scene's faces are coloured with: its colours, and how the field's value interpolated at
// a point becomes a place t on them. On a linear scale the stored values are t already (an affine
// map commutes with interpolation); on a log scale they are the field's own values, placed after
// interpolation (MapPosition), so that a face shows its interpolated value's colour as its isolines
// and legend say.
struct FieldMap {
  ColorMap colors;
  ColorScale scale = ColorScale::Linear;
  double low = 0, high = 1;  // log: the range the values are placed in
  MapPosition position{0, 1};
  bool operator==(const FieldMap& other) const {
    return colors == other.colors && scale == other.scale && low == other.low && high == other.high;
  }
};

// Field colouring (color_by, field_shading.hpp): per face 0 (not coloured) or 1 + the index of its
// FieldMap in `maps` (the scene's distinct maps, at most kMaxMaps), plus kPerFace for element data or
// kPerCorner for element-node data; the value to interpolate (t in [0, 1], or on a log scale the
// field's value; NaN: none) per vertex (node data: interpolated per pixel, then mapped), per face
// (element data) or per face corner (element-node data, kCornerSlots per face in the face's corner
// order: interpolated over the face alone); each of the three is empty when no mesh is coloured by
// that kind.
struct FieldColors {
  static constexpr std::uint8_t kPerFace = 0x80;
  static constexpr std::uint8_t kPerCorner = 0x40;
  static constexpr std::uint8_t kMapBits = 0x3F;  // 1 + the index in maps
  static constexpr std::size_t kMaxMaps = kMapBits;
  std::vector<FieldMap> maps;
  std::vector<std::uint8_t> faceColorMap;
  std::vector<float> vertexFieldT;
  std::vector<float> faceFieldT;
  std::vector<float> cornerFieldT;
  // Per face: the number of discrete colour bands (0: continuous); empty when no mesh has bands.
  std::vector<std::uint16_t> faceBands;
  // One per field (and map) the meshes are coloured by: meshes colouring by one field share its
  // legend and its range. Drawn into the picture at legendPlacement, and by --legend.
  std::vector<LegendSpec> legends;
  LegendPlacement legendPlacement = LegendPlacement::None;
};

// Isolines (isolines = {...}, render/isoline_paint.hpp): per face 0 (none) or an index into styles;
// the field value per scene vertex (NaN: none), and per face corner (kCornerSlots per face, in its
// corner order) for faces of element-node data, whose values are each element's own; cornerValue is
// empty when no mesh draws isolines of element-node data.
struct IsolineStyle {
  std::vector<float> values;  // sorted
  Vec3 color{0, 0, 0};
  std::vector<Vec3> valueColors;  // one per value (color = "map"); empty: `color` for every line
  float widthPixels = 1.5f;
};
struct IsolineOverlay {
  std::vector<std::uint16_t> faceStyle;
  std::vector<float> vertexValue;
  std::vector<float> cornerValue;
  std::vector<IsolineStyle> styles{IsolineStyle{}};
};

// The shadow-catcher floor: points p with dot(p, normal) = offset (scene space).
struct ShadowCatcher {
  Vec3 normal{0, 1, 0};
  float offset = 0;
};

// Every mesh instance transformed into one scene space: the shapes alone (like pbrt-v4's
// TriangleMesh), what the accelerator is built on; indexed by vertex, face or corner.
struct SceneGeometry {
  Vec3d origin;  // world = origin + scene-space position; keeps float precision far from 0
  std::vector<Vec3> positions;
  std::vector<MeshFace> faces;
  std::vector<Vec3> faceNormals;  // geometric, unit; outward on closed shells, else the file's winding
  CornerNormals cornerNormals;    // smooth normals per face corner
  // 1 when the face belongs to a closed, outward-oriented shell or bounds a volume (refraction
  // enters and leaves it); 0 for open surfaces, which transparency treats as thin sheets.
  std::vector<std::uint8_t> faceBoundsSolid;
  Aabb bounds;  // scene space

  Vec3 toSceneSpace(const Vec3d& world) const { return toFloat(world - origin); }
};

// How the surfaces look: materials per face side, shading per face, the lights.
struct SceneAppearance {
  std::vector<Material> materials;
  std::vector<std::uint32_t> faceMaterial;  // of the volume behind the face (its inner side)
  // Of the volume in front of an interface face (on its normal's side), kNoMaterial elsewhere: air.
  // Empty when no mesh has interfaces between volumes.
  static constexpr std::uint32_t kNoMaterial = 0xFFFFFFFFu;
  std::vector<std::uint32_t> faceOuterMaterial;
  std::vector<ShadingMode> faceShading;
  std::vector<SceneLight> lights;  // scene space
  Vec3 ambient{0, 0, 0};
};

// Cut views: the scene's planes ([[clip]]), which cut every mesh, and each mesh's own ([[mesh.clip]]).
struct SceneClipping {
  std::vector<ClipPlane> planes;   // scene space
  std::vector<std::uint8_t> caps;  // 1: cap closed shells cut by planes[i]
  FaceClipSets perMesh;            // empty when no mesh has planes of its own
};

// The scene as the tracer reads it, by feature; each feature a structure of arrays, indexed by face
// or vertex. An optional feature no mesh uses is absent (std::nullopt), not a set of empty arrays.
struct Scene {
  SceneGeometry geometry;
  SceneAppearance appearance;
  SceneClipping clipping;
  std::optional<EdgeOverlay> edges;
  std::optional<FieldColors> fieldColors;
  std::optional<IsolineOverlay> isolines;
  std::optional<ShadowCatcher> shadowCatcher;
  std::optional<SceneEnvironment> environment;

  // What the mesh readers warned about (MeshSourceInfo::warnings), for the CLI to print.
  std::vector<std::string> warnings;
};

// The description's lights in scene space: a sun's point and an undirected area light's aim are
// placed against geometry.bounds (an animation over steps gives it the whole animation's).
std::vector<SceneLight> sceneLights(const SceneDescription& description, const SceneGeometry& geometry);

// The floor's plane in the scene: at its height, else touching the lowest vertex along its normal.
ShadowCatcher shadowCatcherOf(const FloorSettings& floor, const SceneGeometry& geometry);

// Reads every mesh of the description (errors point at the [[mesh]] entry or into the mesh file).
// The preparation runs on `threads` threads (0: every core), with the same result for any number.
// `times`, when given, gets the stages' wall seconds (read, orient, normals, scene).
Scene buildScene(const SceneDescription& description, int threads = 0, StageTimes* times = nullptr);
// Same, with the meshes already read: meshes[i] belongs to description.meshes[i]. With `overlap`,
// a scene of one mesh starts it as soon as its positions are placed (geometry_overlap.hpp).
Scene buildScene(const SceneDescription& description, std::vector<Mesh> meshes, int threads = 0,
                 StageTimes* times = nullptr, GeometryOverlap* overlap = nullptr);
// The meshes of the description as buildScene reads them (a `file` pattern: one step per file).
// With `volumes`, volumes[i] is mesh i's volume when needsVolume says it is needed
// (results/volume_views.hpp: slices, isosurfaces, coloured caps), else null.
std::vector<Mesh> readSceneMeshes(const SceneDescription& description, int threads = 0,
                                  StageTimes* times = nullptr,
                                  std::vector<std::shared_ptr<const VolumeMesh>>* volumes = nullptr);
// The scene at description.when from meshes read once and kept (they hold every step of their views):
// each call copies their geometry, warps it and colours it for that step. An animation over steps
// calls it per frame.
// `layout`, when given, gets where each mesh lies in the scene (scene_update.hpp writes a later
// warped step over the scene with it).
Scene buildSceneAt(const SceneDescription& description, const std::vector<Mesh>& meshes, int threads = 0,
                   StageTimes* times = nullptr, SceneLayout* layout = nullptr);

}  // namespace lancer
