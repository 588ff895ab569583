#include "volume_options.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "lancer/scene/results/volume_view_text.hpp"
#include "lancer/util/input_error.hpp"

namespace lancer::cli {
namespace {

// "V1,V2,...": at least `least` and at most `most` finite numbers that fit a float, or nothing.
std::optional<std::vector<double>> numbersFromText(const std::string& text, std::size_t least,
                                                   std::size_t most) {
  std::vector<double> numbers;
  for (std::size_t start = 0; start <= text.size();) {
    const std::size_t comma = std::min(text.find(',', start), text.size());
    const std::string item = text.substr(start, comma - start);
    char* end = nullptr;
    const double value = std::strtod(item.c_str(), &end);
    if (item.empty() || end != item.c_str() + item.size() || !std::isfinite(value) ||
        std::abs(value) > std::numeric_limits<float>::max() || numbers.size() == most)
      return std::nullopt;
    numbers.push_back(value);
    start = comma + 1;
  }
  if (numbers.size() < least) return std::nullopt;
  return numbers;
}

// --streamline-radius R (model units) or Npx (pixels).
void applyStreamlineRadius(const std::string& text, StreamlineSpec& spec) {
  const SourceLocation where{"--streamline-radius"};
  if (const std::optional<double> pixels = pixelsFromText(text)) {
    if (!(*pixels > 0) || *pixels > kMaxRadiusPixels)
      throw InputError(where, fmt::format("'{}': a radius in pixels must be greater than 0 and at most {:g}",
                                          text, kMaxRadiusPixels));
    spec.radiusPixels = *pixels;
    return;
  }
  const std::optional<std::vector<double>> radius = numbersFromText(text, 1, 1);
  if (!radius || !(radius->front() > 0))
    throw InputError(where, fmt::format("'{}' is not a radius: give a length in model units greater than 0 "
                                        "(0.01) or in pixels (2px)",
                                        text));
  spec.radius = radius->front();
}

// --seed-rectangle X,Y,Z,UX,UY,UZ,VX,VY,VZ: a corner and its two edges.
void applySeedRectangle(const std::string& text, StreamlineSpec& spec) {
  const SourceLocation where{"--seed-rectangle"};
  const std::optional<std::vector<double>> n = numbersFromText(text, 9, 9);
  if (!n)
    throw InputError(where, fmt::format("'{}' is not a rectangle: give a corner and its two edges, "
                                        "X,Y,Z,UX,UY,UZ,VX,VY,VZ",
                                        text));
  const Vec3d corner{(*n)[0], (*n)[1], (*n)[2]}, u{(*n)[3], (*n)[4], (*n)[5]}, v{(*n)[6], (*n)[7], (*n)[8]};
  if (!(length(u) > 0) || !(length(v) > 0))
    throw InputError(where, fmt::format("'{}': the edge {} is 0,0,0; give both edges a length", text,
                                        length(u) > 0 ? "VX,VY,VZ" : "UX,UY,UZ"));
  if (!(length(cross(normalize(u), normalize(v))) > 1e-6))
    throw InputError(where,
                     fmt::format("'{}': the two edges are parallel, so the rectangle has no area", text));
  spec.seeds = StreamlineSpec::Seeds::Rectangle;
  spec.rectangleCorner = corner;
  spec.rectangleEdgeU = u;
  spec.rectangleEdgeV = v;
}

// --streamlines FIELD[:COUNT], --seed-line X1,Y1,Z1,X2,Y2,Z2, --seed-rectangle and
// --streamline-radius.
void applyStreamlineOptions(const SceneOverrides& overrides, RenderOverrides& applied) {
  if (overrides.streamlines.empty()) {
    for (const auto& [given, option] : {std::pair{&overrides.seedLine, "--seed-line"},
                                        std::pair{&overrides.seedRectangle, "--seed-rectangle"},
                                        std::pair{&overrides.streamlineRadius, "--streamline-radius"}})
      if (!given->empty())
        throw InputError(
            SourceLocation{option},
            fmt::format("{} is about the field lines of --streamlines FIELD: add --streamlines", option));
    return;
  }
  if (!overrides.seedLine.empty() && !overrides.seedRectangle.empty())
    throw InputError(SourceLocation{"--seed-rectangle"},
                     "--seed-line and --seed-rectangle both give the seeds of --streamlines: keep one");
  StreamlineSpec spec;
  const auto [field, count] = fieldAndCountFromText(overrides.streamlines, "--streamlines", kMaxStreamlines);
  spec.field = field;
  if (count) spec.count = *count;
  if (!overrides.seedLine.empty()) {
    const std::optional<std::vector<double>> ends = numbersFromText(overrides.seedLine, 6, 6);
    if (!ends)
      throw InputError(
          SourceLocation{"--seed-line"},
          fmt::format("'{}' is not a line: give its two ends X1,Y1,Z1,X2,Y2,Z2", overrides.seedLine));
    const std::vector<double>& n = *ends;
    spec.seeds = StreamlineSpec::Seeds::Line;
    spec.points = {{n[0], n[1], n[2]}, {n[3], n[4], n[5]}};
  }
  if (!overrides.seedRectangle.empty()) applySeedRectangle(overrides.seedRectangle, spec);
  if (!overrides.streamlineRadius.empty()) applyStreamlineRadius(overrides.streamlineRadius, spec);
  applied.streamlines = spec;
}

}  // namespace

void addVolumeOptions(CLI::App& command, SceneOverrides& overrides) {
  command
      .add_option("--slice", overrides.slices,
                  "The section of the volume by a plane, coloured as the mesh (any number): AXIS through the "
                  "centre (x, y, z), AXIS=VALUE (z=0.3) or PX,PY,PZ,NX,NY,NZ; see docs/volume.md")
      ->group(kVolumeGroup);
  command
      .add_option(
          "--skin", overrides.skin,
          "The mesh's own surface beside slices and isosurfaces: ghost (default), edges, hidden or shown")
      ->group(kVolumeGroup);
  command
      .add_option("--isosurfaces", overrides.isosurfaces,
                  "Surfaces where a scalar field of the volume is constant: FIELD[:COUNT] (default 5, evenly "
                  "spaced in its range)")
      ->group(kVolumeGroup);
  command.add_option("--isovalues", overrides.isovalues, "The values of --isosurfaces: V1,V2,...")
      ->group(kVolumeGroup);
  command
      .add_option(
          "--streamlines", overrides.streamlines,
          "Field lines of a vector field of the volume, as tubes: FIELD[:COUNT] (default 50 lines from "
          "seeds spread evenly through the volume)")
      ->group(kVolumeGroup);
  command
      .add_option("--seed-line", overrides.seedLine,
                  "The --streamlines seeds: COUNT points evenly along the segment X1,Y1,Z1,X2,Y2,Z2")
      ->group(kVolumeGroup);
  command
      .add_option("--seed-rectangle", overrides.seedRectangle,
                  "The --streamlines seeds: COUNT points in a grid on the rectangle with corner X,Y,Z and "
                  "edges UX,UY,UZ and VX,VY,VZ (X,Y,Z,UX,UY,UZ,VX,VY,VZ)")
      ->group(kVolumeGroup);
  command
      .add_option("--streamline-radius", overrides.streamlineRadius,
                  "The --streamlines tubes' radius: in model units (0.01) or in pixels of the picture (2px)")
      ->group(kVolumeGroup);
}

void applyVolumeOptions(const SceneOverrides& overrides, RenderOverrides& applied) {
  for (const std::string& slice : overrides.slices)
    applied.slices.push_back(sliceFromText(slice, SourceLocation{"--slice"}));
  if (!overrides.skin.empty()) {
    const auto found = std::find(kSkinStyles.begin(), kSkinStyles.end(), overrides.skin);
    if (found == kSkinStyles.end())
      throw InputError(
          SourceLocation{"--skin"},
          fmt::format("'{}' is not a skin style: use shown, ghost, edges or hidden", overrides.skin));
    applied.skin = static_cast<SkinStyle>(found - kSkinStyles.begin());
  }
  applyStreamlineOptions(overrides, applied);
  if (overrides.isosurfaces.empty()) {
    if (!overrides.isovalues.empty())
      throw InputError(SourceLocation{"--isovalues"},
                       "--isovalues gives the values of --isosurfaces FIELD: add --isosurfaces");
    return;
  }
  IsosurfaceSpec spec;
  const auto [field, count] = fieldAndCountFromText(overrides.isosurfaces, "--isosurfaces", kMaxIsosurfaces);
  spec.field = field;
  if (count) spec.count = *count;
  if (!overrides.isovalues.empty()) {
    const std::optional<std::vector<double>> values =
        numbersFromText(overrides.isovalues, 1, static_cast<std::size_t>(kMaxIsosurfaces));
    if (!values)
      throw InputError(SourceLocation{"--isovalues"},
                       fmt::format("'{}' is not a list of up to {} finite numbers V1,V2,...",
                                   overrides.isovalues, kMaxIsosurfaces));
    spec.values = *values;
  }
  applied.isosurfaces = spec;
}

}  // namespace lancer::cli
