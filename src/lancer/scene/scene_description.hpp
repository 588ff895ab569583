// What a scene file says, checked and with defaults filled in, before any mesh is loaded:
// render settings, camera, lights, materials and the mesh instances that use them.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "lancer/image/image_metadata.hpp"
#include "lancer/image/tone_map.hpp"
#include "lancer/math/vec3.hpp"
#include "lancer/scene/results/annotation_spec.hpp"
#include "lancer/scene/results/color_by_spec.hpp"
#include "lancer/scene/results/gmsh_view.hpp"
#include "lancer/scene/results/volume_view_spec.hpp"
#include "lancer/util/input_error.hpp"

namespace lancer {

struct VolumeMesh;  // mesh/volume/volume_mesh.hpp

enum class Projection { Perspective, Orthographic };
// flat, gouraud, phong: the lighting model (docs/rendering.md); unlit: the material's diffuse colour
// or the field's colour as it is, no lights, no shadows (a colour map that reads as its legend).
// One byte: the scene keeps one per face (Scene::appearance.faceShading).
enum class ShadingMode : std::uint8_t { Flat, Gouraud, Phong, Unlit };
enum class SamplerKind { Regular, Stratified, Adaptive };
// How light is carried (docs/lighting.md): the classic Whitted model, unidirectional path tracing,
// or ambient occlusion.
enum class IntegratorKind { Whitted, Path, AmbientOcclusion };

struct RenderSettings {
  int width = 800;
  int height = 600;
  int samples = 1;   // samples per pixel, a perfect square for the regular grid
  int maxDepth = 5;  // reflection/refraction recursion depth
  IntegratorKind integrator = IntegratorKind::Whitted;
  int maxBounces = 8;  // path: scattering events after the camera ray
  float noise = 0;     // path, ao: stop a pixel once its relative standard error is below this (0: off)
  // path, ao: sample in rounds, more where the standard error of the displayed value (a fraction of
  // white) is above this, up to `samples` (0: off; when on, `noise` is not used). docs/lighting.md.
  float adaptiveNoise = 0;
  float aoDistance = 0;  // ao: occluders farther than this do not count (0: a tenth of the scene's size)
  SamplerKind sampler = SamplerKind::Regular;
  // Adaptive sampler: a square of the pixel is split when two of its corner samples differ by more
  // than this in some channel (linear radiance, 1 = full scale).
  float adaptiveThreshold = 0.05f;
  ShadingMode shading = ShadingMode::Phong;
  Vec3 background{0, 0, 0};
  bool transparentBackground = false;  // background = "transparent": PNG with alpha
  std::string output;                  // resolved against the scene file's folder; may be empty
  // How the radiance becomes a picture (docs/output.md): `encoding = "srgb"` (the default) or
  // "linear" (the raw values, round(255 * clamp(I, 0, 1))), after `exposure` (stops) and
  // `tonemap`; 8 or 16 bits per sample (16: PNG only); `denoise` filters the radiance first.
  bool srgb = true;
  ToneMap toneMap = ToneMap::None;
  float exposure = 0;
  int bitDepth = 8;
  bool denoise = false;
  // JPEG and lossy WebP quality (1 to 100); WebP lossless instead; the DPI written into the file (0: none).
  int quality = kDefaultImageQuality;
  bool lossless = false;
  double dpi = 0;
};

struct CameraSettings {
  Projection projection = Projection::Perspective;
  // When the scene gives no position, the renderer frames the scene's bounding box from a 3/4 view.
  std::optional<Vec3d> position;
  std::optional<Vec3d> lookAt;  // default: centre of the scene's bounding box
  Vec3d up{0, 1, 0};
  // Without a position, the camera looks at the scene from this direction (any length): the 3/4 view
  // from the right, above and in front for y up. `up_axis` and `--up` turn it with `up`.
  Vec3d viewFrom{0.9, 0.65, 1.3};
  double fovDegrees = 40;            // vertical, perspective
  std::optional<double> viewHeight;  // world units, orthographic; default frames the scene
  // The view window's centre off the view axis: in tan units for a perspective camera (gmsh's
  // perspective), in world units for an orthographic one.
  double shiftX = 0, shiftY = 0;
  // Set when the scene or the caller chose the view (`position`, `up`, `up_axis`, `projection`,
  // `--up`, a Python Camera): the automatic camera then keeps the direction and projection given.
  // Otherwise a flat scene is seen straight on, orthographic, filling the picture (frameFlatScene).
  bool viewChosen = false;
  // The automatic camera fits the scene's bounding box as seen along the view (a flat scene
  // straight on) instead of its bounding sphere.
  bool fitBox = false;
  // `--zoom`: the camera this many times closer to its target (an orthographic window this many times
  // smaller), applied when the camera is placed (placeAutomaticCamera); a placed camera moves along
  // its line of sight towards its look_at (default the scene's centre).
  double zoom = 1;
  // The share of the image's width at the right and of its height at the bottom that the legends
  // take: the automatic camera frames the scene in the rest (a placed camera ignores them).
  double legendShareRight = 0, legendShareBottom = 0;
  // `[camera] gmsh_view`, `--gmsh-view`: the view of a gmsh options file, resolved against the scene's
  // bounds when the camera is made (resolveGmshView); it replaces every key above.
  std::optional<GmshView> gmshView;
};

// The camera settings of `camera.gmshView` for a scene of these world bounds and an image
// `imageAspect` (width / height) wide, framed as gmsh frames its export (camera itself without one).
CameraSettings resolveGmshView(const CameraSettings& camera, const Aabbd& worldBounds, double imageAspect);

// `type` of a [[light]]: a point, the sun (a direction and an angular diameter), or a light with
// area (a sphere, a rectangle or a disk). The Whitted model lights with each one's centre.
enum class LightType { Point, Sun, Sphere, Rect, Disk };

struct PointLight {
  Vec3d position;  // point and area lights (the centre)
  Vec3 intensity{1, 1, 1};
  Vec3 attenuation{1, 0, 0};  // constant, linear, quadratic: att(d) = 1 / (c + l d + q d^2)
  LightType type = LightType::Point;
  Vec3d direction{0, 1, 0};      // sun: unit, from the scene towards the sun; rect, disk: the side lit
                                 // ([0, 0, 0]: towards the scene's centre)
  double angleDegrees = 0.53;    // sun: angular diameter
  double radius = 0;             // sphere, disk
  double width = 0, height = 0;  // rect
  SourceLocation where{};
};

// `[environment]`: the light that comes from every direction (the path and AO integrators; the
// Whitted model keeps its [ambient]). A uniform colour, a sky graded from the ground through the
// horizon to the zenith, or an equirectangular map (a Radiance .hdr file), radiance in all cases.
struct EnvironmentSettings {
  enum class Kind { Uniform, Gradient, Map } kind = Kind::Uniform;
  Vec3 color{1, 1, 1};
  Vec3 zenith{0.35f, 0.5f, 0.8f}, horizon{0.85f, 0.88f, 0.92f}, ground{0.3f, 0.28f, 0.25f};
  std::string map;             // resolved against the scene file's folder
  double rotationDegrees = 0;  // about the up axis
  float strength = 1;          // multiplies the map
  bool visible = false;        // camera rays that miss show the environment (else the background)
  SourceLocation where{};      // of the map key (else the table), for errors reading the file
};

struct Material {
  std::string name;
  Vec3 ka{0.2f, 0.2f, 0.2f};
  Vec3 kd{0.7f, 0.7f, 0.7f};
  Vec3 ks{0.3f, 0.3f, 0.3f};
  float shininess = 32;
  Vec3 reflectivity{0, 0, 0};
  float transparency = 0;
  float ior = 1.5f;
  bool fresnel = false;
  Vec3 absorption{0, 0, 0};  // Beer-Lambert, per unit length inside transparent media
  Vec3 emission{0, 0, 0};    // path: radiance the faces send out (lamps); 0 elsewhere
};

// `groups = { Floor = "matte", 7 = "glass" }`: a physical group, by name or tag, and its material.
struct GroupMaterial {
  std::string group;  // name, or the tag written as decimal digits
  int material = 0;   // index into SceneDescription::materials
  SourceLocation where{};
};

// `edges = { width = 1.0, color = [0, 0, 0], only = "features", feature_angle = 30 }`: element
// edges drawn over the shaded surface, `width` pixels wide wherever they are seen.
struct EdgeSettings {
  float widthPixels = 1;
  Vec3 color{0, 0, 0};
  bool featuresOnly = false;       // only boundaries, group borders and creases
  float featureAngleDegrees = 30;  // crease angle for featuresOnly
};

// `[[clip]] point = [..], normal = [..], cap = true`: geometry on the side the normal points to is
// removed for every ray; with `cap`, closed shells cut by the plane show a flat face there. Scene
// coordinates, also for a mesh's own planes (`[[mesh.clip]]`, which remove only that mesh's faces).
struct ClipSettings {
  Vec3d point{0, 0, 0};
  Vec3d normal{1, 0, 0};  // unit
  bool cap = true;
};

// `warp = { field = "displacement", factor = 2.0 }`: every node moved by factor times its vector (a
// node view of 3 components) at the step shown; the deformed shape is what is drawn, lit and cut.
struct WarpSettings {
  std::string field;
  double factor = 1;
  SourceLocation where;  // the warp value, for errors found when the mesh is loaded
};

// `undeformed = "edges" | "ghost"`: the mesh's shape before the warp, drawn too: its feature edges
// on an invisible surface, or a faint transparent copy.
enum class UndeformedStyle { None, Edges, Ghost };

struct MeshInstance {
  std::string file;      // resolved against the scene file's folder
  SourceLocation where;  // of the [[mesh]] table, for errors found when the mesh is loaded
  // `views = ["az.pos"]`: list-based .pos views put on the mesh by their elements' coordinates
  // (mesh/pos/pos_on_mesh.hpp), resolved against the scene file's folder.
  std::vector<std::string> views;
  int material = 0;  // index into SceneDescription::materials
  std::optional<ShadingMode> shading;
  float smoothAngleDegrees = 60;
  std::optional<ColorBy> colorBy;  // colour the surface by a field of the mesh file
  std::optional<IsolineSpec> isolines;
  // Annotations that are meshes of their own (arrows), at most one of each kind
  // (results/annotation_kinds.hpp).
  std::vector<AnnotationSpec> annotations;
  Vec3d translate{0, 0, 0};
  Vec3d rotateDegrees{0, 0, 0};  // about x, then y, then z
  Vec3d scale{1, 1, 1};
  std::vector<GroupMaterial> groupMaterials;
  std::optional<EdgeSettings> edges;
  std::vector<ClipSettings> clips;  // [[mesh.clip]]: planes that cut this mesh only
  std::optional<WarpSettings> warp;
  UndeformedStyle undeformed = UndeformedStyle::None;
  VolumeViews volume;  // slices, isosurfaces (results/volume_view_spec.hpp)
  // Set on an isosurface's or field lines' mesh that follows the steps of its field.
  std::shared_ptr<const VolumeViewSource> volumeSource;
  // Set on the field lines of a flat 2D mesh: they stand off its plane by their radius, which the
  // test for a flat scene (flat_scene.hpp) overlooks.
  bool liesOnPlane = false;
  // The mesh's volume elements, for annotations that sample them (arrows on a grid): set where the
  // volume is read (attachAnnotationVolumes), shared with the slices and caps cut from it.
  std::shared_ptr<const VolumeMesh> annotationVolume;
};

// Where `[animation] label` goes in each frame.
enum class LabelPosition { TopLeft, TopRight, BottomLeft, BottomRight };

struct AnimationSettings {
  int frames = 36;
  double fps = 12;
  int orbitLight = -1;          // -1: the camera orbits; k >= 0: light k orbits
  std::optional<Vec3d> axis;    // default: the camera's up (a turntable about the up axis)
  std::optional<Vec3d> center;  // default: centre of the scene's bounding box
  double degrees = 360;
  // `over = "steps"`: the frames run through the results' time steps (the orbit turns at the same
  // time, when `degrees` is not 0); `frames` then samples the time span evenly, blending steps.
  bool overSteps = false;
  bool framesGiven = false;   // `frames` set (else one frame per step when over = "steps")
  bool degreesGiven = false;  // `degrees` set (else an animation over steps does not turn)
  bool perStepRange = false;  // `range = "step"`: each frame's colours span its own step
  std::string label;          // e.g. "t = {time:.3g} s": drawn into each frame ({time}, {step})
  LabelPosition labelPosition = LabelPosition::TopLeft;
};

// `[floor] shadow_catcher = true`: an infinite plane that is never drawn itself but darkens the
// picture where the meshes shadow it, so a part casts its shadow on the page (or, with a
// transparent background, on whatever the figure is placed over).
struct FloorSettings {
  std::optional<double> height;  // along `normal`; default: the scene's lowest point
  Vec3d normal{0, 1, 0};         // unit, pointing up
};

struct SceneDescription {
  std::string path;  // the scene file, for messages
  RenderSettings render;
  CameraSettings camera;
  Vec3 ambient{0.1f, 0.1f, 0.1f};
  std::vector<PointLight> lights;
  std::optional<EnvironmentSettings> environment;
  bool ambientSet = false;          // the file sets [ambient] or some material's ka (the path warning)
  std::vector<Material> materials;  // materials[0] is always present: "default" when none is named
  std::vector<MeshInstance> meshes;
  std::vector<ClipSettings> clips;
  std::optional<FloorSettings> floor;
  std::optional<AnimationSettings> animation;
  // The moment of the results shown (`[render] step`, `--step`; an animation over steps sets the
  // time of each frame): the colours and the warp of every mesh at that step or time.
  StepSelection when;
  // The quick look's key and fill are placed for the automatic camera: an animation turns them with
  // the camera, so every frame is lit the same way.
  bool lightsFollowCamera = false;
  // The quick look's mesh's face bounds in world space, which its lights are placed from: kept, so
  // that placing them again (another image size, a placed camera) needs no pass over the faces.
  std::optional<Aabbd> quickLookBounds;
  // For the user, with the meshes' warnings (Scene::warnings): what a front end read and does not
  // apply, as "file:line: warning: ...".
  std::vector<std::string> notes;
};

}  // namespace lancer
