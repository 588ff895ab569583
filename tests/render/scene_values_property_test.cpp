// Extreme values for every numeric key of the lights, the environment, [render] and the results
// tables (warp, color_by, isolines, arrows) of a scene file: a render either succeeds or fails with an
// InputError or NonFiniteRenderError (exit code 2 in the CLI), never another exception (exit code 1)
// or a crash. Each key gets each value on its own, with each integrator in turn, then random
// combinations of a few keys; a few go through the CLI to check the exit codes themselves.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <exception>
#include <random>
#include <string>
#include <vector>

#include "lancer/render/render_preparation.hpp"
#include "lancer/scene/scene_loader.hpp"
#include "lancer/util/input_error.hpp"
#include "support/cli.hpp"
#include "support/files.hpp"

namespace lancer {
namespace {

// A tiny render of the gmsh-made cantilever under one light of each type, with its results drawn.
// @key@ marks each value the test changes; the values given here render cleanly with every integrator.
const char* const kSceneTemplate = R"([render]
width = @width@
height = @height@
samples = @samples@
max_depth = @max_depth@
exposure = @exposure@
bit_depth = @bit_depth@
adaptive_threshold = @adaptive_threshold@
step = @step@
max_bounces = @max_bounces@
noise = @noise@
ao_distance = @ao_distance@
integrator = "@integrator@"

[camera]
position = [20, 8, 14]
look_at = [5, 0, 0]

[[light]]
type = "point"
position = @point.position@
intensity = @point.intensity@
attenuation = @point.attenuation@

[[light]]
type = "sun"
direction = @sun.direction@
intensity = @sun.intensity@
angle = @sun.angle@

[[light]]
type = "sphere"
position = [5, 10, 3]
intensity = @sphere.intensity@
radius = @sphere.radius@

[[light]]
type = "rect"
position = @rect.position@
direction = @rect.direction@
intensity = [1, 1, 1]
width = @rect.width@
height = @rect.height@

[[light]]
type = "disk"
position = [5, 10, 3]
direction = @disk.direction@
intensity = @disk.intensity@
radius = @disk.radius@

[environment]
@environment.sky@
strength = @environment.strength@
rotation = @environment.rotation@

[[mesh]]
file = "@mesh@"
warp = { field = "displacement", factor = @warp.factor@ }
color_by = { field = "stress", component = "von_mises", step = @color_by.step@, range = @color_by.range@, bands = @color_by.bands@ }
isolines = { field = "stress", count = @isolines.count@, width = @isolines.width@, step = @isolines.step@ }
arrows = { field = "displacement", max_count = @arrows.max_count@, scale = @arrows.scale@, step = @arrows.step@ }
)";

struct Key {
  std::string name;
  std::string value;   // the clean one
  int components = 0;  // 0: a number; n: an array of n numbers
};

const std::vector<Key>& keys() {
  static const std::vector<Key> kKeys = {
      {"width", "8"},
      {"height", "6"},
      {"samples", "4"},
      {"max_depth", "3"},
      {"exposure", "0.5"},
      {"bit_depth", "8"},
      {"adaptive_threshold", "0.1"},
      {"step", "1"},
      {"max_bounces", "4"},
      {"noise", "0.5"},
      {"ao_distance", "2"},
      {"point.position", "[5, 10, 3]", 3},
      {"point.intensity", "[1, 1, 1]", 3},
      {"point.attenuation", "[1, 0, 0]", 3},
      {"sun.direction", "[-1, -1, -1]", 3},
      {"sun.intensity", "[1, 1, 1]", 3},
      {"sun.angle", "1"},
      {"sphere.intensity", "[1, 1, 1]", 3},
      {"sphere.radius", "0.5"},
      {"rect.position", "[5, 10, 3]", 3},
      {"rect.direction", "[0, -1, 0]", 3},
      {"rect.width", "2"},
      {"rect.height", "1"},
      {"disk.direction", "[0, -1, 0]", 3},
      {"disk.intensity", "[1, 1, 1]", 3},
      {"disk.radius", "0.5"},
      {"environment.zenith", "[0.2, 0.3, 0.5]", 3},
      {"environment.horizon", "[0.8, 0.8, 0.8]", 3},
      {"environment.ground", "[0.1, 0.1, 0.1]", 3},
      {"environment.color", "", 3},  // a uniform sky in place of the gradient
      {"environment.strength", "1"},
      {"environment.rotation", "30"},
      {"warp.factor", "2"},
      {"color_by.step", "1"},
      {"color_by.range", "[0, 10]", 2},
      {"color_by.bands", "5"},
      {"isolines.count", "4"},
      {"isolines.width", "1.5"},
      {"isolines.step", "1"},
      {"arrows.max_count", "20"},
      {"arrows.scale", "1"},
      {"arrows.step", "1"},
  };
  return kKeys;
}

// TOML spellings of extreme numbers: signed zero, tiny, past float, past double's denormals, NaN and
// infinities (as TOML has them and as a string), integers past 32 and 64 bits.
const std::vector<std::string>& extremeValues() {
  static const std::vector<std::string> kValues = {"0",
                                                   "-0.0",
                                                   "-1",
                                                   "0.5",
                                                   "7",
                                                   "1024",
                                                   "1e-30",
                                                   "-1e-30",
                                                   "1e-310",
                                                   "3e38",
                                                   "1e39",
                                                   "-1e39",
                                                   "1e308",
                                                   "\"NaN\"",
                                                   "nan",
                                                   "inf",
                                                   "-inf",
                                                   "2147483648",
                                                   "4294967297",
                                                   "9223372036854775807",
                                                   "-9223372036854775808"};
  return kValues;
}

const char* const kIntegrators[] = {"whitted", "path", "ao"};

// The scene text with `changes` (key name -> TOML value, one component or whole) over the clean values.
struct Change {
  const Key* key;
  std::string value;
  int component;  // -1: the whole value (every component for arrays)
};

std::string sceneText(const std::vector<Change>& changes, const char* integrator) {
  std::string text = kSceneTemplate;
  const auto replace = [&](const std::string& name, const std::string& value) {
    const std::string marker = "@" + name + "@";
    const std::size_t at = text.find(marker);
    ASSERT_NE(at, std::string::npos) << name;
    text.replace(at, marker.size(), value);
  };
  std::string sky =
      "zenith = @environment.zenith@\nhorizon = @environment.horizon@\nground = @environment.ground@";
  for (const Change& change : changes)
    if (change.key->name == "environment.color") sky = "color = @environment.color@";
  replace("environment.sky", sky);
  for (const Key& key : keys()) {
    if (text.find("@" + key.name + "@") == std::string::npos) continue;
    std::string value = key.name == "environment.color" ? "[0.5, 0.5, 0.5]" : key.value;
    for (const Change& change : changes) {
      if (change.key != &key) continue;
      if (key.components == 0 || change.component < 0) {
        value = change.value;
        if (key.components > 0) {
          value = "[" + change.value;
          for (int c = 1; c < key.components; ++c) value += ", " + change.value;
          value += "]";
        }
      } else {
        value = "[";
        for (int c = 0; c < key.components; ++c)
          value += std::string(c > 0 ? ", " : "") + (c == change.component ? change.value : "0.5");
        value += "]";
      }
    }
    replace(key.name, value);
  }
  replace("integrator", integrator);
  replace("mesh", test::dataFile("results/cantilever.msh"));
  return text;
}

// What the CLI would make of the scene: "ok", "input error" (exit code 2), or the failure itself.
std::string outcomeOf(const std::string& text) {
  try {
    RenderRequest request;
    request.description = parseScene(text, "/property/scene.toml");
    request.threads = 1;
    const PreparedRender prepared = prepareRender(std::move(request));
    RenderOptions options;
    options.threads = 1;
    (void)prepared.renderer().renderImage(options);
    return "ok";
  } catch (const InputError&) {
    return "input error";
  } catch (const NonFiniteRenderError&) {
    return "input error";
  } catch (const std::exception& e) {
    return std::string("other exception (exit code 1): ") + e.what();
  }
}

TEST(SceneValues, TheCleanSceneRendersWithEveryIntegrator) {
  for (const char* integrator : kIntegrators)
    EXPECT_EQ(outcomeOf(sceneText({}, integrator)), "ok") << integrator;
}

TEST(SceneValues, EveryKeyTakesEveryExtremeValueAsAnInputErrorOrARender) {
  int trial = 0, rendered = 0;
  for (const Key& key : keys())
    for (const std::string& value : extremeValues())
      for (int component = -1; component < (key.components > 1 ? 1 : 0); ++component) {
        const char* integrator = kIntegrators[trial++ % 3];
        const std::string text = sceneText({{&key, value, component}}, integrator);
        const std::string outcome = outcomeOf(text);
        rendered += outcome == "ok" ? 1 : 0;
        EXPECT_TRUE(outcome == "ok" || outcome == "input error")
            << key.name << " = " << value << " (component " << component << ", " << integrator
            << "): " << outcome;
      }
  // Most extreme values are refused, but not all: the test must render, not only parse.
  EXPECT_GT(rendered, trial / 5) << rendered << " of " << trial;
  std::printf("%d of %d scenes rendered\n", rendered, trial);
}

TEST(SceneValues, RandomCombinationsAreAnInputErrorOrARender) {
  std::mt19937 random(20240611);  // fixed: the same scenes every run
  for (int trial = 0; trial < 150; ++trial) {
    std::vector<Change> changes;
    const int count = 2 + static_cast<int>(random() % 3);
    for (int c = 0; c < count; ++c) {
      const Key& key = keys()[random() % keys().size()];
      const int component = key.components > 0 ? static_cast<int>(random() % (key.components + 1)) - 1 : -1;
      // One image-size key at most, or a combination may ask for a large image.
      if ((key.name == "width" || key.name == "height" || key.name == "samples") &&
          std::any_of(changes.begin(), changes.end(), [](const Change& change) {
            return change.key->name == "width" || change.key->name == "height" ||
                   change.key->name == "samples";
          }))
        continue;
      changes.push_back({&key, extremeValues()[random() % extremeValues().size()], component});
    }
    const char* integrator = kIntegrators[trial % 3];
    const std::string outcome = outcomeOf(sceneText(changes, integrator));
    std::string described;
    for (const Change& change : changes) described += change.key->name + " = " + change.value + "; ";
    EXPECT_TRUE(outcome == "ok" || outcome == "input error") << described << integrator << ": " << outcome;
  }
}

// The CLI itself: exit code 0 or 2 (never 1, never a signal) for one value of each kind.
TEST(SceneValues, TheCliExitsWithZeroOrTwo) {
  const test::ScratchFolder folder;
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"point.intensity", "1e39"},      {"disk.radius", "1e-30"},
      {"exposure", "\"NaN\""},          {"noise", "-0.0"},
      {"isolines.count", "4294967297"}, {"environment.strength", "3e38"},
      {"ao_distance", "inf"},           {"max_bounces", "9223372036854775807"}};
  int trial = 0;
  for (const auto& [name, value] : cases) {
    const std::string& wanted = name;
    const auto key =
        std::find_if(keys().begin(), keys().end(), [&](const Key& k) { return k.name == wanted; });
    ASSERT_NE(key, keys().end()) << name;
    const char* integrator = kIntegrators[trial++ % 3];
    folder.write("scene.toml", sceneText({{&*key, value, -1}}, integrator));
    const test::CommandResult result = test::runCli("render -q " + test::quoted(folder.file("scene.toml")) +
                                                    " -o " + test::quoted(folder.file("out.png")));
    EXPECT_TRUE(result.exitCode == 0 || result.exitCode == 2)
        << name << " = " << value << " (" << integrator << "): exit " << result.exitCode << ": "
        << result.output;
  }
}

}  // namespace
}  // namespace lancer
