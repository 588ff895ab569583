#include "lancer/scene/scene_keys.hpp"

#include <array>

namespace lancer {
namespace {

constexpr std::array<std::string_view, 10> kDocumentKeys = {
    "render", "camera", "ambient", "light", "material", "mesh", "animation", "clip", "floor", "environment"};
constexpr std::array<std::string_view, 24> kRenderKeys = {
    "width",       "height",     "samples",     "max_depth", "sampler",
    "shading",     "background", "output",      "srgb",      "encoding",
    "tonemap",     "exposure",   "bit_depth",   "denoise",   "adaptive_threshold",
    "step",        "integrator", "max_bounces", "noise",     "adaptive_noise",
    "ao_distance", "quality",    "lossless",    "dpi"};
constexpr std::array<std::string_view, 8> kCameraKeys = {
    "projection", "position", "look_at", "up", "up_axis", "fov", "view_height", "gmsh_view"};
constexpr std::array<std::string_view, 1> kAmbientKeys = {"intensity"};
constexpr std::array<std::string_view, 9> kLightKeys = {
    "type", "position", "intensity", "attenuation", "direction", "angle", "radius", "width", "height"};
constexpr std::array<std::string_view, 10> kMaterialKeys = {
    "ka",           "kd",  "ks",      "shininess",  "reflectivity",
    "transparency", "ior", "fresnel", "absorption", "emission"};
constexpr std::array<std::string_view, 20> kMeshKeys = {
    "file",  "views",      "material", "shading",  "smooth_angle", "translate",  "rotate",
    "scale", "groups",     "edges",    "color_by", "isolines",     "arrows",     "clip",
    "warp",  "undeformed", "slice",    "skin",     "isosurfaces",  "streamlines"};
constexpr std::array<std::string_view, 4> kEdgeKeys = {"width", "color", "only", "feature_angle"};
constexpr std::array<std::string_view, 10> kColorByKeys = {"field",     "step",  "map",   "scale", "range",
                                                           "component", "title", "units", "bands", "legend"};
constexpr std::array<std::string_view, 2> kWarpKeys = {"field", "factor"};
constexpr std::array<std::string_view, 7> kArrowKeys = {"field", "step",   "max_count", "grid",
                                                        "scale", "length", "color"};
constexpr std::array<std::string_view, 7> kIsolineKeys = {"field",  "step",  "component", "count",
                                                          "values", "color", "width"};
constexpr std::array<std::string_view, 3> kClipKeys = {"point", "normal", "cap"};
constexpr std::array<std::string_view, 2> kSliceKeys = {"point", "normal"};
constexpr std::array<std::string_view, 6> kIsosurfaceKeys = {"field", "step",  "values",
                                                             "count", "color", "color_by"};
constexpr std::array<std::string_view, 14> kStreamlineKeys = {
    "field",       "step",           "count",  "seed_line",  "seed_points", "seed_center", "seed_normal",
    "seed_radius", "seed_rectangle", "radius", "max_length", "direction",   "color",       "color_by"};
constexpr std::array<std::string_view, 3> kFloorKeys = {"shadow_catcher", "height", "normal"};
constexpr std::array<std::string_view, 10> kAnimationKeys = {
    "frames", "fps", "orbit", "axis", "center", "degrees", "over", "range", "label", "label_position"};
constexpr std::array<std::string_view, 8> kEnvironmentKeys = {"color", "zenith",   "horizon",  "ground",
                                                              "map",   "rotation", "strength", "visible"};

constexpr std::array<SceneTableKeys, 20> kSceneTables = {{
    {SceneTable::Document, "", kDocumentKeys},
    {SceneTable::Render, "render", kRenderKeys},
    {SceneTable::Camera, "camera", kCameraKeys},
    {SceneTable::Ambient, "ambient", kAmbientKeys},
    {SceneTable::Light, "light", kLightKeys},
    {SceneTable::Material, "material.NAME", kMaterialKeys},
    {SceneTable::Mesh, "mesh", kMeshKeys},
    {SceneTable::MeshEdges, "mesh.edges", kEdgeKeys},
    {SceneTable::MeshColorBy, "mesh.color_by", kColorByKeys},
    {SceneTable::MeshIsolines, "mesh.isolines", kIsolineKeys},
    {SceneTable::MeshArrows, "mesh.arrows", kArrowKeys},
    {SceneTable::MeshClip, "mesh.clip", kClipKeys},
    {SceneTable::Clip, "clip", kClipKeys},
    {SceneTable::Floor, "floor", kFloorKeys},
    {SceneTable::Animation, "animation", kAnimationKeys},
    {SceneTable::MeshWarp, "mesh.warp", kWarpKeys},
    {SceneTable::Environment, "environment", kEnvironmentKeys},
    {SceneTable::MeshSlice, "mesh.slice", kSliceKeys},
    {SceneTable::MeshIsosurfaces, "mesh.isosurfaces", kIsosurfaceKeys},
    {SceneTable::MeshStreamlines, "mesh.streamlines", kStreamlineKeys},
}};

constexpr bool inEnumOrder() {
  for (std::size_t i = 0; i < kSceneTables.size(); ++i)
    if (static_cast<std::size_t>(kSceneTables[i].table) != i) return false;
  return true;
}
static_assert(inEnumOrder(), "kSceneTables lists the tables in the order of SceneTable");

}  // namespace

std::span<const std::string_view> sceneKeys(SceneTable table) {
  return kSceneTables[static_cast<std::size_t>(table)].keys;
}

std::span<const SceneTableKeys> sceneFileKeys() { return kSceneTables; }

}  // namespace lancer
