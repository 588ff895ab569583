// Turns a SceneDescription into a Scene: reads meshes, applies instance transforms in double
// precision, recentres everything on one origin, orients closed shells outward, resolves group
// materials, computes normals.
#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <exception>
#include <limits>
#include <map>
#include <span>
#include <utility>

#include <fmt/format.h>

#include "lancer/mesh/face_geometry.hpp"
#include "lancer/mesh/feature_edges.hpp"
#include "lancer/mesh/shell_orientation.hpp"
#include "lancer/scene/geometry_overlap.hpp"
#include "lancer/scene/instance_transform.hpp"
#include "lancer/scene/render_limits.hpp"
#include "lancer/scene/results/annotation_builder.hpp"
#include "lancer/scene/results/color_by.hpp"
#include "lancer/scene/results/volume_views.hpp"
#include "lancer/scene/results/warp.hpp"
#include "lancer/scene/scene.hpp"
#include "lancer/scene/scene_entries.hpp"
#include "lancer/scene/scene_layout.hpp"
#include "lancer/scene/scene_lights.hpp"
#include "lancer/util/check.hpp"
#include "lancer/util/huge_pages.hpp"
#include "lancer/util/parallel_for.hpp"
#include "lancer/util/stopwatch.hpp"

namespace lancer {
namespace {

// Material of each physical tag named in `groups`, checked against the mesh's groups.
std::vector<std::pair<std::int32_t, std::uint32_t>> resolveGroupMaterials(const MeshInstance& instance,
                                                                          const Mesh& mesh) {
  std::vector<std::pair<std::int32_t, std::uint32_t>> result;
  for (const GroupMaterial& entry : instance.groupMaterials) {
    std::int32_t tag = 0;
    const char* first = entry.group.data();
    const char* last = first + entry.group.size();
    const auto [end, ec] = std::from_chars(first, last, tag);
    const bool isTag = ec == std::errc() && end == last;
    bool found = false;
    for (const PhysicalGroup& group : mesh.physicalGroups) {
      if (isTag ? group.tag == tag : group.name == entry.group) {
        tag = group.tag;
        found = group.dimension == 2 || !found;
        if (group.dimension == 2) break;
      }
    }
    if (!found && isTag) {  // a tag used by faces but without a $PhysicalNames entry is fine too
      for (std::int32_t faceTag : mesh.facePhysicalTag) found = found || faceTag == tag;
      for (std::int32_t faceTag : mesh.volumeSides.outerPhysicalTag) found = found || faceTag == tag;
    }
    if (!found) {
      std::string known;
      for (const PhysicalGroup& group : mesh.physicalGroups)
        known += fmt::format("{}{}", known.empty() ? "" : ", ",
                             group.name.empty() ? std::to_string(group.tag) : group.name);
      throw InputError(entry.where, fmt::format("mesh '{}' has no physical group '{}' (its groups: {})",
                                                instance.file, entry.group, known.empty() ? "none" : known));
    }
    result.emplace_back(tag, static_cast<std::uint32_t>(entry.material));
  }
  // A face in several groups takes the most specific mapping: the group with the fewest faces, and
  // of equal ones the mapping written last. The face loop lets the last match win, so the mappings
  // are ordered from the largest group down (stable: file order among equals).
  if (!mesh.extraPhysicalGroups.empty() && result.size() > 1) {
    std::map<std::int32_t, std::uint64_t> faces;
    for (const auto& mapping : result) faces[mapping.first] = 0;
    for (std::size_t f = 0; f < mesh.faceCount(); ++f)
      for (auto& [tag, count] : faces) count += mesh.faceInPhysicalGroup(f, tag);
    std::stable_sort(result.begin(), result.end(),
                     [&](const auto& a, const auto& b) { return faces[a.first] > faces[b.first]; });
  }
  return result;
}

// Items per chunk of the parallel loops over a mesh's vertices and faces.
constexpr std::size_t kFacesPerChunk = 16384;

// One mesh instance in scene space, before it joins the scene: its positions, its closed shells
// oriented outward (the mesh's faces and tags changed in place to match), its smooth normals.
struct PlacedMesh {
  std::vector<Vec3> positions;
  std::vector<std::uint8_t> edgeMasks;  // per face, in step with the oriented faces
  ShellOrientationReport orientation;
  CornerNormals normals;
  std::vector<Vec3> faceNormals;  // unit, per face (computeCornerNormals made them on the way)
};

// `early`, for the one mesh of a scene whose accelerator is built alongside (geometry_overlap.hpp):
// the positions are placed straight into the scene's `geometry`, and the faces copied there as the
// file winds them, before the build starts over both; `geometry` outlives an error here, and
// assembleScene waits for the build before it goes.
PlacedMesh placeMesh(const MeshInstance& instance, Mesh& mesh, const InstanceTransform& transform,
                     const Vec3d& origin, int threads, StageTimes& times, SceneEntryLayout* layout,
                     GeometryOverlap* early = nullptr, SceneGeometry* geometry = nullptr) {
  const Stopwatch orient;
  PlacedMesh placed;
  std::vector<Vec3>& positions = early ? geometry->positions : placed.positions;
  positions.reserve(mesh.positions.size());
  adviseHugePages(positions);
  positions.resize(mesh.positions.size());
  parallelFor(positions.size(), threads, kFacesPerChunk, [&](std::size_t v) {
    positions[v] = toFloat(transform.apply(mesh.worldPosition(static_cast<std::uint32_t>(v))) - origin);
  });
  placed.edgeMasks = mesh.faceEdgeMask;
  placed.edgeMasks.resize(mesh.faces.size(), kAllEdges);
  // A mirroring scale (odd number of negative factors) reverses the winding; keep the file's
  // intent for open surfaces (closed shells are oriented below whatever their winding).
  const bool mirrored = instance.scale.x * instance.scale.y * instance.scale.z < 0;
  if (mirrored) {
    for (std::size_t f = 0; f < mesh.faces.size(); ++f) reverseWinding(mesh.faces[f], placed.edgeMasks[f]);
  }
  if (early) {
    geometry->faces.reserve(mesh.faces.size());
    adviseHugePages(geometry->faces);  // one fault per 2 MiB copied (64 MB at 4M faces)
    geometry->faces.assign(mesh.faces.begin(), mesh.faces.end());
    early->start(geometry->positions, geometry->faces);
  }
  // Refraction and caps tell entering from leaving by the side a ray hits, so solids must face out
  // of their material (cavity walls into the cavity).
  placed.orientation =
      orientClosedShellsOutward(positions, mesh.faces, placed.edgeMasks, mesh.facePhysicalTag,
                                mesh.volumeSides.side, threads, layout ? &layout->shells : nullptr);
  if (early && placed.orientation.flippedFaces > 0) {
    // The build's faces are no longer the scene's: it keeps its own until it is over.
    early->facesChanged(std::move(geometry->faces));
    geometry->faces = std::vector<MeshFace>();
    geometry->faces.reserve(mesh.faces.size());
    adviseHugePages(geometry->faces);
    geometry->faces.assign(mesh.faces.begin(), mesh.faces.end());
  }
  for (const std::uint32_t f : placed.orientation.reversedInterfaces) {
    std::swap(mesh.facePhysicalTag[f], mesh.volumeSides.outerPhysicalTag[f]);
    std::swap(mesh.faceEntityTag[f], mesh.volumeSides.outerEntityTag[f]);
  }
  times.add("orient", orient.seconds());  // shells, orientation, nesting, interfaces
  const Stopwatch normals;
  placed.normals =
      computeCornerNormals(positions, mesh.faces, mesh.facePhysicalTag, instance.smoothAngleDegrees, threads,
                           &placed.faceNormals, layout ? &layout->walks : nullptr);
  times.add("normals", normals.seconds());
  return placed;
}

// The mesh's vertices, faces and normals, renumbered after those already in the scene. The first
// mesh's arrays are moved in, not copied (nothing to renumber; at 4M triangles the copies and the
// fresh pages they fault in cost more than the renumbering loop).
// `placedEarly`: placeMesh put the positions and faces in `geometry` already (the scene's one mesh,
// its accelerator built alongside).
void appendGeometry(SceneGeometry& geometry, const std::vector<MeshFace>& faces, PlacedMesh& placed,
                    int threads, bool placedEarly = false) {
  LANCER_DCHECK(placed.faceNormals.size(), ==, faces.size());
  if (placedEarly) {
    for (const Vec3& p : geometry.positions) geometry.bounds.extend(p);
    geometry.cornerNormals.normals = std::move(placed.normals.normals);
    geometry.cornerNormals.faceCorner = std::move(placed.normals.faceCorner);
    geometry.faceNormals = std::move(placed.faceNormals);
    geometry.faceBoundsSolid = placed.orientation.faceBoundsSolid;
    return;
  }
  for (const Vec3& p : placed.positions) geometry.bounds.extend(p);
  if (geometry.faces.empty() && geometry.positions.empty() && geometry.cornerNormals.normals.empty()) {
    geometry.positions = std::move(placed.positions);
    geometry.cornerNormals.normals = std::move(placed.normals.normals);
    geometry.cornerNormals.faceCorner = std::move(placed.normals.faceCorner);
    geometry.faceNormals = std::move(placed.faceNormals);
    geometry.faces.reserve(faces.size());
    adviseHugePages(geometry.faces);  // one fault per 2 MiB copied (64 MB at 4M faces)
    geometry.faces.assign(faces.begin(), faces.end());
    geometry.faceBoundsSolid = placed.orientation.faceBoundsSolid;
    return;
  }
  const auto vertexBase = static_cast<std::uint32_t>(geometry.positions.size());
  const auto normalBase = static_cast<std::uint32_t>(geometry.cornerNormals.normals.size());
  geometry.positions.insert(geometry.positions.end(), placed.positions.begin(), placed.positions.end());
  geometry.cornerNormals.normals.insert(geometry.cornerNormals.normals.end(), placed.normals.normals.begin(),
                                        placed.normals.normals.end());
  const std::size_t faceBase = geometry.faces.size();
  geometry.faces.resize(faceBase + faces.size());
  geometry.faceNormals.resize(faceBase + faces.size());
  geometry.cornerNormals.faceCorner.resize(faceBase + faces.size());
  geometry.faceBoundsSolid.insert(geometry.faceBoundsSolid.end(), placed.orientation.faceBoundsSolid.begin(),
                                  placed.orientation.faceBoundsSolid.end());
  parallelFor(faces.size(), threads, kFacesPerChunk, [&](std::size_t f) {
    MeshFace face = faces[f];
    auto corners = placed.normals.faceCorner[f];
    for (int c = 0; c < face.cornerCount(); ++c) {
      face.vertex[c] += vertexBase;
      corners[c] += normalBase;
    }
    geometry.faces[faceBase + f] = face;
    geometry.faceNormals[faceBase + f] = placed.faceNormals[f];  // faceNormal(geometry.positions, face)
    geometry.cornerNormals.faceCorner[faceBase + f] = corners;
  });
}

// The materials on both sides of each of the mesh's faces (the scene's from faceBase on), and their
// shading.
void appendAppearance(SceneAppearance& appearance, std::size_t faceBase, const MeshInstance& instance,
                      const Mesh& mesh, const ShellOrientationReport& orientation,
                      const std::vector<std::pair<std::int32_t, std::uint32_t>>& groupMaterials,
                      ShadingMode shading) {
  // The material of the faces of `entity` whose first group is `physical` (groupMaterials is in
  // order of increasing precedence: the last mapping that names one of their groups wins).
  auto lookUp = [&](std::int32_t physical, std::int32_t entity) {
    auto material = static_cast<std::uint32_t>(instance.material);
    for (const auto& [tag, groupMaterial] : groupMaterials)
      if (mesh.inPhysicalGroup(physical, entity, tag)) material = groupMaterial;
    return material;
  };
  // Consecutive faces mostly share their entity: the last answer is kept.
  std::int32_t lastPhysical = 0, lastEntity = 0;
  std::uint32_t lastMaterial = lookUp(0, 0);
  auto materialOf = [&](std::int32_t physical, std::int32_t entity) {
    if (physical != lastPhysical || entity != lastEntity) {
      lastPhysical = physical;
      lastEntity = entity;
      lastMaterial = lookUp(physical, entity);
    }
    return lastMaterial;
  };
  appearance.faceMaterial.reserve(faceBase + mesh.faces.size());
  appearance.faceShading.reserve(faceBase + mesh.faces.size());
  std::size_t nextRegionTag = 0;  // orientation.faceRegionTags is in face order
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    // A face between two regions of a surface-only mesh takes its region's group, that one alone.
    const bool regionTagged = nextRegionTag < orientation.faceRegionTags.size() &&
                              orientation.faceRegionTags[nextRegionTag].first == f;
    appearance.faceMaterial.push_back(regionTagged
                                          ? materialOf(orientation.faceRegionTags[nextRegionTag++].second, 0)
                                          : materialOf(mesh.facePhysicalTag[f], mesh.faceEntityTag[f]));
    // The material in front of the face: the outer volume of an interface, or the solid of another
    // group that a closed surface lies in (a steel ball drawn inside a glass one).
    std::optional<std::uint32_t> outer;
    if (mesh.volumeSides.isInterface(f))
      outer = materialOf(mesh.volumeSides.outerPhysicalTag[f], mesh.volumeSides.outerEntityTag[f]);
    if (!orientation.faceEnclosedBy.empty() &&
        orientation.faceEnclosedBy[f] != ShellOrientationReport::kNotEnclosed)
      outer = materialOf(orientation.faceEnclosedBy[f], 0);
    if (outer) {
      appearance.faceOuterMaterial.resize(faceBase + f, SceneAppearance::kNoMaterial);
      appearance.faceOuterMaterial.push_back(*outer);
    }
    appearance.faceShading.push_back(shading);
  }
}

// The mesh's edges to draw and their style (style 0, none, when the mesh draws no edges).
void appendEdges(EdgeOverlay& overlay, const MeshInstance& instance, Mesh& mesh,
                 std::vector<std::uint8_t> edgeMasks) {
  std::uint16_t edgeStyle = 0;
  if (instance.edges) {
    overlay.styles.push_back({instance.edges->widthPixels, instance.edges->color});
    edgeStyle = static_cast<std::uint16_t>(overlay.styles.size() - 1);
    if (instance.edges->featuresOnly) {
      mesh.faceEdgeMask = edgeMasks;  // in step with the oriented faces
      edgeMasks = featureEdgeMasks(mesh, instance.edges->featureAngleDegrees);
    }
  }
  overlay.faceEdgeMask.insert(overlay.faceEdgeMask.end(), edgeMasks.begin(), edgeMasks.end());
  overlay.faceEdgeStyle.resize(overlay.faceEdgeStyle.size() + mesh.faces.size(), edgeStyle);
}

// The planes of a mesh whose faces start at faceBase and run to the scene's last face.
void appendMeshClips(SceneClipping& clipping, const SceneGeometry& geometry,
                     const std::vector<ClipSettings>& clips, std::size_t faceBase) {
  FaceClipSets& sets = clipping.perMesh;
  FaceClipRange range;
  range.faceBegin = static_cast<std::uint32_t>(faceBase);
  range.faceEnd = static_cast<std::uint32_t>(geometry.faces.size());
  range.planeBegin = static_cast<std::uint32_t>(sets.planes.size());
  for (const ClipSettings& clip : clips) {
    sets.planes.push_back({geometry.toSceneSpace(clip.point), toFloat(clip.normal)});
    sets.caps.push_back(clip.cap ? 1 : 0);
  }
  range.planeEnd = static_cast<std::uint32_t>(sets.planes.size());
  sets.ranges.push_back(range);
}

// Kept when some mesh draws its edges, with the corners where drawn edges end, so that faces
// meeting a line only at a corner draw its end too.
void finishEdgeOverlay(Scene& scene, EdgeOverlay overlay) {
  if (overlay.styles.size() <= 1) return;
  const std::vector<MeshFace>& faces = scene.geometry.faces;
  std::vector<std::uint8_t> onLine(scene.geometry.positions.size(), 0);
  for (std::size_t f = 0; f < faces.size(); ++f) {
    if (overlay.faceEdgeStyle[f] == 0) continue;
    const MeshFace& face = faces[f];
    const int n = face.cornerCount();
    for (int c = 0; c < n; ++c)
      if (overlay.faceEdgeMask[f] & (1u << c)) onLine[face.vertex[c]] = onLine[face.vertex[(c + 1) % n]] = 1;
  }
  overlay.faceLineCorners.assign(faces.size(), 0);
  for (std::size_t f = 0; f < faces.size(); ++f) {
    const MeshFace& face = faces[f];
    for (int c = 0; c < face.cornerCount(); ++c)
      if (onLine[face.vertex[c]]) overlay.faceLineCorners[f] |= static_cast<std::uint8_t>(1u << c);
  }
  LANCER_DCHECK(overlay.faceEdgeMask.size(), ==, faces.size());
  LANCER_DCHECK(overlay.faceEdgeStyle.size(), ==, faces.size());
  scene.edges = std::move(overlay);
}

}  // namespace

Scene buildScene(const SceneDescription& description, int threads, StageTimes* times) {
  SceneDescription expanded = description;
  std::vector<std::shared_ptr<const VolumeMesh>> volumes;
  std::vector<Mesh> meshes = readSceneMeshes(expanded, threads, times, &volumes);
  attachAnnotationVolumes(expanded, volumes);
  addVolumeViews(expanded, meshes, volumes);
  return buildScene(expanded, std::move(meshes), threads, times);
}

namespace {

// Waits for the accelerator built alongside when the scene's preparation fails: it reads the
// scene's positions and faces, which go as the error unwinds.
class AbandonOnError {
 public:
  explicit AbandonOnError(GeometryOverlap* overlap) : overlap_(overlap) {}
  ~AbandonOnError() {
    if (overlap_ && std::uncaught_exceptions() > exceptions_) overlap_->abandon();
  }
  AbandonOnError(const AbandonOnError&) = delete;
  AbandonOnError& operator=(const AbandonOnError&) = delete;

 private:
  GeometryOverlap* overlap_;
  int exceptions_ = std::uncaught_exceptions();
};

// `overlap`: with a scene of one mesh, its accelerator's build is started there as soon as the
// positions are placed (geometry_overlap.hpp).
Scene assembleScene(const SceneDescription& description, std::vector<SceneEntry> entries,
                    std::vector<Material> materials, std::vector<std::string> warnings, int threads,
                    StageTimes& times, SceneLayout* layout = nullptr, GeometryOverlap* overlap = nullptr) {
  const Stopwatch whole;
  const double secondsBefore = times.totalSeconds();
  Scene scene;
  const AbandonOnError waitOnError(overlap);  // after `scene`: gone before it
  GeometryOverlap* early = entries.size() == 1 ? overlap : nullptr;
  scene.warnings = std::move(warnings);
  scene.warnings.insert(scene.warnings.begin(), description.notes.begin(), description.notes.end());
  SceneGeometry& geometry = scene.geometry;
  SceneAppearance& appearance = scene.appearance;
  appearance.materials = std::move(materials);
  appearance.ambient = description.ambient;

  // One origin for the whole scene: the centre of all instances' world bounds, in double.
  std::vector<InstanceTransform> transforms;
  Aabbd worldBounds;
  for (const SceneEntry& entry : entries) {
    transforms.emplace_back(entry.instance);
    for (const MeshFace& face : entry.mesh.faces)
      for (int c = 0; c < face.cornerCount(); ++c)
        worldBounds.extend(transforms.back().apply(entry.mesh.worldPosition(face.vertex[c])));
  }
  geometry.origin = worldBounds.empty() ? Vec3d{} : worldBounds.center();

  // Gathered mesh by mesh, kept at the end when some mesh uses them.
  EdgeOverlay overlay;
  std::vector<EntryAnnotation> annotations;
  for (std::size_t i = 0; i < entries.size(); ++i) {
    const MeshInstance& instance = entries[i].instance;
    Mesh& mesh = entries[i].mesh;
    scene.warnings.insert(scene.warnings.end(), mesh.source.warnings.begin(), mesh.source.warnings.end());
    const auto groupMaterials = resolveGroupMaterials(instance, mesh);
    SceneEntryLayout* entryLayout = layout ? &layout->entries.emplace_back() : nullptr;
    // Taken before placeMesh: with the build alongside, it places the positions and faces in
    // `geometry` itself.
    const auto vertexBase = static_cast<std::uint32_t>(geometry.positions.size());
    const std::size_t faceBase = geometry.faces.size();
    PlacedMesh placed = placeMesh(instance, mesh, transforms[i], geometry.origin, threads, times, entryLayout,
                                  early, &geometry);
    if (entryLayout) {
      entryLayout->meshIndex = entries[i].meshIndex;
      entryLayout->undeformedCopy = entries[i].undeformedCopy;
      entryLayout->vertexBase = vertexBase;
      entryLayout->vertexCount = static_cast<std::uint32_t>(mesh.positions.size());
      entryLayout->faceBase = static_cast<std::uint32_t>(faceBase);
      entryLayout->faceCount = static_cast<std::uint32_t>(mesh.faces.size());
      entryLayout->normalBase = static_cast<std::uint32_t>(geometry.cornerNormals.normals.size());
      entryLayout->collapsedFaces = entries[i].collapsedFaces;
      entryLayout->reversedInterfaces = placed.orientation.reversedInterfaces;
      entryLayout->featureEdges = instance.edges && instance.edges->featuresOnly;
    }
    appendGeometry(geometry, mesh.faces, placed, threads, early != nullptr);
    appendAppearance(appearance, faceBase, instance, mesh, placed.orientation, groupMaterials,
                     instance.shading.value_or(description.render.shading));
    appendEdges(overlay, instance, mesh, placed.edgeMasks);
    const std::optional<FieldColoring>& coloring = entries[i].coloring;
    annotations.push_back({&instance, coloring ? &*coloring : nullptr,
                           entries[i].colorBy ? &*entries[i].colorBy : nullptr,
                           entries[i].fields ? entries[i].fields : &mesh, vertexBase,
                           geometry.positions.size(), faceBase, geometry.faces.size()});
    if (!instance.clips.empty() && !mesh.faces.empty())
      appendMeshClips(scene.clipping, geometry, instance.clips, faceBase);
  }
  if (!appearance.faceOuterMaterial.empty())
    appearance.faceOuterMaterial.resize(geometry.faces.size(), SceneAppearance::kNoMaterial);
  annotateScene(scene, description.when, annotations);
  finishEdgeOverlay(scene, std::move(overlay));

  // Every per-face array in step with the faces (the tracer indexes them all by face).
  LANCER_DCHECK(geometry.faceNormals.size(), ==, geometry.faces.size());
  LANCER_DCHECK(geometry.cornerNormals.faceCorner.size(), ==, geometry.faces.size());
  LANCER_DCHECK(geometry.faceBoundsSolid.size(), ==, geometry.faces.size());
  LANCER_DCHECK(appearance.faceMaterial.size(), ==, geometry.faces.size());
  LANCER_DCHECK(appearance.faceShading.size(), ==, geometry.faces.size());
  if (!appearance.faceOuterMaterial.empty())
    LANCER_DCHECK(appearance.faceOuterMaterial.size(), ==, geometry.faces.size());

  if (description.floor) scene.shadowCatcher = shadowCatcherOf(*description.floor, geometry);
  for (const ClipSettings& clip : description.clips) {
    scene.clipping.planes.push_back({geometry.toSceneSpace(clip.point), toFloat(clip.normal)});
    scene.clipping.caps.push_back(clip.cap ? 1 : 0);
  }
  appearance.lights = sceneLights(description, geometry);
  if (description.environment)
    scene.environment = sceneEnvironment(*description.environment, toFloat(description.camera.up));
  if (description.render.integrator == IntegratorKind::Path && description.ambientSet)
    scene.warnings.push_back(formatInputWarning(
        SourceLocation{description.path},
        "[ambient] and ka are not used by integrator = \"path\": light from all around comes from "
        "[environment] (docs/lighting.md)"));
  // "scene": the rest of this call (placing, gathering geometry, materials, edges, fields, clips).
  times.add("scene", whole.seconds() - (times.totalSeconds() - secondsBefore));
  return scene;
}

}  // namespace

Scene buildScene(const SceneDescription& description, std::vector<Mesh> meshes, int threads,
                 StageTimes* timesOrNull, GeometryOverlap* overlap) {
  if (hasAnnotationMeshes(description)) {  // arrows are meshes of their own, built once here
    SceneDescription annotated = description;
    std::vector<Mesh> annotations = addAnnotationMeshes(annotated, meshes);
    for (Mesh& mesh : annotations) meshes.push_back(std::move(mesh));
    return buildScene(annotated, std::move(meshes), threads, timesOrNull, overlap);
  }
  StageTimes unused;
  StageTimes& times = timesOrNull ? *timesOrNull : unused;
  // Each mesh holds its own fields: colours are resolved before the warp moves its positions and
  // drops faces (element colours follow).
  const std::vector<const Mesh*> fields(meshes.size(), nullptr);
  std::vector<Material> materials = description.materials;
  std::vector<std::string> warnings;
  std::vector<SceneEntry> entries = sceneEntries(description, std::move(meshes), fields, materials, warnings);
  return assembleScene(description, std::move(entries), std::move(materials), std::move(warnings), threads,
                       times, nullptr, overlap);
}

Scene buildSceneAt(const SceneDescription& description, const std::vector<Mesh>& meshes, int threads,
                   StageTimes* timesOrNull, SceneLayout* layout) {
  StageTimes unused;
  StageTimes& times = timesOrNull ? *timesOrNull : unused;
  // Arrows of the step the scene names: meshes of their own, holding their one field (the meshes as
  // read, with every step, are not copied).
  SceneDescription annotated = description;
  std::vector<Mesh> annotations = addAnnotationMeshes(annotated, meshes);
  std::vector<Mesh> geometry;
  std::vector<const Mesh*> fields;
  for (const Mesh& mesh : meshes) {
    geometry.push_back(geometryOf(mesh));
    fields.push_back(&mesh);
  }
  for (Mesh& mesh : annotations) {
    geometry.push_back(std::move(mesh));
    fields.push_back(nullptr);  // its own
  }
  std::vector<Material> materials = annotated.materials;
  std::vector<std::string> warnings;
  std::vector<SceneEntry> entries = sceneEntries(annotated, std::move(geometry), fields, materials, warnings);
  if (layout) *layout = SceneLayout{};
  return assembleScene(annotated, std::move(entries), std::move(materials), std::move(warnings), threads,
                       times, layout);
}

}  // namespace lancer
