// Bad lighting input, each with the message the user sees: unknown integrator or light type, a
// negative or non-finite intensity, a sun angle outside (0, 180), noise outside (0, 1), keys of
// another light type, and environment maps that are missing, unreadable or not 2:1.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "lancer/image/exr_io.hpp"
#include "lancer/scene/scene_loader.hpp"
#include "support/input_errors.hpp"
#include "support/test_scenes.hpp"

namespace lancer {
namespace {

TEST(LightingKeys, UnknownIntegratorNamesTheChoices) {
  test::expectSceneErrorContains("[render]\nintegrator = \"photon\"\n", "scene.toml:2");
  test::expectSceneErrorContains("[render]\nintegrator = \"photon\"\n", "whitted");
}

TEST(LightingKeys, UnknownLightType) {
  test::expectSceneErrorContains("[[light]]\ntype = \"spot\"\nposition = [0, 0, 0]\n", "scene.toml:2");
  test::expectSceneErrorContains("[[light]]\ntype = \"spot\"\nposition = [0, 0, 0]\n", "sphere");
}

TEST(LightingKeys, NegativeOrNonFiniteIntensity) {
  test::expectSceneErrorContains("[[light]]\nposition = [0, 0, 0]\nintensity = [1, -1, 1]\n", "scene.toml:3");
  test::expectSceneErrorContains("[[light]]\nposition = [0, 0, 0]\nintensity = [1, inf, 1]\n", "finite");
  test::expectSceneErrorContains("[[light]]\nposition = [0, 0, 0]\nintensity = [nan, 1, 1]\n",
                                 "scene.toml:3");
}

TEST(LightingKeys, SunAngleOutsideZeroTo180) {
  for (const char* angle : {"0", "180", "-5", "200"})
    test::expectSceneErrorContains(
        std::string("[[light]]\ntype = \"sun\"\ndirection = [0, 1, 0]\nangle = ") + angle + "\n",
        "scene.toml:4");
  test::expectSceneErrorContains("[[light]]\ntype = \"sun\"\n", "direction = [x, y, z]");
}

TEST(LightingKeys, KeysOfAnotherLightType) {
  test::expectSceneErrorContains("[[light]]\nposition = [0, 0, 0]\nangle = 3\n", "sun lights");
  test::expectSceneErrorContains("[[light]]\ntype = \"sphere\"\nposition = [0, 0, 0]\n", "radius");
  test::expectSceneErrorContains("[[light]]\ntype = \"rect\"\nposition = [0, 0, 0]\nwidth = 1\n", "height");
}

TEST(LightingKeys, NoiseOutsideZeroToOne) {
  for (const char* noise : {"0", "1", "-0.1", "2"})
    test::expectSceneErrorContains(std::string("[render]\nnoise = ") + noise + "\n", "scene.toml:2");
}

TEST(LightingKeys, AdaptiveNoiseOutsideZeroToOne) {
  for (const char* noise : {"0", "1", "-0.1", "nan", "1e40"})
    test::expectSceneErrorContains(std::string("[render]\nadaptive_noise = ") + noise + "\n", "scene.toml:2");
  test::expectSceneErrorContains("[render]\nadaptive_noise = 2\n",
                                 "adaptive_noise must be greater than 0 and less than 1 (the error of the "
                                 "displayed value, a fraction of white, e.g. 0.01), found 2");
}

TEST(LightingKeys, EnvironmentKindsAreExclusive) {
  test::expectSceneErrorContains("[environment]\ncolor = [1, 1, 1]\nmap = \"sky.hdr\"\n", "give one of");
}

TEST(LightingKeys, ValuesBeyondAFloatAreRefusedNamingTheKey) {
  test::expectSceneErrorContains("[environment]\nrotation = 1e41\n",
                                 "scene.toml:2:12: error: environment.rotation must be between -3.402823e+38 "
                                 "and 3.402823e+38 (the range of a float), found 1e+41");
  test::expectSceneErrorContains("[[light]]\nposition = [0, 0, 0]\nintensity = [1e39, 1, 1]\n",
                                 "light[0].intensity[0] must be between -3.402823e+38");
  test::expectSceneErrorContains("[environment]\nstrength = 1e39\n", "environment.strength must be between");
  test::expectSceneErrorContains("[material.m]\nemission = [0, 0, -1e300]\n", "material.m.emission[2]");
  test::expectSceneErrorContains("[[light]]\ntype = \"disk\"\nposition = [0, 0, 0]\nradius = 1e39\n",
                                 "light[0].radius must be between");
}

// buildScene's message for the scene `text` (no meshes).
std::string buildErrorOf(const std::string& text) {
  SceneDescription d = parseScene(text, "scene.toml");
  return test::messageOf([&] { buildScene(d, std::vector<Mesh>{}); });
}

TEST(LightingKeys, LightsWhoseRadianceOverflowsAreRefused) {
  std::string message = buildErrorOf("[[light]]\ntype = \"disk\"\nposition = [0, 0, 0]\nradius = 1e-30\n");
  EXPECT_NE(
      message.find("scene.toml:1:1: error: the disk light of radius 1e-30 and intensity [1, 1, 1] has a "
                   "radiance (pi intensity / area, area 0) too large for a float: give it a larger size "
                   "or a smaller intensity"),
      std::string::npos)
      << message;
  message = buildErrorOf("[[light]]\ntype = \"sun\"\ndirection = [0, 1, 0]\nangle = 1e-30\n");
  EXPECT_NE(message.find("the sun light of angle 1e-30"), std::string::npos) << message;
  message = buildErrorOf(
      "[[light]]\ntype = \"rect\"\nposition = [0, 0, 0]\nwidth = 0.1\nheight = 0.1\nintensity = [3e38, 1, "
      "1]\n");
  EXPECT_NE(message.find("the rect light of width 0.1 and height 0.1"), std::string::npos) << message;
  EXPECT_EQ(buildErrorOf("[[light]]\ntype = \"disk\"\nposition = [0, 0, 0]\nradius = 1e-6\n"),
            "(no InputError)");
}

TEST(LightingKeys, EnvironmentStrengthTimesItsColourMustFitAFloat) {
  const std::string message = buildErrorOf("[environment]\ncolor = [1, 3e38, 1]\nstrength = 10\n");
  EXPECT_NE(message.find("scene.toml:1:1: error: environment.strength 10 times the environment's brightest "
                         "value 3e+38 is too large for a float: lower the strength"),
            std::string::npos)
      << message;
}

TEST(LightingKeys, EnvironmentRotationIsReducedToOneTurnBeforeBecomingAFloat) {
  for (const char* rotation : {"1e20", "-3.4e38", "720"}) {
    SceneDescription d =
        parseScene(std::string("[environment]\nrotation = ") + rotation + "\n", "scene.toml");
    const Scene scene = buildScene(d, std::vector<Mesh>{});
    ASSERT_TRUE(scene.environment);
    EXPECT_LE(std::abs(scene.environment->rotationRadians), 2 * 3.1415927f) << rotation;
  }
}

// buildScene's message for a description whose environment map is `file`.
std::string mapErrorOf(const std::string& file) {
  SceneDescription d = parseScene("[environment]\nmap = \"" + file + "\"\n", "scene.toml");
  return test::messageOf([&] { buildScene(d, std::vector<Mesh>{}); });
}

TEST(LightingKeys, MissingMapNamesTheFileAndTheLine) {
  const std::string message = mapErrorOf("/nonexistent/sky.hdr");
  EXPECT_NE(message.find("scene.toml:2"), std::string::npos) << message;
  EXPECT_NE(message.find("/nonexistent/sky.hdr"), std::string::npos) << message;
}

TEST(LightingKeys, UnreadableMapSaysWhatWasRead) {
  const std::filesystem::path file = std::filesystem::temp_directory_path() / "lancer_not_a_map.hdr";
  std::ofstream(file) << "sky 2 2\n255\n";
  const std::string message = mapErrorOf(file.string());
  EXPECT_NE(message.find("the first line is \"sky 2 2\""), std::string::npos) << message;
  EXPECT_NE(message.find("#?RADIANCE"), std::string::npos) << message;
  std::filesystem::remove(file);
}

TEST(LightingKeys, MapThatIsNotTwoToOne) {
  const std::filesystem::path file = std::filesystem::temp_directory_path() / "lancer_square_map.hdr";
  {
    std::ofstream out(file, std::ios::binary);
    out << "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 4 +X 4\n";
    for (int i = 0; i < 16; ++i) out << '\x80' << '\x80' << '\x80' << '\x80';
  }
  const std::string message = mapErrorOf(file.string());
  EXPECT_NE(message.find("4 x 4"), std::string::npos) << message;
  EXPECT_NE(message.find("twice as wide"), std::string::npos) << message;
  std::filesystem::remove(file);
}

TEST(LightingKeys, KaInAPathSceneIsAWarning) {
  const auto warningsOf = [](const std::string& text) {
    SceneDescription d = parseScene(text, "scene.toml");
    return buildScene(d, std::vector<Mesh>{}).warnings;
  };
  const std::vector<std::string> path =
      warningsOf("[render]\nintegrator = \"path\"\n[material.m]\nka = [0.1, 0.1, 0.1]\n");
  ASSERT_EQ(path.size(), 1u);
  EXPECT_NE(path[0].find("scene.toml"), std::string::npos) << path[0];
  EXPECT_NE(path[0].find("ka are not used by integrator = \"path\""), std::string::npos) << path[0];
  EXPECT_EQ(warningsOf("[render]\nintegrator = \"path\"\n[ambient]\nintensity = [0.1, 0.1, 0.1]\n").size(),
            1u);
  EXPECT_TRUE(warningsOf("[material.m]\nka = [0.1, 0.1, 0.1]\n").empty());  // the Whitted model uses it
  EXPECT_TRUE(warningsOf("[render]\nintegrator = \"path\"\n").empty());
}

TEST(LightingKeys, MissingExrMapNamesTheFileAndTheLine) {
  const std::string message = mapErrorOf("/nonexistent/sky.exr");
  EXPECT_NE(message.find("scene.toml:2"), std::string::npos) << message;
  EXPECT_NE(message.find("cannot open '/nonexistent/sky.exr'"), std::string::npos) << message;
}

TEST(LightingKeys, ExrMapThatIsNotAnExrSaysWhatWasRead) {
  const std::filesystem::path file = std::filesystem::temp_directory_path() / "lancer_not_a_map.exr";
  std::ofstream(file) << "Q3\n2 2\n255\n";
  const std::string message = mapErrorOf(file.string());
  EXPECT_NE(message.find("is not an OpenEXR image"), std::string::npos) << message;
  EXPECT_NE(message.find("51 33 0a 32"), std::string::npos) << message;  // "Q3\n2"
  EXPECT_NE(message.find("76 2f 31 01"), std::string::npos) << message;
  std::ofstream(file, std::ios::trunc) << "v/";
  EXPECT_NE(mapErrorOf(file.string()).find("2 bytes long"), std::string::npos);
  std::filesystem::remove(file);
}

TEST(LightingKeys, ExrMapThatIsNotTwoToOneOrNotFinite) {
  if (!exrSupported()) GTEST_SKIP() << "built without OpenEXR";
  const std::filesystem::path file = std::filesystem::temp_directory_path() / "lancer_bad_map.exr";
  writeExr(file.string(), Image(6, 4));
  std::string message = mapErrorOf(file.string());
  EXPECT_NE(message.find("6 x 4"), std::string::npos) << message;
  EXPECT_NE(message.find("twice as wide"), std::string::npos) << message;
  Image withNan(8, 4);
  withNan.at(5, 2).g = std::nanf("");
  writeExr(file.string(), withNan);
  message = mapErrorOf(file.string());
  EXPECT_NE(message.find("non-finite"), std::string::npos) << message;
  EXPECT_NE(message.find("pixel (5, 2)"), std::string::npos) << message;
  EXPECT_NE(message.find("scene.toml:2"), std::string::npos) << message;
  std::filesystem::remove(file);
}

}  // namespace
}  // namespace lancer
