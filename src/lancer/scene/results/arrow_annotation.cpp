// The annotation kind "arrows" (annotation_kinds.hpp): the arrows' mesh, on the surface or through
// the volume, and how their instance is coloured.
#include <algorithm>
#include <cmath>
#include <utility>

#include <fmt/format.h>

#include "lancer/mesh/field_steps.hpp"
#include "lancer/scene/results/arrows.hpp"
#include "lancer/scene/results/color_by.hpp"
#include "lancer/scene/results/volume_arrows.hpp"
#include "lancer/util/input_error.hpp"

namespace lancer {

namespace {

// The error of a log scale over arrows whose magnitudes reach 0 (or never leave it), in the words of
// the option or key that asked for it, with a range that would do.
InputError logScaleNeedsARange(const ArrowSpec& spec, const ColorBy& asked, const std::string& file,
                               std::pair<double, double> range) {
  const double high = range.second > 0 ? range.second : 0.0;
  const bool option = !asked.logOption.empty();
  const auto [where, log, advice, linear] = logScaleWords(asked, high);
  if (!(high > 0))
    return InputError(where,
                      fmt::format("arrows of \"{}\" in {} have no magnitude above 0, so {} cannot show "
                                  "them: {}",
                                  spec.field, file, log, option ? linear : "use " + linear));
  return InputError(where, fmt::format("arrows of \"{}\" in {} have magnitudes down to {:g}, but {} needs "
                                       "values > 0: give a range whose low end is > 0, e.g. {} (values below "
                                       "it are drawn at it), or {}",
                                       spec.field, file, std::max(range.first, 0.0), log, advice, linear));
}

}  // namespace

bool arrowsSampleVolume(const AnnotationSpec& spec) { return std::get<ArrowSpec>(spec).grid.has_value(); }

Mesh buildArrowAnnotation(const AnnotationSpec& annotation, const AnnotationSite& site,
                          MeshInstance& instance) {
  const ArrowSpec& spec = std::get<ArrowSpec>(annotation);
  const MeshInstance& owner = site.owner;
  std::pair<double, double> range{INFINITY, -INFINITY};  // the magnitudes over every step
  Mesh arrows;
  if (spec.grid) {
    // A volume that could not be read (none was asked for this mesh) reads as one without elements.
    const VolumeMesh empty;
    const VolumeMesh& volume = site.volume ? *site.volume : empty;
    arrows = volumeArrowMesh(spec, volume, site.when, owner.file);
    range = volumeMagnitudeRange(volume, spec.field, spec.step);
  } else {
    arrows = arrowMesh(spec, site.mesh, site.when, owner.warp ? &*owner.warp : nullptr);
    for (const MeshField* step : viewSteps(site.mesh, spec.field)) {
      const auto [low, high] = componentRange(*step, FieldComponent{});
      range = {std::min(range.first, low), std::max(range.second, high)};
    }
  }
  if (spec.color) {
    Material material = site.materials[static_cast<std::size_t>(instance.material)];
    material.name += " (arrows)";
    material.ka = material.kd = *spec.color;
    material.transparency = 0;
    instance.material = static_cast<int>(site.materials.size());
    site.materials.push_back(material);
    instance.colorBy.reset();
    return arrows;
  }
  // Solid whatever they stand on: grid arrows inside a skin drawn as a ghost or in outline took its
  // see-through material, washed out to grey (or clear).
  if (const Material& own = site.materials[static_cast<std::size_t>(instance.material)];
      own.transparency > 0) {
    Material material = own;
    material.name += " (arrows)";
    material.transparency = 0;
    instance.material = static_cast<int>(site.materials.size());
    site.materials.push_back(material);
  }
  ColorBy colorBy;
  colorBy.field = arrows.fields.front().name;
  colorBy.step = 0;
  // One colour range over every step, as the mesh's own colours.
  if (!spec.step && range.first <= range.second) colorBy.range = range;
  colorBy.map = owner.colorBy ? owner.colorBy->map : ColorMap{};  // linear: magnitudes reach 0
  colorBy.legend = owner.colorBy ? owner.colorBy->legend : std::nullopt;
  colorBy.where = spec.where;
  colorBy.title = "|" + spec.field + "|";
  // Arrows of the field the mesh is coloured by (its magnitude) share its colours, so its one
  // legend: the same title, units, bands and range (and scale, with the range).
  const ColorBy* surface = owner.colorBy ? &*owner.colorBy : nullptr;
  if (surface && surface->field == spec.field && surface->component == FieldComponent{}) {
    if (surface->title) colorBy.title = surface->title;
    colorBy.units = surface->units;
    colorBy.bands = surface->bands;
    if (surface->range) {  // a log scale needs the range's low end above 0, which the mesh's has
      colorBy.range = surface->range;
      colorBy.scale = surface->scale;
    } else if (surface->scale == ColorScale::Log) {
      // Over the arrows' own magnitudes, which reach 0 wherever the field vanishes: refused as the
      // mesh's colours refuse it, never a linear legend instead of the log one asked for.
      if (!(range.first > 0)) throw logScaleNeedsARange(spec, *surface, owner.file, range);
      colorBy.scale = ColorScale::Log;
    }
  }
  instance.colorBy = colorBy;
  return arrows;
}

}  // namespace lancer
