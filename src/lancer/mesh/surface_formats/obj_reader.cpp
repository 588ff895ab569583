#include "lancer/mesh/surface_formats/obj_reader.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>

#include "lancer/mesh/msh/text_number.hpp"
#include "lancer/mesh/surface_formats/surface_mesh.hpp"
#include "lancer/mesh/surface_formats/text_lines.hpp"

namespace lancer {
namespace {

// The statements of the OBJ specification (Wavefront's "Object Files (.obj)", appendix B1) that
// lancer reads past: texture and normal data, free-form geometry, grouping it does not use, display
// attributes.
constexpr std::string_view kIgnored[] = {
    "vt",         "vn",        "vp",    "cstype", "deg",      "bmat",     "step", "p",      "l",
    "curv",       "curv2",     "surf",  "parm",   "trim",     "hole",     "scrv", "sp",     "end",
    "con",        "s",         "mg",    "bevel",  "c_interp", "d_interp", "lod",  "usemtl", "mtllib",
    "shadow_obj", "trace_obj", "ctech", "stech",  "maplib",   "usemap"};

bool isIgnored(std::string_view keyword) {
  return std::find(std::begin(kIgnored), std::end(kIgnored), keyword) != std::end(kIgnored);
}

// A positive index checked once every point is read (a file may name points before it lists them),
// the largest with where it was.
struct LargestIndex {
  std::int64_t index = 0;
  std::int64_t line = 0;
  std::int64_t column = 0;
};

}  // namespace

bool looksLikeObj(std::span<const char> head) {
  TextLines lines(head, "");
  int points = 0, statements = 0;
  // The last line may be cut by the head's end: only whole lines count.
  while (lines.nextLine() && lines.nextLineOffset() <= head.size() && statements < 64) {
    const std::string_view keyword = lines.token();
    if (keyword.empty() || keyword.front() == '#') continue;
    if (keyword == "v") {
      ++points;
    } else if (keyword != "f" && keyword != "g" && keyword != "o" && !isIgnored(keyword)) {
      return false;
    }
    ++statements;
  }
  return points > 0;
}

Mesh readObj(std::span<const char> bytes, const std::string& name) {
  TextLines lines(bytes, name);
  SurfaceData data;
  SurfaceGroup* group = nullptr;
  LargestIndex largest;
  std::vector<std::uint32_t> corners;
  while (lines.nextLine()) {
    const std::string_view keyword = lines.token();
    if (keyword.empty() || keyword.front() == '#') continue;
    if (keyword == "v") {
      Vec3d p;
      p.x = lines.readNumber("the x coordinate of a vertex");
      p.y = lines.readNumber("the y coordinate of a vertex");
      p.z = lines.readNumber("the z coordinate of a vertex");
      // A weight or a colour (r g b, as some scanners write) may follow: not used.
      if (data.points.size() == UINT32_MAX - 1)
        lines.fail("more than 4294967294 vertices: too many for lancer");
      data.points.push_back(p);
    } else if (keyword == "f") {
      corners.clear();
      for (std::string_view corner = lines.token(); !corner.empty() && corner.front() != '#';
           corner = lines.token()) {
        // v, v/vt, v//vn or v/vt/vn: the point's index is before the first slash.
        const std::string_view text = corner.substr(0, corner.find('/'));
        std::int64_t index = 0;
        const auto [next, error] = std::from_chars(text.data(), text.data() + text.size(), index);
        if (error == std::errc::result_out_of_range)
          lines.fail(fmt::format("vertex index {} is out of range", quoteTokenForMessage(text)));
        if (error != std::errc() || next != text.data() + text.size() || text.empty())
          lines.fail(fmt::format("expected a face corner (v, v/vt, v//vn or v/vt/vn, v an integer), found {}",
                                 quoteTokenForMessage(corner)));
        const auto defined = static_cast<std::int64_t>(data.points.size());
        if (index == 0)
          lines.fail("vertex index 0: OBJ numbers vertices from 1 (or from -1 back from the last)");
        if (index < 0) {
          if (-index > defined)
            lines.fail(
                fmt::format("vertex index {} counts back past the first vertex: {} {} defined before "
                            "this line",
                            index, defined, defined == 1 ? "is" : "are"));
          index += defined + 1;
        } else if (index > largest.index) {
          largest = {index, lines.lineNumber(), lines.tokenColumn()};
        }
        corners.push_back(static_cast<std::uint32_t>(index - 1));
      }
      if (corners.size() < 3)
        lines.failAtLine(fmt::format("a face with {} {}: a face needs at least 3", corners.size(),
                                     corners.size() == 1 ? "vertex" : "vertices"));
      if (!group) group = &data.group("");
      if (corners.size() == 4) {
        group->quads.insert(group->quads.end(), corners.begin(), corners.end());
      } else {
        for (std::size_t k = 1; k + 1 < corners.size(); ++k)
          for (const std::uint32_t corner : {corners[0], corners[k], corners[k + 1]})
            group->triangles.push_back(corner);
      }
    } else if (keyword == "g" || keyword == "o") {
      group = &data.group(lines.restOfLine());
    } else if (!isIgnored(keyword)) {
      lines.fail(
          fmt::format("{} is not an OBJ statement (v, f, g, o, and those lancer ignores: vt, vn, "
                      "usemtl, ...)",
                      quoteTokenForMessage(keyword)));
    }
  }
  if (largest.index > static_cast<std::int64_t>(data.points.size()))
    throw InputError(SourceLocation{name, largest.line, largest.column},
                     fmt::format("vertex index {} is out of range: the file defines {} vertices",
                                 largest.index, data.points.size()));
  MeshSourceInfo source;
  source.path = name;
  source.format = "obj";
  source.fileBytes = bytes.size();
  return meshFromSurface(data, std::move(source));
}

}  // namespace lancer
