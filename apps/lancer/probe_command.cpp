// `lancer probe FILE --at X,Y,Z [--field F] [--step K] [--json]`: a volume's fields at points,
// interpolated in the element that holds each (mesh/volume/volume_probe.hpp).
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <charconv>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "commands.hpp"
#include "lancer/mesh/mesh_file.hpp"
#include "lancer/mesh/volume/volume_locator.hpp"
#include "lancer/mesh/volume/volume_probe.hpp"
#include "lancer/util/input_error.hpp"

namespace lancer::cli {
namespace {

// "X,Y,Z" as a point; throws InputError naming --at otherwise.
Vec3d parsePoint(const std::string& text) {
  Vec3d point;
  const char* at = text.data();
  const char* end = text.data() + text.size();
  for (int axis = 0; axis < 3; ++axis) {
    while (at < end && *at == ' ') ++at;
    if (at < end && *at == '+') ++at;
    double value = 0;
    const auto [next, error] = std::from_chars(at, end, value);
    if (error != std::errc() || !std::isfinite(value))
      throw InputError(
          SourceLocation{"--at"},
          fmt::format("'{}' is not a point: give X,Y,Z, three finite numbers (e.g. --at 0,0.5,1)",
                      text.substr(0, 80)));
    point[axis] = value;
    at = next;
    while (at < end && *at == ' ') ++at;
    if (axis < 2) {
      if (at == end || *at != ',')
        throw InputError(
            SourceLocation{"--at"},
            fmt::format("'{}' is not a point: give X,Y,Z separated by commas (e.g. --at 0,0.5,1)",
                        text.substr(0, 80)));
      ++at;
    }
  }
  if (at != end)
    throw InputError(SourceLocation{"--at"},
                     fmt::format("'{}' is not a point: give X,Y,Z, three numbers", text.substr(0, 80)));
  return point;
}

std::string valuesText(const ProbeValue& value) {
  if (value.values.size() == 1) return fmt::format("{:.9g}", value.values[0]);
  double squares = 0;
  for (const float v : value.values) squares += double{v} * v;
  return fmt::format("({:.9g}), magnitude {:.9g}", fmt::join(value.values, ", "), std::sqrt(squares));
}

}  // namespace

void addProbeCommand(CLI::App& app, CommandRunner& runner) {
  struct Options {
    std::string file;
    std::vector<std::string> views;
    std::vector<std::string> points;
    std::string field;
    std::optional<int> step;
    bool json = false;
  };
  auto options = std::make_shared<Options>();
  CLI::App* command = app.add_subcommand(
      "probe", "The value of a volume's fields at points, interpolated in the element that holds each");
  command->add_option("FILE", options->file, "the .msh or .pos file with volume elements and fields")
      ->required();
  command->add_option(
      "VIEWS", options->views,
      "list-based .pos views to put on the file's volume (the views a solver computed on it)");
  command->add_option("--at", options->points, "a point X,Y,Z (repeat for several)")
      ->required()
      ->type_name("X,Y,Z");
  command->add_option("--field", options->field, "the field to give (default: every field)");
  command->add_option("--step", options->step, "the time step (default: every step)")
      ->check(CLI::Range(0, 1000000000));
  command->add_flag("--json", options->json, "machine-readable output");
  command->callback([&runner, options] {
    runner = [options] {
      std::vector<Vec3d> points;
      for (const std::string& text : options->points) points.push_back(parsePoint(text));
      MeshWithVolume read = readMeshFileWithVolume(options->file);
      addViewFiles(read, options->views);
      const VolumeMesh& volume = *read.volume;
      const VolumeLocator locator(volume);
      std::string json = "[";
      for (std::size_t p = 0; p < points.size(); ++p) {
        const Vec3d& point = points[p];
        const ProbeResult result =
            probeVolume(volume, locator, point, options->field, options->step, options->file);
        if (options->json) {
          for (const ProbeValue& value : result.values) {
            if (json.size() > 1) json += ",";
            json += fmt::format(
                "\n  {{\"point\": [{:.17g}, {:.17g}, {:.17g}], \"field\": \"{}\", \"at\": \"{}\", \"step\": "
                "{}, "
                "\"time\": {:.17g}, \"element\": \"{}\", \"values\": [{:.9g}]}}",
                point.x, point.y, point.z, value.name, fieldAtName(value.at), value.step, value.time,
                cellShapeName(result.shape), fmt::join(value.values, ", "));
          }
          continue;
        }
        for (const ProbeValue& value : result.values)
          std::printf("%s at (%.9g, %.9g, %.9g), step %d (t = %.9g): %s\n", value.name.c_str(), point.x,
                      point.y, point.z, value.step, value.time, valuesText(value).c_str());
      }
      if (options->json) std::printf("%s\n]\n", json.c_str());
      return kExitOk;
    };
  });
}

}  // namespace lancer::cli
