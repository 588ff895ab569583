// Every error path of the scene loader: each test checks the full file:line:col of the offending key
// or value and the words of the message (what was expected, what was found, what to try).
#include <gtest/gtest.h>

#include <string>
#include <string_view>

#include "lancer/scene/scene_loader.hpp"
#include "lancer/util/input_error.hpp"
#include "support/input_errors.hpp"

namespace lancer {
namespace {

const std::string kDataDir = LANCER_TEST_DATA_DIR "/scene";

using test::sceneErrorOf;

// `where` is "LINE:COL"; `message` must appear in the text after "scene.toml:LINE:COL: error: ".
testing::AssertionResult failsAt(std::string_view text, std::string_view where, std::string_view message) {
  const std::string actual = sceneErrorOf(text);
  const std::string prefix = "scene.toml:" + std::string(where) + ": error: ";
  if (actual.starts_with(prefix) && actual.find(message, prefix.size()) != std::string::npos)
    return testing::AssertionSuccess();
  return testing::AssertionFailure() << "expected \"" << prefix << "...\" containing \"" << message
                                     << "\"\n     got \"" << actual << "\"";
}

// ---- TOML syntax: toml++'s description and position, passed through as they are -------------------

TEST(SceneLoaderBadInput, SyntaxErrorKeepsTomlPosition) {
  EXPECT_EQ(sceneErrorOf("[render]\nwidth = 800\nheight = = 600\n"),
            "scene.toml:3:10: error: Error while parsing value: could not determine value type");
}

TEST(SceneLoaderBadInput, DuplicateKeyIsASyntaxError) {
  EXPECT_TRUE(failsAt("[camera]\nfov = 40\nfov = 50\n", "3:7", "cannot redefine existing integer 'fov'"));
}

TEST(SceneLoaderBadInput, UnterminatedString) {
  EXPECT_TRUE(failsAt("[render]\noutput = \"out.png\n", "2:18", "string"));
}

TEST(SceneLoaderBadInput, IntegerTooLargeForToml) {
  // toml++ points at the end of the number.
  EXPECT_TRUE(failsAt("[render]\nwidth = 99999999999999999999\n", "2:29",
                      "'99999999999999999999' is not representable in 64 bits"));
}

TEST(SceneLoaderBadInput, SyntaxErrorInAFileNamesThatFile) {
  const std::string path = kDataDir + "/syntax_error.toml";
  try {
    loadScene(path);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_TRUE(std::string(e.what()).starts_with(path + ":3:10: error: ")) << e.what();
    EXPECT_EQ(e.location().file, path);
    EXPECT_EQ(e.location().line, 3);
    EXPECT_EQ(e.location().column, 10);
  }
}

// ---- the file itself ---------------------------------------------------------------------------------

TEST(SceneLoaderBadInput, MissingFile) {
  const std::string path = kDataDir + "/no_such_scene.toml";
  try {
    loadScene(path);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), path + ": error: cannot open '" + path + "': No such file or directory");
  }
}

TEST(SceneLoaderBadInput, DirectoryInsteadOfFile) {
  try {
    loadScene(kDataDir);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              kDataDir + ": error: cannot open '" + kDataDir + "': it is a directory, not a scene file");
  }
}

// ---- unknown keys and tables ---------------------------------------------------------------------------

TEST(SceneLoaderBadInput, MisspeltKeySuggestsTheClosest) {
  EXPECT_EQ(sceneErrorOf("[render]\nwidht = 800\n"),
            "scene.toml:2:1: error: unknown key 'widht' in [render] (did you mean 'width'?)");
  EXPECT_TRUE(failsAt("[material.steel]\nshinyness = 50\n", "2:1",
                      "unknown key 'shinyness' in [material.steel] (did you mean 'shininess'?)"));
  EXPECT_TRUE(failsAt("[camera]\nlookat = [0, 0, 0]\n", "2:1",
                      "unknown key 'lookat' in [camera] (did you mean 'look_at'?)"));
}

TEST(SceneLoaderBadInput, UnknownKeyWithNothingCloseListsTheKnownOnes) {
  EXPECT_EQ(
      sceneErrorOf("[render]\nwidth = 10\ncolour = [1, 0, 0]\n"),
      "scene.toml:3:1: error: unknown key 'colour' in [render]; expected one of: width, height, samples, "
      "max_depth, sampler, shading, background, output, srgb, encoding, tonemap, exposure, bit_depth, "
      "denoise, adaptive_threshold, step, integrator, max_bounces, noise, adaptive_noise, ao_distance, "
      "quality, "
      "lossless, dpi");
  EXPECT_TRUE(
      failsAt("[[light]]\nposition = [0, 0, 0]\ncolor = [1, 1, 1]\n", "3:1",
              "unknown key 'color' in light[0]; expected one of: type, position, intensity, attenuation, "
              "direction, angle, radius, width, height"));
}

TEST(SceneLoaderBadInput, FirstUnknownKeyInFileOrderIsReported) {
  EXPECT_TRUE(failsAt("[render]\nzz = 1\naa = 2\n", "2:1", "unknown key 'zz'"));
}

TEST(SceneLoaderBadInput, UnknownKeyWrittenAsDottedKey) {
  EXPECT_TRUE(
      failsAt("render.widht = 800\n", "1:8", "unknown key 'widht' in [render] (did you mean 'width'?)"));
}

TEST(SceneLoaderBadInput, UnknownTopLevelTable) {
  EXPECT_EQ(sceneErrorOf("[ground]\nshadow_catcher = true\n"),
            "scene.toml:1:2: error: unknown key 'ground'; expected one of: render, camera, ambient, light, "
            "material, mesh, animation, clip, floor, environment");
  EXPECT_TRUE(failsAt("[[clip]]\npoint = [0, 0, 0]\n", "1:1", "clip[0] has no 'normal'"));
  EXPECT_TRUE(failsAt("[camra]\n", "1:2", "unknown key 'camra' (did you mean 'camera'?)"));
}

TEST(SceneLoaderBadInput, MeshClipIsCheckedLikeSceneClip) {
  const std::string mesh = "[[mesh]]\nfile = \"a.msh\"\n";
  EXPECT_TRUE(failsAt(mesh + "[[mesh.clip]]\npoint = [0, 0, 0]\n", "3:1",
                      "mesh[0].clip[0] has no 'normal'; add normal = [x, y, z]"));
  EXPECT_TRUE(failsAt(mesh + "[[mesh.clip]]\nnormal = [0, 0, 1]\n", "3:1", "mesh[0].clip[0] has no 'point'"));
  EXPECT_TRUE(failsAt(mesh + "[[mesh.clip]]\npoint = [0, 0, 0]\nnormal = [0, 0, 0]\n", "5:10",
                      "mesh[0].clip[0].normal must not be [0, 0, 0]"));
  EXPECT_TRUE(failsAt(mesh + "[[mesh.clip]]\npoint = [0, 0, 0]\nnormal = [0, 0, 1]\ncpa = true\n", "6:1",
                      "unknown key 'cpa' in mesh[0].clip[0] (did you mean 'cap'?)"));
  EXPECT_TRUE(
      failsAt(mesh + "[[mesh.clip]]\npoint = [0, 0]\nnormal = [0, 0, 1]\n", "4:9", "mesh[0].clip[0].point"));
  EXPECT_TRUE(failsAt(mesh + "[[mesh.clip]]\npoint = [0, 0, 0]\nnormal = [0, 0, 1]\ncap = \"yes\"\n", "6:7",
                      "mesh[0].clip[0].cap"));
  // The second mesh's second plane is named as such.
  EXPECT_TRUE(
      failsAt(mesh + mesh +
                  "[[mesh.clip]]\npoint = [0, 0, 0]\nnormal = [0, 0, 1]\n[[mesh.clip]]\npoint = [0, 0, 0]\n",
              "8:1", "mesh[1].clip[1] has no 'normal'"));
  EXPECT_TRUE(failsAt(mesh + "clip = 3\n", "3:8",
                      "mesh[0].clip must be an array of tables: write [[mesh.clip]] for each one, not"));
  EXPECT_TRUE(
      failsAt(mesh + "[mesh.clip]\npoint = [0, 0, 0]\n", "3:1",
              "mesh[0].clip must be an array of tables: write [[mesh.clip]] for each one, not [mesh.clip]"));
  EXPECT_TRUE(failsAt(mesh + "clip = [1]\n", "3:9", "mesh[0].clip[0] must be a table written [[mesh.clip]]"));
  EXPECT_TRUE(failsAt(mesh + "clp = []\n", "3:1", "unknown key 'clp' in mesh[0] (did you mean 'clip'?)"));
}

TEST(SceneLoaderBadInput, EdgesKeyIsCheckedLikeEveryOther) {
  EXPECT_TRUE(failsAt("[[mesh]]\nfile = \"a.msh\"\nedges = 3\n", "3:9",
                      "mesh[0].edges must be true, false or a table"));
  EXPECT_TRUE(failsAt("[[mesh]]\nfile = \"a.msh\"\nedges = { widht = 1.0 }\n", "3:11",
                      "unknown key 'widht' in mesh[0].edges (did you mean 'width'?)"));
  EXPECT_TRUE(failsAt("[[mesh]]\nfile = \"a.msh\"\nedges = { width = 0 }\n", "3:19", "mesh[0].edges.width"));
  EXPECT_TRUE(failsAt("[[mesh]]\nfile = \"a.msh\"\nedges = { only = \"feature\" }\n", "3:18",
                      "did you mean 'features'"));
}

TEST(SceneLoaderBadInput, ColorByIsChecked) {
  EXPECT_TRUE(failsAt("[[mesh]]\nfile = \"a.msh\"\ncolor_by = \"t\"\n", "3:12",
                      "mesh[0].color_by must be a table like { field = \"temperature\""));
  EXPECT_TRUE(failsAt("[[mesh]]\nfile = \"a.msh\"\ncolor_by = { field = \"t\", map = \"jte\" }\n", "3:33",
                      "mesh[0].color_by.map: \"jte\" is not a colour map (did you mean 'jet'?)"));
  EXPECT_TRUE(failsAt("[[mesh]]\nfile = \"a.msh\"\ncolor_by = { field = \"t\", rnage = [0, 1] }\n", "3:27",
                      "unknown key 'rnage' in mesh[0].color_by"));
}

TEST(SceneLoaderBadInput, UnknownAnimationKey) {
  EXPECT_TRUE(failsAt("[animation]\nspeed = 2\n", "2:1",
                      "unknown key 'speed' in [animation]; expected one of: frames"));
}

// ---- wrong types ---------------------------------------------------------------------------------------

TEST(SceneLoaderBadInput, StringWhereIntegerExpected) {
  EXPECT_EQ(sceneErrorOf("[render]\nwidth = \"800\"\n"),
            "scene.toml:2:9: error: render.width must be an integer, found string \"800\"");
}

TEST(SceneLoaderBadInput, FloatWhereIntegerExpected) {
  EXPECT_EQ(
      sceneErrorOf("[render]\nheight = 600.0\n"),
      "scene.toml:2:10: error: render.height must be an integer, found floating-point number 600; write it "
      "without a decimal point");
  EXPECT_TRUE(failsAt("[render]\nsamples = 4.5\n", "2:11",
                      "render.samples must be an integer, found floating-point number 4.5"));
}

TEST(SceneLoaderBadInput, SectionThatIsNotATable) {
  EXPECT_TRUE(failsAt("render = 5\n", "1:10", "render must be a table written [render], found integer 5"));
}

TEST(SceneLoaderBadInput, VectorComponentOfWrongType) {
  EXPECT_TRUE(failsAt("[camera]\nposition = [1, 2, \"3\"]\n", "2:19",
                      "camera.position[2] must be a number, found string \"3\""));
}

TEST(SceneLoaderBadInput, NumberWhereVectorExpected) {
  EXPECT_TRUE(failsAt("[camera]\nup = 1\n", "2:6",
                      "camera.up must be an array of 3 numbers [x, y, z], found integer 1"));
}

TEST(SceneLoaderBadInput, VectorOfWrongLength) {
  EXPECT_TRUE(failsAt("[ambient]\nintensity = [0.1, 0.1]\n", "2:13",
                      "ambient.intensity must be an array of 3 numbers [r, g, b], found array of 2 values"));
}

TEST(SceneLoaderBadInput, BooleanKeys) {
  EXPECT_TRUE(failsAt("[render]\nsrgb = \"yes\"\n", "2:8",
                      "render.srgb must be true or false, found string \"yes\""));
  EXPECT_TRUE(failsAt("[material.steel]\nfresnel = 1\n", "2:11",
                      "material.steel.fresnel must be true or false, found integer 1"));
}

TEST(SceneLoaderBadInput, OutputPath) {
  EXPECT_TRUE(failsAt("[render]\noutput = 5\n", "2:10", "render.output must be a string, found integer 5"));
  EXPECT_TRUE(failsAt("[render]\noutput = \"\"\n", "2:10", "render.output must not be empty"));
}

TEST(SceneLoaderBadInput, LightWrittenAsSingleTable) {
  EXPECT_TRUE(failsAt("[light]\nposition = [0, 0, 0]\n", "1:1",
                      "light must be an array of tables: write [[light]] for each one, not [light]"));
  EXPECT_TRUE(
      failsAt("light = [1, 2]\n", "1:10", "light[0] must be a table written [[light]], found integer 1"));
}

TEST(SceneLoaderBadInput, MeshWrittenAsSingleTable) {
  EXPECT_TRUE(failsAt("[mesh]\nfile = \"a.msh\"\n", "1:1", "write [[mesh]] for each one, not [mesh]"));
}

TEST(SceneLoaderBadInput, MeshFileNotAString) {
  EXPECT_TRUE(failsAt("[[mesh]]\nfile = 7\n", "2:8", "mesh[0].file must be a string, found integer 7"));
  EXPECT_TRUE(failsAt("[[mesh]]\nfile = \"\"\n", "2:8", "mesh[0].file must not be empty"));
}

TEST(SceneLoaderBadInput, MaterialKeysOutsideAMaterialTable) {
  EXPECT_TRUE(
      failsAt("[material]\nka = [0.2, 0.2, 0.2]\n", "2:6",
              "material.ka must be a table of material keys (ka, kd, ks, shininess, ...), found array of 3 "
              "values; each material is a section [material.NAME]"));
  EXPECT_TRUE(failsAt("material.steel = 5\n", "1:18", "material.steel must be a table of material keys"));
}

TEST(SceneLoaderBadInput, MaterialReferenceNotAString) {
  EXPECT_TRUE(failsAt("[[mesh]]\nfile = \"a.msh\"\nmaterial = 3\n", "3:12",
                      "mesh[0].material must be a material name (a string), found integer 3"));
  EXPECT_TRUE(failsAt("[[mesh]]\nfile = \"a.msh\"\ngroups = { Floor = 2 }\n", "3:20",
                      "mesh[0].groups.Floor must be a material name (a string), found integer 2"));
}

TEST(SceneLoaderBadInput, GroupsNotATable) {
  EXPECT_TRUE(failsAt(
      "[[mesh]]\nfile = \"a.msh\"\ngroups = \"Floor\"\n", "3:10",
      "mesh[0].groups must be a table of group = \"material\", e.g. { Floor = \"matte\", 7 = \"glass\" }, "
      "found string \"Floor\""));
}

// ---- choices among names -------------------------------------------------------------------------------

TEST(SceneLoaderBadInput, MisspeltShading) {
  EXPECT_EQ(
      sceneErrorOf("[render]\nshading = \"phnog\"\n"),
      "scene.toml:2:11: error: render.shading must be \"flat\", \"gouraud\", \"phong\" or \"unlit\", found "
      "\"phnog\" "
      "(did you mean 'phong'?)");
  EXPECT_TRUE(
      failsAt("[[mesh]]\nfile = \"a.msh\"\nshading = \"smooth\"\n", "3:11",
              "mesh[0].shading must be \"flat\", \"gouraud\", \"phong\" or \"unlit\", found \"smooth\""));
  EXPECT_TRUE(
      failsAt("[render]\nshading = 1\n", "2:11",
              "render.shading must be the string \"flat\", \"gouraud\", \"phong\" or \"unlit\", found "
              "integer 1"));
}

TEST(SceneLoaderBadInput, UnknownSampler) {
  EXPECT_TRUE(
      failsAt("[render]\nsampler = \"jittered\"\n", "2:11",
              "render.sampler must be \"regular\", \"stratified\" or \"adaptive\", found \"jittered\""));
}

TEST(SceneLoaderBadInput, UnknownProjection) {
  EXPECT_TRUE(failsAt("[camera]\nprojection = \"ortho\"\n", "2:14",
                      "camera.projection must be \"perspective\" or \"orthographic\", found \"ortho\""));
}

TEST(SceneLoaderBadInput, BackgroundWord) {
  EXPECT_TRUE(
      failsAt("[render]\nbackground = \"transparant\"\n", "2:14",
              "render.background must be [r, g, b] or \"transparent\", found \"transparant\" (did you mean "
              "'transparent'?)"));
  EXPECT_TRUE(failsAt("[render]\nbackground = 0\n", "2:14",
                      "render.background must be [r, g, b] or \"transparent\", found integer 0"));
}

// ---- values out of range -------------------------------------------------------------------------------

TEST(SceneLoaderBadInput, ImageSize) {
  EXPECT_TRUE(failsAt("[render]\nwidth = 0\n", "2:9", "render.width must be between 1 and 32768, found 0"));
  EXPECT_TRUE(failsAt("[render]\nheight = 40000\n", "2:10",
                      "render.height must be between 1 and 32768, found 40000"));
}

TEST(SceneLoaderBadInput, SampleCount) {
  EXPECT_TRUE(
      failsAt("[render]\nsamples = 2000\n", "2:11", "render.samples must be between 1 and 1024, found 2000"));
  EXPECT_TRUE(
      failsAt("[render]\nsamples = 0\n", "2:11", "render.samples must be between 1 and 1024, found 0"));
}

TEST(SceneLoaderBadInput, SamplesNotASquareForGridSamplers) {
  EXPECT_EQ(
      sceneErrorOf("[render]\nsamples = 8\n"),
      "scene.toml:2:11: error: render.samples must be a perfect square (an n x n sub-pixel grid) for "
      "the regular sampler, found 8; use 4 or 9, or the adaptive sampler, or the path or ao integrator");
  // The sampler may come after samples in the file: it is still taken into account.
  EXPECT_TRUE(failsAt("[render]\nsamples = 5\nsampler = \"stratified\"\n", "2:11",
                      "for the stratified sampler, found 5; use 4 or 9"));
}

TEST(SceneLoaderBadInput, MaxDepth) {
  EXPECT_TRUE(
      failsAt("[render]\nmax_depth = 65\n", "2:13", "render.max_depth must be between 0 and 64, found 65"));
  EXPECT_TRUE(
      failsAt("[render]\nmax_depth = -1\n", "2:13", "render.max_depth must be between 0 and 64, found -1"));
}

TEST(SceneLoaderBadInput, NegativeBackgroundComponent) {
  EXPECT_TRUE(failsAt("[render]\nbackground = [0, -0.5, 0]\n", "2:18",
                      "render.background[1] must be >= 0, found -0.5"));
}

TEST(SceneLoaderBadInput, FieldOfView) {
  EXPECT_TRUE(failsAt("[camera]\nfov = 180\n", "2:7",
                      "camera.fov must be greater than 0 and less than 180, found 180"));
  EXPECT_TRUE(
      failsAt("[camera]\nfov = 0\n", "2:7", "camera.fov must be greater than 0 and less than 180, found 0"));
  EXPECT_TRUE(failsAt("[camera]\nfov = nan\n", "2:7", "camera.fov must be a finite number, found nan"));
}

TEST(SceneLoaderBadInput, ViewHeight) {
  EXPECT_TRUE(failsAt("[camera]\nview_height = 0\n", "2:15", "camera.view_height must be > 0, found 0"));
}

TEST(SceneLoaderBadInput, NegativeIntensities) {
  EXPECT_TRUE(
      failsAt("[ambient]\nintensity = [0, 0, -1]\n", "2:20", "ambient.intensity[2] must be >= 0, found -1"));
  EXPECT_TRUE(failsAt("[[light]]\nposition = [0, 0, 0]\nintensity = [-1, 1, 1]\n", "3:14",
                      "light[0].intensity[0] must be >= 0, found -1"));
}

TEST(SceneLoaderBadInput, AttenuationThatDividesByZero) {
  EXPECT_TRUE(
      failsAt("[[light]]\nposition = [0, 0, 0]\nattenuation = [0, 0, 0]\n", "3:15",
              "light[0].attenuation must not be [0, 0, 0]: att(d) = 1 / (c + l d + q d^2) would divide by "
              "zero; use [1, 0, 0] for no attenuation"));
}

TEST(SceneLoaderBadInput, MaterialCoefficientAboveOne) {
  EXPECT_EQ(sceneErrorOf("[material.steel]\nka = [1.5, 0, 0]\n"),
            "scene.toml:2:7: error: material.steel.ka[0] must be between 0 and 1, found 1.5");
  EXPECT_TRUE(failsAt("[material.steel]\nks = [0, 0, 2]\n", "2:13",
                      "material.steel.ks[2] must be between 0 and 1, found 2"));
}

TEST(SceneLoaderBadInput, NegativeShininess) {
  EXPECT_TRUE(failsAt("[material.steel]\nshininess = -1\n", "2:13",
                      "material.steel.shininess must be >= 0, found -1"));
}

TEST(SceneLoaderBadInput, Reflectivity) {
  EXPECT_TRUE(failsAt("[material.glass]\nreflectivity = 1.5\n", "2:16",
                      "material.glass.reflectivity must be between 0 and 1, found 1.5"));
  EXPECT_TRUE(failsAt("[material.glass]\nreflectivity = [0, 1.1, 0]\n", "2:20",
                      "material.glass.reflectivity[1] must be between 0 and 1, found 1.1"));
  EXPECT_TRUE(
      failsAt("[material.glass]\nreflectivity = \"high\"\n", "2:16",
              "material.glass.reflectivity must be a number or an array of 3 numbers [r, g, b], found string "
              "\"high\""));
}

TEST(SceneLoaderBadInput, Transparency) {
  EXPECT_TRUE(failsAt("[material.glass]\ntransparency = -0.1\n", "2:16",
                      "material.glass.transparency must be between 0 and 1, found -0.1"));
}

TEST(SceneLoaderBadInput, IndexOfRefraction) {
  EXPECT_TRUE(failsAt("[material.glass]\nior = 0\n", "2:7", "material.glass.ior must be > 0, found 0"));
}

TEST(SceneLoaderBadInput, NegativeAbsorption) {
  EXPECT_TRUE(failsAt("[material.glass]\nabsorption = [0, 0, -2]\n", "2:21",
                      "material.glass.absorption[2] must be >= 0, found -2"));
}

TEST(SceneLoaderBadInput, SmoothAngle) {
  EXPECT_TRUE(failsAt("[[mesh]]\nfile = \"a.msh\"\nsmooth_angle = 200\n", "3:16",
                      "mesh[0].smooth_angle must be between 0 and 180, found 200"));
}

TEST(SceneLoaderBadInput, ZeroScale) {
  EXPECT_TRUE(
      failsAt("[[mesh]]\nfile = \"a.msh\"\nscale = 0\n", "3:9", "mesh[0].scale must be non-zero, found 0"));
  EXPECT_TRUE(failsAt("[[mesh]]\nfile = \"a.msh\"\nscale = [1, 0, 1]\n", "3:13",
                      "mesh[0].scale[1] must be non-zero, found 0"));
  EXPECT_TRUE(
      failsAt("[[mesh]]\nfile = \"a.msh\"\nscale = [1, 1]\n", "3:9",
              "mesh[0].scale must be a number or an array of 3 numbers [x, y, z], found array of 2 values"));
}

TEST(SceneLoaderBadInput, AnimationFrames) {
  EXPECT_TRUE(
      failsAt("[animation]\nframes = 0\n", "2:10", "animation.frames must be between 1 and 10000, found 0"));
  EXPECT_TRUE(failsAt("[animation]\nframes = 10001\n", "2:10",
                      "animation.frames must be between 1 and 10000, found 10001"));
}

TEST(SceneLoaderBadInput, AnimationFps) {
  EXPECT_TRUE(failsAt("[animation]\nfps = 0\n", "2:7",
                      "animation.fps must be a number of frames per second between 0.01 and 100, found 0"));
}

TEST(SceneLoaderBadInput, AnimationDegreesNotFinite) {
  EXPECT_TRUE(failsAt("[animation]\ndegrees = inf\n", "2:11",
                      "animation.degrees must be a finite number, found inf"));
}

TEST(SceneLoaderBadInput, AnimationZeroAxis) {
  EXPECT_TRUE(
      failsAt("[animation]\naxis = [0, 0, 0]\n", "2:8",
              "animation.axis must not be [0, 0, 0]; give the direction to orbit about, e.g. [0, 1, 0]"));
}

// ---- camera geometry -----------------------------------------------------------------------------------

TEST(SceneLoaderBadInput, UpParallelToViewDirection) {
  EXPECT_EQ(
      sceneErrorOf("[camera]\nposition = [0, 5, 0]\nlook_at = [0, 0, 0]\nup = [0, 2, 0]\n"),
      "scene.toml:4:6: error: camera.up [0, 2, 0] is parallel to the view direction (look_at - position = "
      "[0, -5, 0]); choose an up across the line of sight, e.g. up = [0, 0, 1]");
}

TEST(SceneLoaderBadInput, ZeroUp) {
  EXPECT_TRUE(
      failsAt("[camera]\nup = [0, 0, 0]\n", "2:6", "camera.up must not be [0, 0, 0]; use e.g. [0, 1, 0]"));
}

TEST(SceneLoaderBadInput, LookAtEqualsPosition) {
  EXPECT_TRUE(
      failsAt("[camera]\nposition = [1, 2, 3]\nlook_at = [1, 2, 3]\n", "3:11",
              "camera.look_at is the same point as camera.position [1, 2, 3]; the camera needs a direction "
              "to look in"));
}

// ---- missing required keys -----------------------------------------------------------------------------

TEST(SceneLoaderBadInput, LightWithoutPosition) {
  EXPECT_EQ(sceneErrorOf("[[light]]\nintensity = [1, 1, 1]\n"),
            "scene.toml:1:1: error: light[0] has no 'position'; add position = [x, y, z]");
}

TEST(SceneLoaderBadInput, MeshWithoutFile) {
  EXPECT_TRUE(failsAt("[[mesh]]\nfile = \"a.msh\"\n\n[[mesh]]\nmaterial = \"default\"\n", "4:1",
                      "mesh[1] has no 'file'; add file = \"part.msh\""));
}

// ---- material names ------------------------------------------------------------------------------------

TEST(SceneLoaderBadInput, UnknownMeshMaterialSuggestsTheClosest) {
  EXPECT_EQ(
      sceneErrorOf("[material.steel]\n[[mesh]]\nfile = \"a.msh\"\nmaterial = \"stel\"\n"),
      "scene.toml:4:12: error: mesh[0].material names material 'stel', which is not defined (did you mean "
      "'steel'?); defined materials: default, steel");
}

TEST(SceneLoaderBadInput, UnknownGroupMaterial) {
  EXPECT_TRUE(failsAt(
      "[material.matte]\n[[mesh]]\nfile = \"a.msh\"\ngroups = { Floor = \"glass\" }\n", "4:20",
      "mesh[0].groups.Floor names material 'glass', which is not defined; defined materials: default, "
      "matte"));
}

TEST(SceneLoaderBadInput, EmptyGroupName) {
  EXPECT_TRUE(failsAt("[[mesh]]\nfile = \"a.msh\"\ngroups = { \"\" = \"default\" }\n", "3:12",
                      "mesh[0].groups has an empty group name"));
}

// ---- animation orbit -----------------------------------------------------------------------------------

TEST(SceneLoaderBadInput, OrbitLightOutOfRange) {
  EXPECT_EQ(
      sceneErrorOf("[[light]]\nposition = [0, 0, 0]\n[animation]\norbit = \"light:1\"\n"),
      "scene.toml:4:9: error: animation.orbit names light 1, but the scene has 1 light (use \"light:0\")");
  EXPECT_TRUE(failsAt(
      "[[light]]\nposition = [0, 0, 0]\n[[light]]\nposition = [1, 0, 0]\n[animation]\norbit = \"light:2\"\n",
      "6:9", "animation.orbit names light 2, but the scene has 2 lights (light:0 to light:1)"));
  EXPECT_TRUE(failsAt("[animation]\norbit = \"light:0\"\n", "2:9",
                      "animation.orbit names light 0, but the scene has no [[light]]"));
}

TEST(SceneLoaderBadInput, OrbitNotCameraOrLight) {
  for (const char* orbit : {"lights:0", "light:-1", "light:", "light:1x", "light: 1", "light:+1",
                            "light:99999999999", "Camera"}) {
    SCOPED_TRACE(orbit);
    EXPECT_TRUE(failsAt(
        "[[light]]\nposition = [0, 0, 0]\n[animation]\norbit = \"" + std::string(orbit) + "\"\n", "4:9",
        "animation.orbit must be \"camera\" or \"light:K\" (K the index of a [[light]], from 0), "
        "found \"" +
            std::string(orbit) + "\""));
  }
  EXPECT_TRUE(
      failsAt("[animation]\norbit = 0\n", "2:9", "animation.orbit must be a string, found integer 0"));
}

}  // namespace
}  // namespace lancer
