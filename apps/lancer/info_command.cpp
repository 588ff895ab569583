// `lancer info FILE.msh [--json]`: what the reader made of a mesh file: format, counts as read and
// as rendered, physical groups, fields, bounding box, area, shells and their orientation, load time.
#include <fmt/format.h>

#include <cstdio>
#include <string>
#include <vector>

#include "commands.hpp"
#include "info_accel.hpp"
#include "lancer/mesh/mesh_file.hpp"
#include "lancer/mesh/mesh_stats.hpp"
#include "lancer/mesh/msh/element_types.hpp"
#include "lancer/mesh/nothing_to_draw.hpp"
#include "scene_setup.hpp"

namespace lancer::cli {
namespace {

constexpr std::size_t kShellsListed = 10;

std::string jsonString(const std::string& text) {
  std::string out = "\"";
  for (const char c : text) {
    const auto u = static_cast<unsigned char>(c);
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (u < 0x20) {
      out += fmt::format("\\u{:04x}", u);
    } else {
      out += c;
    }
  }
  return out + "\"";
}

std::uint64_t countOf(const std::map<std::int32_t, std::uint64_t>& counts, std::int32_t tag) {
  const auto found = counts.find(tag);
  return found == counts.end() ? 0 : found->second;
}

// A volume of MeshStats::interfaces as `info` names it: "Name" (tag), or its tag alone, or its
// elementary entity when it is in no physical group.
std::string volumeLabel(const Mesh& mesh, std::int64_t volume) {
  if (volume < 0) return fmt::format("volume entity {} (no physical group)", -volume);
  const std::string name = mesh.physicalName(static_cast<std::int32_t>(volume));
  return name.empty() ? fmt::format("{}", volume) : fmt::format("\"{}\" ({})", name, volume);
}

std::string shellDescription(const MeshShell& shell) {
  std::string text = fmt::format("{} faces, area {:.6g}, ", shell.faceCount, shell.area);
  if (!shell.closed)
    return text +
           (shell.consistentlyOriented ? "open, consistently oriented" : "open, not consistently oriented");
  if (!shell.consistentlyOriented) return text + "closed, NOT consistently oriented";
  // The file's own winding; lancer turns every solid's faces out of its material when it renders.
  const char* winding = shell.signedVolume >= 0 ? "normals point outward" : "normals point inward";
  if (shell.cavity)
    winding = shell.signedVolume < 0 ? "cavity wall, normals point into the cavity"
                                     : "cavity wall, normals point into the material";
  if (shell.interface) winding = "interface between volumes";
  return text + fmt::format("closed, consistently oriented ({}, volume {:.6g})", winding,
                            std::abs(shell.signedVolume));
}

// Why a section `lancer info` lists as skipped changes nothing in the picture.
std::string_view skippedSectionReason(std::string_view name) {
  if (name == "$Periodic") return "periodic node links; each side is drawn as it is meshed";
  if (name == "$InterpolationScheme")
    return "interpolation matrices; fields are drawn from their values at the element corners";
  if (name == "$Comments") return "comments";
  if (name == "$GhostElements") return "ghost elements of partitions; each element is drawn once";
  if (name == "$Parametrizations") return "surface parametrizations; the mesh is drawn as meshed";
  return "a section lancer does not know; nothing of it is drawn";
}

void printText(const Mesh& mesh, const MeshStats& stats) {
  const MeshSourceInfo& source = mesh.source;
  fmt::print("file:            {} ({} bytes)\n", source.path, source.fileBytes);
  if (source.format == "pos")
    fmt::print("format:          list-based views (.pos, gmsh's parsed post-processing format)\n");
  else if (source.format == "stl")
    fmt::print("format:          STL {}\n", source.binary ? "binary" : "ASCII");
  else if (source.format == "obj")
    fmt::print("format:          Wavefront OBJ\n");
  else if (source.format == "ply")
    fmt::print("format:          PLY {}\n", source.formatVersion);
  else
    fmt::print("format:          MSH {} {}{}\n", source.formatVersion, source.binary ? "binary" : "ASCII",
               source.partitionCount ? fmt::format(", {} partitions", source.partitionCount) : "");
  fmt::print("nodes:           {}\n", source.nodeCount);
  fmt::print("elements read:\n");
  for (const auto& [type, count] : source.elementsByType) {
    const std::string how = mshElementRenderNote(type);
    fmt::print("  {:>10}  {} (type {}){}\n", count, mshElementTypeName(type), type,
               how.empty() ? "" : ": " + how);
  }
  fmt::print("faces rendered:  {} ({} triangles, {} quads)\n", mesh.faceCount(), stats.triangles,
             stats.quads);
  if (const std::string reason = nothingToDrawReason(mesh); !reason.empty())
    fmt::print("nothing to draw: {}\n", reason);
  if (source.volumeElements)
    fmt::print("volume skin:     {} faces from {} volume elements ({} already surface elements)\n",
               source.skinFaces, source.volumeElements, source.skinFacesCoveredBySurfaces);
  if (source.interfaceFaces)
    fmt::print("interfaces:      {} faces shared by two volumes ({} surface elements on them merged)\n",
               source.interfaceFaces, source.interfaceSurfaceElementsMerged);
  if (!source.unrenderableByType.empty()) {
    fmt::print("not rendered:\n");
    for (const auto& [type, count] : source.unrenderableByType)
      fmt::print("  {:>10}  {} (type {}): lancer does not draw this type\n", count, mshElementTypeName(type),
                 type);
  }
  if (source.duplicateElementsSkipped)
    fmt::print(
        "copies skipped:  {} (MSH 2 repeats an element for each further physical group; the first "
        "copy is kept, in all the groups)\n",
        source.duplicateElementsSkipped);
  for (const std::string& warning : source.warnings) fmt::print("{}\n", warning);
  if (!source.skippedSections.empty()) {
    fmt::print("sections skipped:\n");
    for (const auto& [name, count] : source.skippedSections)
      fmt::print("  {:>10}  {}: {}\n", count, name, skippedSectionReason(name));
  }
  fmt::print("physical groups:\n");
  for (const PhysicalGroup& group : mesh.physicalGroups) {
    const auto faces = stats.facesByPhysicalTag.find(group.tag);
    const std::uint64_t count =
        group.dimension >= 2 && faces != stats.facesByPhysicalTag.end() ? faces->second : 0;
    const std::uint64_t shared =
        group.dimension == 3 ? countOf(stats.interfaceFacesByPhysicalTag, group.tag) : 0;
    fmt::print("  dim {} tag {:<6} {:<24} {} faces{}\n", group.dimension, group.tag,
               group.name.empty() ? "(unnamed)" : fmt::format("\"{}\"", group.name), count,
               shared ? fmt::format(" ({} skin, {} interface)", count - shared, shared) : "");
  }
  for (const auto& [pair, count] : stats.interfaces)
    fmt::print("  interface {} | {}: {} faces\n", volumeLabel(mesh, pair.first),
               volumeLabel(mesh, pair.second), count);
  if (const auto none = stats.facesByPhysicalTag.find(0); none != stats.facesByPhysicalTag.end())
    fmt::print("  (no physical group)                    {} faces\n", none->second);
  if (!mesh.fields.empty()) {
    fmt::print("fields:\n");
    for (const MeshField& field : mesh.fields) {
      const auto [low, high] = field.range();
      fmt::print("  {:<24} {} data, {} component{}, step {} (time {:g}), {} {:.6g} .. {:.6g}\n",
                 fmt::format("\"{}\"", field.name), fieldAtName(field.at), field.components,
                 field.components == 1 ? "" : "s", field.step, field.time,
                 field.components == 1 ? "values" : "magnitudes", low, high);
    }
    // A large result's steps stay in the file (docs/results.md): said, with what they would take.
    std::uint64_t bytes = 0;
    for (const MeshField& field : mesh.fields)
      bytes += field.itemCount() * static_cast<std::uint64_t>(field.components) * sizeof(float);
    if (mesh.fields.front().isStored())
      fmt::print(
          "  the steps ({} as floats) stay in the file and are read when a picture needs them "
          "(LANCER_STEP_MEMORY_MB: {} MB)\n",
          bytes < (1 << 20) ? fmt::format("{:.0f} KB", static_cast<double>(bytes) / 1024)
                            : fmt::format("{:.1f} MB", static_cast<double>(bytes) / (1 << 20)),
          defaultResidentFieldBytes() >> 20);
  }
  if (mesh.faceCount()) {
    const Aabbd& box = stats.worldBounds;
    fmt::print("bounding box:    [{:.9g}, {:.9g}, {:.9g}] .. [{:.9g}, {:.9g}, {:.9g}]\n", box.lower.x,
               box.lower.y, box.lower.z, box.upper.x, box.upper.y, box.upper.z);
  }
  fmt::print("surface area:    {:.9g}\n", stats.area);
  std::size_t closed = 0, oriented = 0;
  for (const MeshShell& shell : stats.shells) {
    closed += shell.closed;
    oriented += shell.closed && shell.consistentlyOriented;
  }
  fmt::print("shells:          {} ({} closed, {} closed and consistently oriented)\n", stats.shells.size(),
             closed, oriented);
  for (std::size_t s = 0; s < stats.shells.size() && s < kShellsListed; ++s)
    fmt::print("  shell {}: {}\n", s + 1, shellDescription(stats.shells[s]));
  if (stats.shells.size() > kShellsListed)
    fmt::print("  ... and {} more\n", stats.shells.size() - kShellsListed);
  fmt::print("load time:       {:.3f} ms\n", source.loadSeconds * 1e3);
}

template <typename Map>
std::string jsonCounts(const Map& counts) {
  std::string out = "{";
  for (const auto& [type, count] : counts)
    out += fmt::format("{}\"{}\": {}", out.size() > 1 ? ", " : "", type, count);
  return out + "}";
}

void printJson(const Mesh& mesh, const MeshStats& stats, const std::string& accelMember) {
  const MeshSourceInfo& source = mesh.source;
  std::string out = "{\n";
  out += fmt::format("  \"file\": {},\n  \"bytes\": {},\n", jsonString(source.path), source.fileBytes);
  out +=
      fmt::format("  \"format\": \"{}\",\n  \"version\": \"{}\",\n  \"binary\": {},\n  \"partitions\": {},\n",
                  source.format, source.formatVersion, source.binary, source.partitionCount);
  out += fmt::format("  \"nodes\": {},\n", source.nodeCount);
  out += fmt::format("  \"elementsByType\": {},\n", jsonCounts(source.elementsByType));
  out += fmt::format("  \"unrenderableByType\": {},\n", jsonCounts(source.unrenderableByType));
  out += fmt::format("  \"faces\": {{\"total\": {}, \"triangles\": {}, \"quads\": {}}},\n", mesh.faceCount(),
                     stats.triangles, stats.quads);
  out += fmt::format("  \"volumeElements\": {},\n  \"skinFaces\": {},\n  \"degenerateFacesDropped\": {},\n",
                     source.volumeElements, source.skinFaces, source.degenerateFacesDropped);
  out += fmt::format("  \"duplicateElementsSkipped\": {},\n", source.duplicateElementsSkipped);
  const std::string reason = nothingToDrawReason(mesh);
  out += fmt::format("  \"nothingToDraw\": {},\n", reason.empty() ? "null" : jsonString(reason));
  out += "  \"warnings\": [";
  for (std::size_t i = 0; i < source.warnings.size(); ++i)
    out += fmt::format("{}{}", i ? ", " : "", jsonString(source.warnings[i]));
  out += "],\n";
  out += "  \"skippedSections\": {";
  for (const auto& [name, count] : source.skippedSections)
    out += fmt::format("{}{}: {}", out.back() == '{' ? "" : ", ", jsonString(name), count);
  out += "},\n";
  out += "  \"physicalGroups\": [";
  for (std::size_t i = 0; i < mesh.physicalGroups.size(); ++i) {
    const PhysicalGroup& group = mesh.physicalGroups[i];
    const auto faces = stats.facesByPhysicalTag.find(group.tag);
    const std::uint64_t count =
        group.dimension >= 2 && faces != stats.facesByPhysicalTag.end() ? faces->second : 0;
    const std::uint64_t shared =
        group.dimension == 3 ? countOf(stats.interfaceFacesByPhysicalTag, group.tag) : 0;
    out += fmt::format(
        "{}\n    {{\"dimension\": {}, \"tag\": {}, \"name\": {}, \"faces\": {}, \"interfaceFaces\": {}}}",
        i ? "," : "", group.dimension, group.tag, jsonString(group.name), count, shared);
  }
  out += mesh.physicalGroups.empty() ? "],\n" : "\n  ],\n";
  out += fmt::format("  \"interfaceFaces\": {},\n  \"interfaces\": [", source.interfaceFaces);
  bool firstInterface = true;
  for (const auto& [pair, count] : stats.interfaces) {
    // A volume in no physical group is tag 0 with its elementary entity; a grouped one, entity 0.
    const auto tag = [](std::int64_t v) { return v > 0 ? v : 0; };
    const auto entity = [](std::int64_t v) { return v < 0 ? -v : 0; };
    const auto name = [&](std::int64_t v) {
      return jsonString(mesh.physicalName(static_cast<std::int32_t>(tag(v))));
    };
    out += fmt::format(
        "{}\n    {{\"tags\": [{}, {}], \"entities\": [{}, {}], \"names\": [{}, {}], \"faces\": {}}}",
        firstInterface ? "" : ",", tag(pair.first), tag(pair.second), entity(pair.first), entity(pair.second),
        name(pair.first), name(pair.second), count);
    firstInterface = false;
  }
  out += stats.interfaces.empty() ? "],\n" : "\n  ],\n";
  out += "  \"fields\": [";
  for (std::size_t i = 0; i < mesh.fields.size(); ++i) {
    const MeshField& field = mesh.fields[i];
    const auto [low, high] = field.range();
    out += fmt::format(
        "{}\n    {{\"name\": {}, \"location\": \"{}\", \"components\": {}, \"step\": {}, \"time\": {:.17g}, "
        "\"min\": {:.9g}, \"max\": {:.9g}}}",
        i ? "," : "", jsonString(field.name), fieldAtName(field.at), field.components, field.step, field.time,
        low, high);
  }
  out += mesh.fields.empty() ? "],\n" : "\n  ],\n";
  if (mesh.faceCount()) {
    const Aabbd& box = stats.worldBounds;
    out += fmt::format(
        "  \"boundingBox\": {{\"min\": [{:.17g}, {:.17g}, {:.17g}], \"max\": [{:.17g}, {:.17g}, "
        "{:.17g}]}},\n",
        box.lower.x, box.lower.y, box.lower.z, box.upper.x, box.upper.y, box.upper.z);
  } else {
    out += "  \"boundingBox\": null,\n";
  }
  out += fmt::format("  \"area\": {:.17g},\n  \"shells\": [", stats.area);
  for (std::size_t s = 0; s < stats.shells.size(); ++s) {
    const MeshShell& shell = stats.shells[s];
    out += fmt::format(
        "{}\n    {{\"faces\": {}, \"area\": {:.17g}, \"closed\": {}, \"consistentlyOriented\": {}, "
        "\"signedVolume\": {:.17g}, \"cavity\": {}, \"interface\": {}}}",
        s ? "," : "", shell.faceCount, shell.area, shell.closed, shell.consistentlyOriented,
        shell.signedVolume, shell.cavity, shell.interface);
  }
  out += stats.shells.empty() ? "],\n" : "\n  ],\n";
  if (!accelMember.empty()) out += accelMember + ",\n";
  out += fmt::format("  \"loadSeconds\": {:.6f}\n}}\n", source.loadSeconds);
  std::fputs(out.c_str(), stdout);
}

}  // namespace

void addInfoCommand(CLI::App& app, CommandRunner& runner) {
  struct Options {
    std::vector<std::string> files;  // the mesh, then .pos views to put on it
    bool json = false;
    std::string accel;  // empty: no accelerator section
  };
  auto options = std::make_shared<Options>();
  CLI::App* command =
      app.add_subcommand("info", "Describe a gmsh .msh file (or .pos view) as lancer reads it");
  command->add_option("FILE", options->files, "the .msh or .pos file, then .pos views to put on it")
      ->required();
  command->add_flag("--json", options->json, "machine-readable output");
  command
      ->add_option("--accel", options->accel,
                   "also build an accelerator (default bvh) and report its statistics")
      ->expected(0, 1)
      ->default_str(std::string(kDefaultAccelName))
      ->check(CLI::IsMember(std::vector<std::string>(kAccelNames.begin(), kAccelNames.end())));
  command->callback([&runner, options] {
    runner = [options] {
      std::vector<std::string> views;
      const std::string file = takeMeshInput(options->files, views);
      Mesh mesh = readMeshFile(file);
      addViewFiles(mesh, views);
      const MeshStats stats = computeMeshStats(mesh);
      if (options->json) {
        printJson(mesh, stats,
                  options->accel.empty()
                      ? ""
                      : accelStatsJson(buildAccelStats(mesh, parseAccelKind(options->accel))));
      } else {
        printText(mesh, stats);
        if (!options->accel.empty())
          std::fputs(accelStatsText(buildAccelStats(mesh, parseAccelKind(options->accel))).c_str(), stdout);
      }
      return kExitOk;
    };
  });
}

}  // namespace lancer::cli
