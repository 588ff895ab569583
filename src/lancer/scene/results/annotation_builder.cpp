#include "lancer/scene/results/annotation_builder.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <utility>

#include "lancer/image/color_map.hpp"
#include "lancer/scene/results/annotation_kinds.hpp"
#include "lancer/scene/results/color_by.hpp"
#include "lancer/scene/results/isolines.hpp"

namespace lancer {

std::vector<std::optional<ColorBy>> sharedColorRanges(const SceneDescription& description,
                                                      const std::vector<Mesh>& meshes) {
  std::vector<std::optional<ColorBy>> specs(meshes.size());
  // The range of each mesh's own field, when it has the field (else resolveColorBy reports it).
  std::vector<std::optional<std::pair<double, double>>> own(meshes.size());
  for (std::size_t i = 0; i < meshes.size(); ++i) {
    specs[i] = description.meshes[i].colorBy;
    if (!specs[i] || specs[i]->range) continue;
    for (const MeshField& field : meshes[i].fields)
      if (field.name == specs[i]->field && field.step == specs[i]->step) {
        const auto [low, high] = field.range();
        if (std::isfinite(low) && std::isfinite(high)) own[i] = std::pair<double, double>(low, high);
        break;
      }
  }
  for (std::size_t i = 0; i < meshes.size(); ++i) {
    if (!own[i]) continue;
    std::pair<double, double> range = *own[i];
    for (std::size_t j = 0; j < meshes.size(); ++j)
      if (own[j] && specs[j]->field == specs[i]->field && specs[j]->step == specs[i]->step &&
          specs[j]->map == specs[i]->map && specs[j]->scale == specs[i]->scale) {
        range.first = std::min(range.first, own[j]->first);
        range.second = std::max(range.second, own[j]->second);
      }
    // Only a range shared with other meshes is written down; a mesh alone keeps its own. A log scale
    // over values <= 0 is left to resolveColorBy, which names the mesh's own least value.
    const bool logOverNonPositive = specs[i]->scale == ColorScale::Log && !(range.first > 0);
    if (range != *own[i] && !logOverNonPositive) specs[i]->range = range;
  }
  return specs;
}

namespace {

// Values per face corner slot (MeshField's kCorner order) appended to `out` in the corner order of
// the scene's faces [faceBase, faceEnd), which the orientation of shells may have turned.
void appendInCornerOrder(std::vector<float>& out, const std::vector<float>& slots,
                         const std::vector<MeshFace>& sceneFaces, std::size_t faceBase, std::size_t faceEnd) {
  out.resize(faceBase * kCornerSlots, std::nanf(""));
  if (slots.size() != (faceEnd - faceBase) * kCornerSlots) {  // not this mesh's faces: none
    out.resize(faceEnd * kCornerSlots, std::nanf(""));
    return;
  }
  for (std::size_t f = faceBase; f < faceEnd; ++f) {
    const MeshFace& face = sceneFaces[f];
    const float* slot = slots.data() + (f - faceBase) * kCornerSlots;
    for (int c = 0; c < static_cast<int>(kCornerSlots); ++c)
      out.push_back(c < face.cornerCount() ? slot[cornerSlot(face, c)] : std::nanf(""));
  }
}

// Records a coloured mesh whose vertices run from vertexBase to vertexEnd and faces from faceBase to
// faceEnd: its faces get the map, its vertices (or faces, or face corners) the field's t (the
// mesh's vertices and faces are the scene's from the bases on, in order). Earlier meshes' entries
// are filled with "not coloured" first.
void appendFieldColoring(FieldColors& fields, const FieldColoring& coloring, const ColorBy& spec,
                         std::uint32_t vertexBase, std::size_t vertexEnd, std::size_t faceBase,
                         std::size_t faceEnd, const std::vector<MeshFace>& sceneFaces) {
  const int kind = coloring.at == FieldAt::kElement  ? FieldColors::kPerFace
                   : coloring.at == FieldAt::kCorner ? FieldColors::kPerCorner
                                                     : 0;
  FieldMap fieldMap{coloring.map, coloring.scale};
  if (coloring.scale == ColorScale::Log) {
    fieldMap.low = coloring.low;
    fieldMap.high = coloring.high;
    fieldMap.position = MapPosition(coloring.low, coloring.high, ColorScale::Log);
  }
  auto map = std::find(fields.maps.begin(), fields.maps.end(), fieldMap);
  if (map == fields.maps.end()) {
    if (fields.maps.size() == FieldColors::kMaxMaps)
      throw InputError(spec.where,
                       fmt::format("color_by map \"{}\": a scene colours its meshes with at most {} "
                                   "different colour maps (or log ranges); give some meshes the same "
                                   "map",
                                   coloring.map.name(), FieldColors::kMaxMaps));
    map = fields.maps.insert(fields.maps.end(), std::move(fieldMap));
  }
  const int mapIndex = static_cast<int>(map - fields.maps.begin());
  fields.faceColorMap.resize(faceBase, 0);
  fields.faceColorMap.resize(faceEnd, static_cast<std::uint8_t>((1 + mapIndex) | kind));
  if (coloring.at == FieldAt::kCorner) {
    appendInCornerOrder(fields.cornerFieldT, coloring.t, sceneFaces, faceBase, faceEnd);
    return;
  }
  const bool perFace = coloring.at == FieldAt::kElement;
  std::vector<float>& t = perFace ? fields.faceFieldT : fields.vertexFieldT;
  t.resize(perFace ? faceBase : vertexBase, std::nanf(""));
  t.insert(t.end(), coloring.t.begin(), coloring.t.end());
  t.resize(perFace ? faceEnd : vertexEnd, std::nanf(""));
}

// Meshes after the last coloured one are not coloured.
void finishFieldColors(Scene& scene, std::optional<FieldColors> fields) {
  if (!fields) return;
  const SceneGeometry& geometry = scene.geometry;
  fields->faceColorMap.resize(geometry.faces.size(), 0);
  if (!fields->vertexFieldT.empty()) fields->vertexFieldT.resize(geometry.positions.size(), std::nanf(""));
  if (!fields->faceFieldT.empty()) fields->faceFieldT.resize(geometry.faces.size(), std::nanf(""));
  if (!fields->cornerFieldT.empty())
    fields->cornerFieldT.resize(geometry.faces.size() * kCornerSlots, std::nanf(""));
  scene.fieldColors = std::move(fields);
}

}  // namespace

void appendLegendAndBands(FieldColors& fields, const ColorBy& spec, const FieldColoring& coloring,
                          std::size_t faceBase, std::size_t faceEnd) {
  if (!spec.ownLegend) return;
  const std::string title = spec.title.value_or(fieldTitle(spec.field, spec.component, coloring.components));
  auto same = [&](const LegendSpec& legend) {
    return legend.map == coloring.map && legend.low == coloring.low && legend.high == coloring.high &&
           legend.title == title && legend.units == spec.units && legend.bands == spec.bands &&
           legend.scale == coloring.scale;
  };
  if (std::none_of(fields.legends.begin(), fields.legends.end(), same))
    fields.legends.push_back(
        {coloring.map, coloring.low, coloring.high, title, spec.units, spec.bands, coloring.scale});
  if (spec.legend && fields.legendPlacement == LegendPlacement::None) fields.legendPlacement = *spec.legend;
  if (spec.bands > 0) {
    fields.faceBands.resize(faceBase, 0);
    fields.faceBands.resize(faceEnd, static_cast<std::uint16_t>(spec.bands));
  }
}

void finishBands(FieldColors& fields, std::size_t faceCount) {
  if (!fields.faceBands.empty()) fields.faceBands.resize(faceCount, 0);
}

std::vector<Vec3> isolineValueColors(const std::vector<float>& values, const ColorMap& map, double low,
                                     double high, ColorScale scale) {
  std::vector<Vec3> colors;
  colors.reserve(values.size());
  const MapPosition position(low, high, scale);  // as the surface colours are placed on the map
  for (const float v : values) colors.push_back(map(position(v)));
  return colors;
}

void appendIsolines(std::optional<IsolineOverlay>& overlay, const IsolineSpec& spec,
                    ResolvedIsolines resolved, std::uint32_t vertexBase, std::size_t faceBase,
                    std::size_t faceEnd, std::size_t vertexEnd, const std::vector<MeshFace>& sceneFaces,
                    std::vector<Vec3> valueColors) {
  if (!overlay) overlay.emplace();
  overlay->styles.push_back(
      {std::move(resolved.values), spec.color, std::move(valueColors), spec.widthPixels});
  overlay->faceStyle.resize(faceBase, 0);
  overlay->faceStyle.resize(faceEnd, static_cast<std::uint16_t>(overlay->styles.size() - 1));
  if (resolved.at == FieldAt::kCorner) {
    appendInCornerOrder(overlay->cornerValue, resolved.vertexValue, sceneFaces, faceBase, faceEnd);
    return;
  }
  // The mesh's vertices are the scene's from vertexBase on, in order.
  overlay->vertexValue.resize(vertexBase, std::nanf(""));
  overlay->vertexValue.insert(overlay->vertexValue.end(), resolved.vertexValue.begin(),
                              resolved.vertexValue.end());
  overlay->vertexValue.resize(vertexEnd, std::nanf(""));
}

void finishIsolines(Scene& scene, std::optional<IsolineOverlay> overlay) {
  if (!overlay) return;
  overlay->faceStyle.resize(scene.geometry.faces.size(), 0);
  overlay->vertexValue.resize(scene.geometry.positions.size(), std::nanf(""));
  if (!overlay->cornerValue.empty())
    overlay->cornerValue.resize(scene.geometry.faces.size() * kCornerSlots, std::nanf(""));
  scene.isolines = std::move(overlay);
}

void annotateScene(Scene& scene, const StepSelection& when, const std::vector<EntryAnnotation>& entries) {
  // The arrays the scene had are emptied and filled again: an animation annotates every frame, and
  // fresh arrays of a million faces would each fault their pages in again.
  auto emptied = [](auto& array) {  // its memory, without its values
    auto kept = std::move(array);
    kept.clear();
    return kept;
  };
  FieldColors spareFields;  // the old arrays, emptied, for the first coloured mesh
  IsolineOverlay spareIsolines;
  if (FieldColors* old = scene.fieldColors ? &*scene.fieldColors : nullptr) {
    spareFields.faceColorMap = emptied(old->faceColorMap);
    spareFields.vertexFieldT = emptied(old->vertexFieldT);
    spareFields.faceFieldT = emptied(old->faceFieldT);
    spareFields.cornerFieldT = emptied(old->cornerFieldT);
    spareFields.faceBands = emptied(old->faceBands);
  }
  if (IsolineOverlay* old = scene.isolines ? &*scene.isolines : nullptr) {
    spareIsolines.faceStyle = emptied(old->faceStyle);
    spareIsolines.vertexValue = emptied(old->vertexValue);
    spareIsolines.cornerValue = emptied(old->cornerValue);
  }
  scene.fieldColors.reset();
  scene.isolines.reset();
  std::optional<FieldColors> fields;
  std::optional<IsolineOverlay> isolines;
  auto startFields = [&] {
    if (!fields) fields.emplace(std::exchange(spareFields, FieldColors{}));
  };
  for (const EntryAnnotation& entry : entries) {
    if (entry.coloring) {
      startFields();
      if (entry.colorBy->paintsSurface)
        appendFieldColoring(*fields, *entry.coloring, *entry.colorBy, entry.vertexBase, entry.vertexEnd,
                            entry.faceBase, entry.faceEnd, scene.geometry.faces);
      appendLegendAndBands(*fields, *entry.colorBy, *entry.coloring, entry.faceBase, entry.faceEnd);
    }
    if (!entry.instance->isolines) continue;
    const IsolineSpec& spec = *entry.instance->isolines;
    std::optional<std::pair<double, double>> colorRange;  // gmsh's iso-values span the colours' range
    ColorScale scale = ColorScale::Linear;                // and a log scale's lines are spaced as it is
    if (entry.coloring && entry.colorBy->field == spec.field && entry.colorBy->component == spec.component) {
      colorRange = std::pair{entry.coloring->low, entry.coloring->high};
      scale = entry.coloring->scale;
    }
    ResolvedIsolines resolved = resolveIsolines(spec, *entry.fields, when, colorRange, scale);
    if (resolved.fromElementData) {
      const std::string note = formatInputWarning(
          spec.where, fmt::format("isolines of element data \"{}\" follow its mean at each vertex (of the "
                                  "elements around it), not the values of the elements themselves",
                                  spec.field));
      if (std::find(scene.warnings.begin(), scene.warnings.end(), note) == scene.warnings.end())
        scene.warnings.push_back(note);
    }
    if (!isolines) isolines.emplace(std::exchange(spareIsolines, IsolineOverlay{}));
    std::vector<Vec3> valueColors;  // color = "map": over the colours' range, else over the lines'
    if (spec.colorFromMap && !resolved.values.empty()) {
      const auto [low, high] =
          colorRange.value_or(std::pair<double, double>{resolved.values.front(), resolved.values.back()});
      valueColors = isolineValueColors(resolved.values, entry.colorBy ? entry.colorBy->map : ColorMap{}, low,
                                       high, scale);
    }
    appendIsolines(isolines, spec, std::move(resolved), entry.vertexBase, entry.faceBase, entry.faceEnd,
                   entry.vertexEnd, scene.geometry.faces, std::move(valueColors));
  }
  if (fields) finishBands(*fields, scene.geometry.faces.size());
  finishFieldColors(scene, std::move(fields));
  finishIsolines(scene, std::move(isolines));
}

bool hasAnnotationMeshes(const SceneDescription& description) {
  return std::any_of(description.meshes.begin(), description.meshes.end(),
                     [](const MeshInstance& instance) { return !instance.annotations.empty(); });
}

std::vector<Mesh> addAnnotationMeshes(SceneDescription& description, const std::vector<Mesh>& meshes) {
  std::vector<Mesh> added;
  // The volumes an annotation kind has sampled already: a slice or cap cut from a mesh carries the
  // mesh's annotations, and the arrows through its volume are drawn once.
  std::vector<std::pair<std::size_t, const VolumeMesh*>> sampled;
  const std::size_t originals = description.meshes.size();
  for (std::size_t i = 0; i < originals; ++i) {
    const std::vector<AnnotationSpec> specs = std::exchange(description.meshes[i].annotations, {});
    for (const AnnotationSpec& spec : specs) {
      const AnnotationKind& kind = annotationKind(spec);
      const MeshInstance& owner = description.meshes[i];
      const VolumeMesh* volume = owner.annotationVolume.get();
      if (kind.samplesVolume(spec) && volume) {
        const std::pair<std::size_t, const VolumeMesh*> key{spec.index(), volume};
        if (std::find(sampled.begin(), sampled.end(), key) != sampled.end()) continue;
        sampled.push_back(key);
      }
      MeshInstance instance = owner;
      instance.file += fmt::format(" ({})", kind.key);
      instance.groupMaterials.clear();
      instance.edges.reset();
      instance.isolines.reset();
      instance.warp.reset();  // what is drawn on the surface stands on its warped shape already
      instance.undeformed = UndeformedStyle::None;
      instance.shading = ShadingMode::Phong;
      instance.annotationVolume.reset();
      const AnnotationSite site{owner, meshes[i], volume, description.when, description.materials};
      Mesh mesh = kind.build(spec, site, instance);
      description.meshes.push_back(std::move(instance));  // `owner` is not used past here
      added.push_back(std::move(mesh));
    }
  }
  return added;
}

void attachAnnotationVolumes(SceneDescription& description,
                             const std::vector<std::shared_ptr<const VolumeMesh>>& volumes) {
  for (std::size_t i = 0; i < std::min(description.meshes.size(), volumes.size()); ++i)
    if (volumes[i] && annotationsSampleVolume(description.meshes[i]))
      description.meshes[i].annotationVolume = volumes[i];
}

}  // namespace lancer
