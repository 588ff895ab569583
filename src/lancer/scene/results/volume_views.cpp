#include "lancer/scene/results/volume_views.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "lancer/mesh/volume/field_line_tubes.hpp"
#include "lancer/mesh/volume/field_lines.hpp"
#include "lancer/mesh/volume/planar_domain.hpp"
#include "lancer/mesh/volume/volume_cut.hpp"
#include "lancer/mesh/volume/volume_locator.hpp"
#include "lancer/scene/camera_placement.hpp"
#include "lancer/scene/instance_transform.hpp"
#include "lancer/scene/render_limits.hpp"
#include "lancer/scene/results/annotation_kinds.hpp"
#include "lancer/scene/results/isolines.hpp"
#include "lancer/scene/results/streamline_seeds.hpp"
#include "lancer/scene/results/warp.hpp"
#include "lancer/scene/scene_entries.hpp"

namespace lancer {
namespace {

// A cut that lies on a capped clipping plane is moved this fraction of the volume's diagonal into
// the kept side, where rays meet it before the plane's grey cap (scene_queries.cpp).
constexpr double kCapOffset = 1e-5;

// The volume's cut added to `into` (a mesh of cuts of the same volume), with every field of the
// volume carried over, in the volume's field order.
void appendCut(Mesh& into, const VolumeCut& cut, const VolumeMesh& volume) {
  const auto vertexBase = static_cast<std::uint32_t>(into.positions.size());
  into.positions.insert(into.positions.end(), cut.surface.positions.begin(), cut.surface.positions.end());
  for (MeshFace face : cut.surface.faces) {
    for (int c = 0; c < 3; ++c) face.vertex[c] += vertexBase;
    into.faces.push_back(face);
  }
  into.facePhysicalTag.insert(into.facePhysicalTag.end(), cut.surface.facePhysicalTag.begin(),
                              cut.surface.facePhysicalTag.end());
  into.faceEntityTag.insert(into.faceEntityTag.end(), cut.surface.faceEntityTag.begin(),
                            cut.surface.faceEntityTag.end());
  into.faceEdgeMask.insert(into.faceEdgeMask.end(), cut.surface.faceEdgeMask.begin(),
                           cut.surface.faceEdgeMask.end());
  const bool first = into.fields.empty();
  for (std::size_t k = 0; k < volume.fields.size(); ++k) {
    MeshField field = cutField(cut, volume, volume.fields[k]);
    if (first) {
      into.fields.push_back(std::move(field));
    } else {
      std::vector<float>& values = into.fields[k].values;
      values.insert(values.end(), field.values.begin(), field.values.end());
    }
  }
}

Mesh emptyCutMesh(const VolumeMesh& volume, const Mesh& parent, const std::string& what) {
  Mesh mesh;
  mesh.origin = volume.origin;
  mesh.physicalGroups = parent.physicalGroups;
  mesh.source.path = fmt::format("{} ({})", parent.source.path, what);
  return mesh;
}

// The instance that draws a cut of `parent`'s volume: its placement, material, groups, clips,
// colours, isolines and arrows; not its views, warp, edges or volume requests.
MeshInstance cutInstance(const MeshInstance& parent) {
  MeshInstance child = parent;
  child.views.clear();
  child.warp.reset();
  child.undeformed = UndeformedStyle::None;
  child.edges.reset();
  child.volume = VolumeViews{};
  return child;
}

// The instance of an isosurface's or a field line's mesh: the parent's placement and clips, one
// `color`, or coloured by the field `field` with the parent's map (its legend when the field is the
// parent's own).
MeshInstance colouredChild(const MeshInstance& parent, const std::optional<Vec3>& color,
                           const std::string& field, const SourceLocation& where,
                           std::vector<Material>& materials, const char* name) {
  MeshInstance child = cutInstance(parent);
  child.isolines.reset();
  child.annotations.clear();
  child.groupMaterials.clear();  // one colour, or the field's
  if (color) {
    child.colorBy.reset();
    Material material = materials[static_cast<std::size_t>(parent.material)];
    material.name = name;
    material.ka = material.kd = *color;
    materials.push_back(material);
    child.material = static_cast<int>(materials.size() - 1);
    return child;
  }
  ColorBy colorBy = parent.colorBy.value_or(ColorBy{});
  if (!parent.colorBy || parent.colorBy->field != field) {
    colorBy.field = field;
    colorBy.component = FieldComponent{};
    colorBy.title.reset();
    colorBy.units.clear();
    colorBy.range.reset();
  }
  colorBy.where = where;
  colorBy.paintsSurface = true;
  child.colorBy = colorBy;
  return child;
}

// The step of a field that a volume view shows: its own, else the scene's, else the first.
const VolumeField* viewStep(const VolumeMesh& volume, const std::string& name, std::optional<int> step,
                            const StepSelection& when) {
  const std::vector<const VolumeField*> steps = volume.fieldSteps(name);
  if (steps.empty()) return nullptr;
  const int wanted = step.value_or(when.step.value_or(steps.front()->step));
  for (const VolumeField* field : steps)
    if (field->step == wanted) return field;
  return step || when.step ? nullptr : steps.front();
}

std::string fieldList(const VolumeMesh& volume) {
  std::vector<std::string> names;
  for (const VolumeField& field : volume.fields)
    if (std::find(names.begin(), names.end(), field.name) == names.end()) names.push_back(field.name);
  return names.empty() ? "none" : fmt::format("{}", fmt::join(names, ", "));
}

std::pair<double, double> scalarRange(const VolumeField& field) {
  double low = std::numeric_limits<double>::infinity(), high = -low;
  for (const float value : field.values) {
    if (!std::isfinite(value)) continue;
    low = std::min<double>(low, value);
    high = std::max<double>(high, value);
  }
  return {low, high};
}

Vec3d volumeCentre(const VolumeMesh& volume) {
  Aabbd box;
  for (const Vec3& node : volume.nodes) box.extend(toDouble(node));
  return box.center();
}

double volumeDiagonal(const VolumeMesh& volume) {
  Aabbd box;
  for (const Vec3& node : volume.nodes) box.extend(toDouble(node));
  return length(box.extent());
}

const VolumeField& isosurfaceField(const VolumeMesh& volume, const IsosurfaceSpec& spec,
                                   const StepSelection& when, const std::string& file) {
  const std::vector<const VolumeField*> steps = volume.fieldSteps(spec.field);
  if (steps.empty())
    throw InputError(spec.where, fmt::format("isosurfaces of '{}': {} has no such field inside its volume "
                                             "(its fields: {})",
                                             spec.field, file, fieldList(volume)));
  if (steps.front()->components != 1)
    throw InputError(
        spec.where,
        fmt::format("isosurfaces of '{}': it has {} components, and an isosurface is where a scalar "
                    "takes a value; give a scalar field (colour the surfaces by this one with "
                    "color_by = \"{}\")",
                    spec.field, steps.front()->components, spec.field));
  const int step = spec.step.value_or(when.step.value_or(steps.front()->step));
  for (const VolumeField* field : steps)
    if (field->step == step) return *field;
  if (!spec.step && !when.step) return *steps.front();
  throw InputError(spec.where, fmt::format("isosurfaces of '{}': it has no step {}", spec.field, step));
}

// The mesh a source's isosurfaces make of `field` (the step or time shown): each of its values inside
// the field's range, the others added to `outside` when given.
Mesh isosurfaceMesh(const VolumeViewSource& source, const VolumeField& field, std::vector<double>* outside) {
  const VolumeMesh& volume = *source.volume;
  Mesh parent;
  parent.physicalGroups = source.groups;
  parent.source.path = source.path;
  Mesh surfaces = emptyCutMesh(volume, parent, "isosurfaces");
  const auto [low, high] = scalarRange(field);
  // Element and element-node data are cut at their node means: one surface, smooth and closed.
  const VolumeField atNodes = nodeMeans(volume, field);
  const CellLevels levels = [&](std::uint32_t cell, float* out) {
    cellPointValues(volume, atNodes, cell, out);
  };
  for (const double value : source.values) {
    if (!(value >= low && value <= high)) {
      if (outside) outside->push_back(value);
      continue;
    }
    appendCut(surfaces, cutVolume(volume, levels, static_cast<float>(value), true), volume);
  }
  return surfaces;
}

// The field lines of a source's `field` (the step or time shown) from its seeds.
std::vector<FieldLine> sourceFieldLines(const VolumeViewSource& source, const VolumeField& field,
                                        const VolumeLocator& locator, const std::vector<Vec3d>& seeds) {
  const StreamlineSpec& spec = *source.parent.volume.streamlines;
  FieldLineSettings settings;
  settings.forward = spec.forward;
  settings.backward = spec.backward;
  if (spec.maxLength) settings.maxLength = *spec.maxLength;
  // Element and element-node data follow their node means: a field that jumps at every face
  // (a gradient of P1 elements) turns lines back and forth where its neighbours disagree.
  VolumeField followed = nodeMeans(*source.volume, field);
  if (source.planar) {
    projectIntoPlane(followed, source.planar->normal);
    settings.cellSize = source.planar->cellSize;
  }
  return traceFieldLines(*source.volume, locator, followed, seeds, settings);
}

// The tubes of a source's field lines; on a planar domain, lying on its plane on the side it is seen
// from (their lowest point a hundredth of their radius above it).
Mesh sourceTubes(const VolumeViewSource& source, const VolumeLocator& locator, std::vector<FieldLine> lines) {
  const VolumeMesh& volume = *source.volume;
  const StreamlineSpec& spec = *source.parent.volume.streamlines;
  const double radius = spec.radius
                            ? *spec.radius / std::max(length(source.parent.scale), 1e-300) * std::sqrt(3.0)
                            : 0.003 * volumeDiagonal(volume);
  if (source.planar) liftOntoPlane(lines, *source.planar, source.planeSide * 1.01 * radius);
  Mesh tubes = fieldLineTubes(volume, locator, lines, radius);
  tubes.source.path = fmt::format("{} (streamlines)", source.path);
  return tubes;
}

}  // namespace

const std::string& VolumeViewSource::field() const {
  return streamlines ? parent.volume.streamlines->field : parent.volume.isosurfaces->field;
}

std::vector<double> volumeViewTimes(const VolumeViewSource& source) {
  std::vector<double> times;
  for (const auto& [time, step] : volumeFieldTimeline(*source.volume, source.field())) times.push_back(time);
  return times;
}

Mesh remakeVolumeView(const VolumeViewSource& source, double time) {
  const VolumeField field = volumeFieldAt(*source.volume, source.field(), time);
  if (!source.streamlines) return isosurfaceMesh(source, field, nullptr);
  const VolumeLocator locator(*source.volume);
  const std::vector<Vec3d> seeds = streamlineSeeds(*source.parent.volume.streamlines, *source.volume, locator,
                                                   InstanceTransform(source.parent), source.planar.get());
  return sourceTubes(source, locator, sourceFieldLines(source, field, locator, seeds));
}

namespace {

// Where the first of a mesh's volume views was asked for (any() is true).
const SourceLocation& volumeViewsWhere(const VolumeViews& views) {
  if (!views.slices.empty()) return views.slices.front().where;
  return views.isosurfaces ? views.isosurfaces->where : views.streamlines->where;
}

// The one-layer volume of a mesh without volume elements whose field lines are asked for; throws
// InputError when its faces are not in one plane.
std::shared_ptr<const PlanarDomain> flatDomain(const Mesh& mesh, const MeshInstance& instance) {
  const SourceLocation& where = instance.volume.streamlines->where;
  const PlaneFit fit = fitPlane(mesh);
  if (!(fit.diagonal > 0))
    throw InputError(where, fmt::format("streamlines of '{}': '{}' has no volume elements and no faces to "
                                        "trace them across",
                                        instance.volume.streamlines->field, instance.file));
  if (!fit.flat()) {
    const Vec3d p = fit.farthestVertex + mesh.origin;
    throw InputError(
        where, fmt::format("streamlines of '{}': '{}' has no volume elements and its faces are not in one "
                           "plane (the vertex at ({:.6g}, {:.6g}, {:.6g}) is {:.3g} off the plane of the "
                           "others, more than a millionth of the mesh's size {:.3g}); field lines are "
                           "traced inside volumes (tetrahedra, hexahedra, prisms, pyramids) or across a "
                           "flat 2D mesh",
                           instance.volume.streamlines->field, instance.file, p.x, p.y, p.z, fit.farthest,
                           fit.diagonal));
  }
  return std::make_shared<const PlanarDomain>(planarDomain(mesh, fit));
}

// The side of a planar domain's plane the camera sees (+1: its normal's), in the mesh's frame: the
// camera's position, else the automatic camera's direction.
double sideSeen(const CameraSettings& camera, const InstanceTransform& transform,
                const PlanarDomain& domain) {
  const Vec3d origin = domain.volume.origin;
  const Vec3d towards = camera.position
                            ? transform.toLocal(*camera.position) - origin - domain.point
                            : transform.toLocal(camera.viewFrom) - transform.toLocal(Vec3d{0, 0, 0});
  return dot(towards, domain.normal) < 0 ? -1.0 : 1.0;
}

// Field-line tubes whose radius is given in pixels, kept to be made again (fitPixelTubes).
struct PixelTubes {
  std::size_t mesh;  // their index in the meshes
  std::shared_ptr<VolumeViewSource> source;
  std::shared_ptr<const VolumeLocator> locator;
  std::vector<FieldLine> lines;
  double pixels;
};

// Tubes sized in pixels are first made for the camera that frames the meshes as read; the picture's
// camera frames what the scene then holds (tubes past the skin, a hidden skin, slices, isosurfaces),
// whose pixel may be several percent larger or smaller. Their radius is made again for the pixel of
// the camera that frames the meshes as they now are, until the two agree to a thousandth (the tubes'
// own radius moves the bounds a little).
void fitPixelTubes(const SceneDescription& description, std::vector<Mesh>& meshes,
                   std::vector<PixelTubes>& tubes, const CameraSettings& seenBy) {
  constexpr int kMostRemakes = 3;
  constexpr double kAgreement = 1e-3;
  for (int remake = 0; remake < kMostRemakes && !tubes.empty(); ++remake) {
    const double pixel = pixelSizeAtTarget(seenBy, warpedWorldBounds(description, meshes),
                                           description.render.width, description.render.height);
    bool changed = false;
    for (PixelTubes& made : tubes) {
      double& radius = *made.source->parent.volume.streamlines->radius;
      if (std::abs(made.pixels * pixel - radius) <= kAgreement * radius) continue;
      radius = made.pixels * pixel;
      meshes[made.mesh] = sourceTubes(*made.source, *made.locator, made.lines);
      changed = true;
    }
    if (!changed) return;
  }
}

}  // namespace

bool needsVolume(const SceneDescription& description, const MeshInstance& instance) {
  if (instance.volume.any() || annotationsSampleVolume(instance)) return true;
  if (!instance.colorBy || !instance.colorBy->paintsSurface) return false;
  const auto capped = [](const std::vector<ClipSettings>& clips) {
    return std::any_of(clips.begin(), clips.end(), [](const ClipSettings& clip) { return clip.cap; });
  };
  return capped(description.clips) || capped(instance.clips);
}

void addVolumeViews(SceneDescription& description, std::vector<Mesh>& meshes,
                    const std::vector<std::shared_ptr<const VolumeMesh>>& volumes) {
  const std::size_t original = std::min(description.meshes.size(), volumes.size());
  std::vector<std::size_t> hidden;
  std::vector<PixelTubes> pixelTubes;
  // For field lines (radii in pixels, the side of a 2D domain they lie on): the meshes as read and the
  // camera that sees them (a flat scene's straight on, as the render turns it: flat_scene.hpp).
  Aabbd readBounds;
  CameraSettings seenBy = description.camera;
  if (std::any_of(description.meshes.begin(), description.meshes.end(),
                  [](const MeshInstance& mesh) { return mesh.volume.streamlines.has_value(); })) {
    readBounds = warpedWorldBounds(description, meshes);
    frameFlatScene(seenBy, readBounds);
  }
  for (std::size_t i = 0; i < original; ++i) {
    if (!volumes[i]) continue;
    std::shared_ptr<const VolumeMesh> volumeShared = volumes[i];
    const MeshInstance instance = description.meshes[i];  // a copy: the vector grows below
    const InstanceTransform transform(instance);
    // Field lines alone on a mesh without volume elements: across its faces when they are flat.
    std::shared_ptr<const PlanarDomain> planar;
    if (instance.volume.any() && volumeShared->empty()) {
      if (!instance.volume.slices.empty() || instance.volume.isosurfaces)
        throw InputError(volumeViewsWhere(instance.volume),
                         fmt::format("'{}' has no volume elements (tetrahedra, hexahedra, prisms, pyramids): "
                                     "slices and isosurfaces are drawn inside volumes",
                                     instance.file));
      planar = flatDomain(meshes[i], instance);
      volumeShared = std::shared_ptr<const VolumeMesh>(planar, &planar->volume);
    }
    const VolumeMesh& volume = *volumeShared;
    // What the cuts take of the mesh, copied before `meshes` grows below (it may move the mesh).
    Mesh parent;
    parent.physicalGroups = meshes[i].physicalGroups;
    parent.source.path = meshes[i].source.path;
    if (volume.empty()) continue;

    // Slices, and caps that show the colour field: one mesh of sections.
    Mesh sections = emptyCutMesh(volume, parent, "slices");
    for (const SliceSpec& slice : instance.volume.slices) {
      const Vec3d point =
          slice.point ? transform.toLocal(*slice.point) - volume.origin : volumeCentre(volume);
      const VolumeCut cut = sliceVolume(volume, point, transform.normalToLocal(slice.normal));
      if (cut.surface.faces.empty()) {
        const Vec3d shown = slice.point ? *slice.point : transform.apply(point + volume.origin);
        description.notes.push_back(formatInputWarning(
            slice.where,
            fmt::format("the slice through ({:.6g}, {:.6g}, {:.6g}) with normal ({:.3g}, {:.3g}, "
                        "{:.3g}) misses the volume of '{}'; it is not drawn",
                        shown.x, shown.y, shown.z, slice.normal.x, slice.normal.y, slice.normal.z,
                        instance.file)));
        continue;
      }
      appendCut(sections, cut, volume);
    }
    if (!planar && instance.colorBy && instance.colorBy->paintsSurface &&
        !volume.fieldSteps(instance.colorBy->field).empty()) {
      const double offset = kCapOffset * volumeDiagonal(volume);
      for (const std::vector<ClipSettings>* clips :
           std::array<const std::vector<ClipSettings>*, 2>{&description.clips, &instance.clips}) {
        for (const ClipSettings& clip : *clips) {
          if (!clip.cap) continue;
          const Vec3d normal = normalize(transform.normalToLocal(clip.normal));
          const Vec3d point = transform.toLocal(clip.point) - volume.origin - normal * offset;
          appendCut(sections, sliceVolume(volume, point, normal), volume);
        }
      }
    }
    if (!sections.faces.empty()) {
      // What the mesh shows of fields its volume does not carry (a view on its surfaces only) is
      // left off the sections, with a note, instead of failing the picture.
      MeshInstance child = cutInstance(instance);
      const auto notInVolume = [&](const std::string& field) { return volume.fieldSteps(field).empty(); };
      std::vector<const std::string*> fields{child.colorBy ? &child.colorBy->field : nullptr,
                                             child.isolines ? &child.isolines->field : nullptr};
      for (const AnnotationSpec& annotation : child.annotations)
        fields.push_back(&annotationField(annotation));
      for (const std::string* field : fields) {
        if (field && notInVolume(*field))
          description.notes.push_back(formatInputWarning(
              instance.where, fmt::format("'{}' is not given inside the volume of '{}': its slices and cut "
                                          "caps do not show it",
                                          *field, instance.file)));
      }
      if (child.colorBy && notInVolume(child.colorBy->field)) child.colorBy.reset();
      if (child.isolines && notInVolume(child.isolines->field)) child.isolines.reset();
      std::erase_if(child.annotations, [&](const AnnotationSpec& annotation) {
        return notInVolume(annotationField(annotation));
      });
      description.meshes.push_back(child);
      meshes.push_back(std::move(sections));
    }

    // Isosurfaces: one mesh of every value's surface. Their values stay over an animation.
    if (const std::optional<IsosurfaceSpec>& spec = instance.volume.isosurfaces) {
      const VolumeField& field = isosurfaceField(volume, *spec, description.when, instance.file);
      const auto [low, high] = scalarRange(field);
      if (!(low <= high))
        throw InputError(spec->where,
                         fmt::format("isosurfaces of '{}': the field has no finite value", spec->field));
      const auto source = std::make_shared<VolumeViewSource>(VolumeViewSource{
          volumes[i], instance, parent.physicalGroups, parent.source.path, false,
          spec->values.empty() ? evenIsoValues(low, high, spec->count) : spec->values, nullptr, 1});
      std::vector<double> outside;
      Mesh surfaces = isosurfaceMesh(*source, field, &outside);
      if (!outside.empty())
        description.notes.push_back(formatInputWarning(
            spec->where, fmt::format("isosurfaces of '{}': {} outside its range {:.6g} .. {:.6g}, not drawn",
                                     spec->field, fmt::join(outside, ", "), low, high)));
      if (!surfaces.faces.empty()) {
        MeshInstance child = colouredChild(instance, spec->color, spec->colorBy.value_or(spec->field),
                                           spec->where, description.materials, "isosurfaces");
        if (!spec->step && volume.fieldSteps(spec->field).size() > 1) child.volumeSource = source;
        description.meshes.push_back(child);
        meshes.push_back(std::move(surfaces));
      }
    }

    // Field lines: one mesh of tubes.
    if (const std::optional<StreamlineSpec>& spec = instance.volume.streamlines) {
      const VolumeField* field = viewStep(volume, spec->field, spec->step, description.when);
      if (!field)
        throw InputError(
            spec->where,
            fmt::format("streamlines of '{}': {} has no {} {} (its fields: {})", spec->field, instance.file,
                        volume.fieldSteps(spec->field).empty() ? "such field" : "such step of it",
                        planar ? "on its 2D domain" : "inside its volume", fieldList(volume)));
      if (field->components != 3)
        throw InputError(spec->where,
                         fmt::format("streamlines of '{}': it has {} component{}, and field lines "
                                     "follow a vector (3 components)",
                                     spec->field, field->components, field->components == 1 ? "" : "s"));
      const auto source = std::make_shared<VolumeViewSource>(VolumeViewSource{
          volumeShared, instance, parent.physicalGroups, parent.source.path, true, {}, planar, 1});
      if (planar) source->planeSide = sideSeen(seenBy, transform, *planar);
      if (spec->radiusPixels)
        source->parent.volume.streamlines->radius =
            *spec->radiusPixels *
            pixelSizeAtTarget(seenBy, readBounds, description.render.width, description.render.height);
      const auto locator = std::make_shared<const VolumeLocator>(volume);
      const std::vector<Vec3d> seeds = streamlineSeeds(*spec, volume, *locator, transform, planar.get());
      std::vector<FieldLine> lines = sourceFieldLines(*source, *field, *locator, seeds);
      const auto outside = static_cast<std::size_t>(std::count_if(
          lines.begin(), lines.end(), [](const FieldLine& line) { return line.points.empty(); }));
      if (outside == lines.size())
        throw InputError(spec->where,
                         fmt::format("streamlines of '{}': none of the {} seeds is inside the {} of "
                                     "'{}' (its box: {:.6g} to {:.6g} along x)",
                                     spec->field, seeds.size(), planar ? "2D domain" : "volume",
                                     instance.file, locator->bounds().lower.x + volume.origin.x,
                                     locator->bounds().upper.x + volume.origin.x));
      if (outside > 0 && spec->seeds != StreamlineSpec::Seeds::Automatic)
        description.notes.push_back(formatInputWarning(
            spec->where,
            fmt::format("streamlines of '{}': {} of the {} seeds are outside the {} and start no "
                        "line",
                        spec->field, outside, seeds.size(), planar ? "2D domain" : "volume")));
      Mesh tubes = sourceTubes(*source, *locator, lines);
      if (!tubes.faces.empty()) {
        // On a 2D domain painted in the colours they would take, tubes of those colours vanish into
        // it: they are white instead, lit, unless a colour or another field is asked for.
        const bool sameColours = planar && !spec->color && !spec->colorBy && instance.colorBy &&
                                 instance.colorBy->paintsSurface && instance.colorBy->field == spec->field;
        const std::optional<Vec3> color = sameColours ? std::optional<Vec3>(Vec3{1, 1, 1}) : spec->color;
        MeshInstance child = colouredChild(instance, color, spec->colorBy.value_or(spec->field), spec->where,
                                           description.materials, "streamlines");
        if (!spec->step && volume.fieldSteps(spec->field).size() > 1) child.volumeSource = source;
        child.liesOnPlane = planar != nullptr;
        if (spec->radiusPixels)
          pixelTubes.push_back({meshes.size(), source, locator, std::move(lines), *spec->radiusPixels});
        description.meshes.push_back(child);
        meshes.push_back(std::move(tubes));
      }
    }

    if (!instance.volume.any() && !annotationsSampleVolume(instance)) continue;
    // A 2D domain is the picture the lines lie on: shown as it is unless asked otherwise.
    const SkinStyle skin = instance.volume.skin.value_or(planar ? SkinStyle::Shown : SkinStyle::Ghost);
    switch (skin) {
      case SkinStyle::Shown:
        break;
      case SkinStyle::Ghost:
      case SkinStyle::Edges:
        description.meshes[i] = backdropInstance(instance, skin == SkinStyle::Ghost, description.materials);
        break;
      case SkinStyle::Hidden:
        hidden.push_back(i);
        break;
    }
  }
  for (auto it = hidden.rbegin(); it != hidden.rend(); ++it) {
    description.meshes.erase(description.meshes.begin() + static_cast<std::ptrdiff_t>(*it));
    meshes.erase(meshes.begin() + static_cast<std::ptrdiff_t>(*it));
  }
  for (PixelTubes& made : pixelTubes) made.mesh -= hidden.size();  // appended after every hidden mesh
  fitPixelTubes(description, meshes, pixelTubes, seenBy);
}

}  // namespace lancer
