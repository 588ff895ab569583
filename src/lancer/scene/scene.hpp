// The scene ready to render: every mesh instance transformed into one scene space (float, relative
// to a double-precision origin), with per-face material and shading, smooth normals and lights.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "lancer/math/aabb.hpp"
#include "lancer/math/clip_planes.hpp"
#include "lancer/math/face_clip_sets.hpp"
#include "lancer/mesh/mesh.hpp"
#include "lancer/mesh/vertex_normals.hpp"
#include "lancer/scene/scene_description.hpp"

namespace lancer {

struct SceneLight {
  Vec3 position;  // scene space
  Vec3 intensity;
  Vec3 attenuation;  // constant, linear, quadratic
};

// How a mesh's element edges are drawn (Scene::edgeStyles[0] means "not drawn").
struct EdgeStyle {
  float widthPixels = 0;
  Vec3 color{0, 0, 0};
};

struct Scene {
  Vec3d origin;  // world = origin + scene-space position; keeps float precision far from 0
  std::vector<Vec3> positions;
  std::vector<MeshFace> faces;
  std::vector<Vec3> faceNormals;  // geometric, unit; outward on closed shells, else the file's winding
  CornerNormals cornerNormals;    // smooth normals per face corner
  std::vector<std::uint32_t> faceMaterial;  // of the volume behind the face (its inner side)
  // Of the volume in front of an interface face (on its normal's side), kNoMaterial elsewhere: air.
  // Empty when no mesh has interfaces between volumes.
  static constexpr std::uint32_t kNoMaterial = 0xFFFFFFFFu;
  std::vector<std::uint32_t> faceOuterMaterial;
  std::vector<ShadingMode> faceShading;
  std::vector<std::uint8_t> faceEdgeMask;     // element edges (or feature edges) of each face
  std::vector<std::uint16_t> faceEdgeStyle;   // index into edgeStyles; 0: edges not drawn
  std::vector<std::uint8_t> faceLineCorners;  // bit c: corner c is the end of a drawn edge of some face
  std::vector<EdgeStyle> edgeStyles{EdgeStyle{}};
  // 1 when the face belongs to a closed, outward-oriented shell (it bounds a solid: refraction
  // enters and leaves it); 0 for open surfaces, which transparency treats as thin sheets.
  std::vector<std::uint8_t> faceBoundsSolid;
  // Field colouring (color_by): per face 0 (not coloured) or 1 + the ColorMapKind, plus
  // kFaceFieldColor for element data; the normalised field value t in [0, 1] (NaN: none) per vertex
  // (node data: interpolated per pixel, then mapped) or per face (element data). All are empty when
  // no mesh is coloured (faceFieldT also when none is coloured by element data).
  static constexpr std::uint8_t kFaceFieldColor = 0x80;
  std::vector<std::uint8_t> faceColorMap;
  std::vector<float> vertexFieldT;
  std::vector<float> faceFieldT;
  // The first coloured mesh's map and range, for the --legend colour bar.
  struct FieldLegend {
    ColorMapKind map = ColorMapKind::Viridis;
    double low = 0;
    double high = 1;
  };
  std::optional<FieldLegend> legend;
  std::vector<Material> materials;
  std::vector<SceneLight> lights;
  std::vector<ClipPlane> clipPlanes;   // scene space
  std::vector<std::uint8_t> clipCaps;  // 1: cap closed shells cut by clipPlanes[i]
  // Each mesh's own planes ([[mesh.clip]]), which remove only its faces; empty when no mesh has any.
  FaceClipSets meshClips;
  // The shadow-catcher floor: points p with dot(p, floorNormal) = floorOffset (scene space).
  bool hasShadowCatcher = false;
  Vec3 floorNormal{0, 1, 0};
  float floorOffset = 0;
  Vec3 ambient{0, 0, 0};
  Aabb bounds;  // scene space
  // What the mesh readers warned about (MeshSourceInfo::warnings), for the CLI to print.
  std::vector<std::string> warnings;

  Vec3 toSceneSpace(const Vec3d& world) const { return toFloat(world - origin); }
};

// Reads every mesh of the description (errors point at the [[mesh]] entry or into the mesh file).
Scene buildScene(const SceneDescription& description);
// Same, with the meshes already read: meshes[i] belongs to description.meshes[i].
Scene buildScene(const SceneDescription& description, std::vector<Mesh> meshes);

}  // namespace lancer
