// Bad colour maps and log scales: an unknown map (with the closest name and the maps there are), a
// bad colour in a list, a list too short, a log scale over values <= 0 (naming the field and its least
// value, and what to do), gmsh's ColormapNumber past its maps; through the scene file, --color-map
// and a gmsh options file. The CLI exits with 2 and writes nothing.
#include <gtest/gtest.h>

#include <filesystem>

#include "lancer/mesh/msh_reader.hpp"
#include "lancer/scene/results/color_by.hpp"
#include "lancer/scene/results/gmsh_post_options.hpp"
#include "lancer/scene/scene.hpp"
#include "support/cli.hpp"
#include "support/files.hpp"
#include "support/input_errors.hpp"

namespace lancer {
namespace {

std::string parseError(const std::string& text) {
  return test::messageOf([&] {
    const toml::table root = toml::parse(std::string_view(text), std::string_view("scene.toml"));
    const TomlTableReader reader(root, "mesh[0]", "scene.toml", SceneTable::Mesh);
    readColorBy("scene.toml", reader);
  });
}

bool startsWith(const std::string& text, const std::string& start) { return text.rfind(start, 0) == 0; }

TEST(ColorMapBadInput, UnknownNameOffersTheClosestAndListsTheMaps) {
  const std::string what = parseError(R"(color_by = { field = "t", map = "virdis" })");
  EXPECT_TRUE(startsWith(what,
                         "scene.toml:1:33: error: mesh[0].color_by.map: \"virdis\" is not a colour map (did "
                         "you mean 'viridis'?): use viridis, plasma, inferno, magma, cividis, "))
      << what;
  EXPECT_NE(
      what.find(", twilight (matplotlib's), gmsh:0 to gmsh:24 (gmsh's View.ColormapNumber); NAME_r reverses "
                "any; or a list of colours such as [\"#000080\", \"white\", \"#800000\"]"),
      std::string::npos)
      << what;
  EXPECT_NE(parseError(R"(color_by = { field = "t", map = "virdis_r" })").find("(did you mean 'viridis_r'?)"),
            std::string::npos);
  EXPECT_NE(parseError(R"(color_by = { field = "t", map = "rdbu" })").find("(did you mean 'RdBu'?)"),
            std::string::npos);
  EXPECT_NE(parseError(R"(color_by = { field = "t", map = "gmsh:25" })")
                .find("mesh[0].color_by.map: \"gmsh:25\" is not one of gmsh's colour maps: gmsh:0 to gmsh:24 "
                      "(gmsh's View.ColormapNumber), with _r to reverse one"),
            std::string::npos);
  EXPECT_NE(parseError(R"(color_by = { field = "t", map = 3 })")
                .find("mesh[0].color_by.map must be a colour map's name (\"viridis\") or a list of colours "
                      "([\"#000080\", \"white\", \"#800000\"]), found integer 3"),
            std::string::npos);
}

TEST(ColorMapBadInput, BadListsPointAtTheColour) {
  EXPECT_EQ(parseError(R"(color_by = { field = "t", map = ["#000080", "whte"] })"),
            "scene.toml:1:45: error: mesh[0].color_by.map[1]: \"whte\" is not a colour (did you mean "
            "'white'?): use "
            "\"#rrggbb\", \"#rgb\" or a CSS colour name such as \"navy\"");
  EXPECT_EQ(
      parseError(R"(color_by = { field = "t", map = ["#000080", [1, 2, 0]] })"),
      "scene.toml:1:45: error: mesh[0].color_by.map[1] must be a colour: \"#rrggbb\", \"#rgb\", a CSS colour "
      "name such as \"navy\", or [r, g, b] with each 0 to 1; found array of 3 values");
  EXPECT_NE(
      parseError(R"(color_by = { field = "t", map = ["#000080"] })")
          .find("mesh[0].color_by.map must list 2 to 256 colours, evenly spaced from the low end to the high "
                "end, found array of 1 value"),
      std::string::npos)
      << parseError(R"(color_by = { field = "t", map = ["#000080"] })");
}

TEST(ColorMapBadInput, LogScaleNeedsARangeAboveZero) {
  EXPECT_EQ(
      parseError(R"(color_by = { field = "t", scale = "logarithmic" })"),
      "scene.toml:1:35: error: mesh[0].color_by.scale must be \"linear\" or \"log\", found \"logarithmic\"");
  EXPECT_EQ(
      parseError(R"(color_by = { field = "t", scale = "log", range = [0, 5] })"),
      "scene.toml:1:50: error: mesh[0].color_by.range must have min > 0 with scale = \"log\", found [0, 5]: "
      "the "
      "low end is where the map starts (values below it, 0 and negative ones included, are drawn at it), "
      "e.g. [0.005, 5]");
}

TEST(ColorMapBadInput, LogScaleOverValuesDownToZeroNamesTheLeastValue) {
  const Mesh mesh = readMsh(test::dataFile("fields/node_xy_v41_ascii.msh"));  // x + 2 y over [0, 3]
  ColorBy spec;
  spec.field = "temperature";
  spec.scale = ColorScale::Log;
  spec.where = {"scene.toml", 3, 12};
  EXPECT_EQ(test::messageOf([&] { resolveColorBy(spec, mesh); }),
            "scene.toml:3:12: error: color_by field \"temperature\" in " + mesh.source.path +
                " has values down to 0 (over every step), but scale = \"log\" needs values > 0: give a range "
                "whose low end is > 0, e.g. range = [0.003, 3] (values below it are drawn at it), or scale = "
                "\"linear\"");
  // A field without a value above 0: the cantilever's downward displacement.
  const Mesh cantilever = readMsh(test::dataFile("results/cantilever.msh"));
  spec.field = "displacement";
  spec.component = *parseFieldComponent("y");
  EXPECT_NE(
      test::messageOf([&] { resolveColorBy(spec, cantilever); })
          .find("color_by field \"displacement\" in " + cantilever.source.path +
                " has no value above 0 (its greatest is 0, over every step), so scale = \"log\" cannot show "
                "it: use scale = \"linear\""),
      std::string::npos)
      << test::messageOf([&] { resolveColorBy(spec, cantilever); });
}

TEST(ColorMapBadInput, TooManyMapsInOneScene) {
  // A face's map is one of 63 per scene (FieldColors::kMapBits): a 64th different map is refused.
  const std::string file = test::dataFile("fields/node_xy_v41_ascii.msh");
  SceneDescription description;
  std::vector<Mesh> meshes;
  std::vector<std::string> names;  // 64 different maps: every name ("grey" is "gray"), then reversed
  for (const char* suffix : {"", "_r"})
    for (const std::string_view name : colorMapNames())
      if (name != "grey") names.push_back(std::string(name) + suffix);
  for (std::size_t i = 0; i < 64; ++i) {
    MeshInstance instance;
    instance.file = file;
    ColorBy colorBy;
    colorBy.field = "temperature";
    colorBy.map = *ColorMap::named(names[i]);
    colorBy.where = {"scene.toml", static_cast<std::int64_t>(10 + i), 12};
    instance.colorBy = colorBy;
    description.meshes.push_back(instance);
    meshes.push_back(readMsh(file));
  }
  const std::string last = description.meshes[63].colorBy->map.name();
  EXPECT_EQ(
      test::messageOf([&] { buildScene(description, std::move(meshes), 1); }),
      "scene.toml:73:12: error: color_by map \"" + last +
          "\": a scene colours its meshes with at most 63 different colour maps (or log ranges); give some "
          "meshes the same map");
}

TEST(ColorMapBadInput, GmshColormapNumberPastItsMaps) {
  test::ScratchFolder folder;
  folder.write("bad.opt", "View[0].Name = \"stress\";\nView[0].ColormapNumber = 30;\n");
  EXPECT_EQ(
      test::messageOf([&] { readGmshPostViews(folder.file("bad.opt")); }),
      folder.file("bad.opt") + ":2:26: error: View[0].ColormapNumber = 30: gmsh's colour maps are 0 to 24");
}

TEST(ColorMapBadInput, CliColorMapSaysWhatIsWrongAndWritesNothing) {
  test::ScratchFolder folder;
  const std::string mesh = test::quoted(test::dataFile("fields/node_xy_v41_ascii.msh"));
  const std::string out = folder.file("out.png");
  const auto run = [&](const std::string& options) {
    return test::runCli("render -q " + mesh + " --width 16 --height 16 " + options + " -o " +
                        test::quoted(out));
  };
  test::CommandResult result = run("--color-by temperature --color-map virdis");
  EXPECT_EQ(result.exitCode, 2);
  EXPECT_NE(
      result.output.find("--color-map: error: \"virdis\" is not a colour map (did you mean 'viridis'?): use "
                         "viridis, "),
      std::string::npos)
      << result.output;
  result = run("--color-by temperature --color-map '#000080,whte'");
  EXPECT_EQ(result.exitCode, 2);
  EXPECT_NE(
      result.output.find("--color-map: error: colour 2: \"whte\" is not a colour (did you mean 'white'?)"),
      std::string::npos)
      << result.output;
  result = run("--color-map magma");
  EXPECT_EQ(result.exitCode, 2);
  EXPECT_NE(
      result.output.find("--color-map: error: no mesh is coloured by a field: give --color-by FIELD too (or "
                         "color_by in the scene)"),
      std::string::npos)
      << result.output;
  EXPECT_FALSE(std::filesystem::exists(out));
}

}  // namespace
}  // namespace lancer
