"""Renders a lancer scene file with Blender Cycles, in lancer's units, for bench/cycles_compare.sh and the
committed Cycles reference of tests/render/cycles_reference_test.cpp (a development tool: lancer
never needs Blender to build, test or run).

  blender -b --factory-startup --python bench/cycles_scene.py -- SCENE.toml -o OUT.exr \
      [--samples N] [--seed S] [--threads 2] [--width W --height H]

Reads the scene file itself (tomllib) and accepts only what it can reproduce exactly; anything else is
an error, never a silently different picture:
  [render]      width, height, samples, max_bounces, shading = "flat", integrator = "path"
  [camera]      perspective: position, look_at, up or up_axis, fov (vertical, degrees)
  [[light]]     type = "sun": direction, angle (angular diameter, degrees), intensity
  [environment] color, or zenith/horizon/ground; strength; visible = true
  [material.X]  kd (ks zero): a Lambertian face
  [[mesh]]      file (a gmsh .msh, no transforms), material
Units (docs/lighting.md): a lancer sun of intensity I gives irradiance pi I cos(theta); Cycles' sun
strength is irradiance (W/m^2), so its strength is pi I. An environment of radiance L is a world
background of colour L, strength 1. Cycles' diffuse BSDF is albedo / pi, as lancer's. lancer's
max_bounces counts scattering events after the camera ray (1: direct light only), Cycles' bounces
those after the first hit (0: direct light only), so Cycles gets max_bounces - 1.
Set for an unbiased match: box pixel filter of 1 pixel (lancer's), no clamping, no glossy blur, no
light threshold, no adaptive sampling, no denoising, Standard view transform, film not transparent,
32-bit float linear EXR. The meshes go through gmsh (`gmsh F.msh -save -format msh22`) and a cache
of numpy arrays ($LANCER_CYCLES_CACHE, default /tmp/lancer_cycles_cache).
"""

import argparse
import math
import os
import subprocess
import sys
import time
import tomllib

import bpy
import numpy as np
from mathutils import Matrix, Vector

ALLOWED = {
    "render": {"width", "height", "samples", "max_bounces", "shading", "integrator", "output"},
    "camera": {"position", "look_at", "up", "up_axis", "fov", "projection"},
    "light": {"type", "direction", "angle", "intensity"},
    "environment": {"color", "zenith", "horizon", "ground", "strength", "visible"},
    "material": {"kd", "ks", "ka"},
    "mesh": {"file", "material"},
}
AXES = {"x": (1, 0, 0), "y": (0, 1, 0), "z": (0, 0, 1), "-x": (-1, 0, 0), "-y": (0, -1, 0), "-z": (0, 0, -1)}


def fail(message):
    print(f"cycles_scene.py: error: {message}", file=sys.stderr)
    sys.exit(2)


def check_keys(table, kind, where):
    unknown = set(table) - ALLOWED[kind]
    if unknown:
        fail(f"{where}: {sorted(unknown)} cannot be reproduced in Cycles by this script")


def parse_args():
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    parser = argparse.ArgumentParser(prog="cycles_scene.py")
    parser.add_argument("scene")
    parser.add_argument("-o", "--output", required=True)
    parser.add_argument("--samples", type=int)
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--threads", type=int, default=2)
    parser.add_argument("--width", type=int)
    parser.add_argument("--height", type=int)
    return parser.parse_args(argv)


# ---- gmsh meshes -------------------------------------------------------------------------------

def read_msh22(path):
    """Faces (triangles; quads split along their first diagonal) of an ASCII MSH 2.2 file."""
    with open(path) as f:
        lines = f.read().split("\n")
    i = 0
    nodes = elements = None
    while i < len(lines):
        if lines[i] == "$Nodes":
            count = int(lines[i + 1])
            block = np.array(" ".join(lines[i + 2:i + 2 + count]).split(), dtype=np.float64).reshape(count, 4)
            nodes = block
            i += 2 + count
        elif lines[i] == "$Elements":
            count = int(lines[i + 1])
            elements = lines[i + 2:i + 2 + count]
            i += 2 + count
        else:
            i += 1
    if nodes is None or elements is None:
        fail(f"{path}: no $Nodes or $Elements (is it MSH 2.2 ASCII?)")
    index = {int(n): k for k, n in enumerate(nodes[:, 0])}
    corners = {2: 3, 9: 3, 3: 4, 10: 4, 16: 4}  # triangles and quads, first-order corners first
    tris = []
    for line in elements:
        fields = line.split()
        kind = int(fields[1])
        if kind not in corners:
            continue
        ids = [index[int(v)] for v in fields[3 + int(fields[2]):][:corners[kind]]]
        tris.append(ids[:3])
        if len(ids) == 4:
            tris.append([ids[0], ids[2], ids[3]])
    return nodes[:, 1:4], np.array(tris, dtype=np.int32)


def load_mesh(path):
    cache = os.environ.get("LANCER_CYCLES_CACHE", "/tmp/lancer_cycles_cache")
    os.makedirs(cache, exist_ok=True)
    stat = os.stat(path)
    key = f"{os.path.basename(path)}-{stat.st_size}-{int(stat.st_mtime)}"
    npz = os.path.join(cache, key + ".npz")
    if not os.path.exists(npz):
        ascii_msh = os.path.join(cache, key + ".msh")
        subprocess.run(["gmsh", path, "-save", "-format", "msh22", "-o", ascii_msh], check=True,
                       stdout=subprocess.DEVNULL)
        positions, triangles = read_msh22(ascii_msh)
        os.remove(ascii_msh)
        np.savez(npz, positions=positions, triangles=triangles)
    data = np.load(npz)
    return data["positions"], data["triangles"]


def mesh_object(name, positions, triangles, material):
    mesh = bpy.data.meshes.new(name)
    mesh.vertices.add(len(positions))
    mesh.vertices.foreach_set("co", positions.astype(np.float32).ravel())
    mesh.loops.add(3 * len(triangles))
    mesh.loops.foreach_set("vertex_index", triangles.ravel())
    mesh.polygons.add(len(triangles))
    mesh.polygons.foreach_set("loop_start", np.arange(0, 3 * len(triangles), 3, dtype=np.int32))
    mesh.polygons.foreach_set("loop_total", np.full(len(triangles), 3, dtype=np.int32))
    mesh.polygons.foreach_set("use_smooth", np.zeros(len(triangles), dtype=bool))  # flat shading
    mesh.update()
    mesh.materials.append(material)
    obj = bpy.data.objects.new(name, mesh)
    bpy.context.scene.collection.objects.link(obj)
    return obj


# ---- scene --------------------------------------------------------------------------------------

def diffuse_material(name, kd):
    material = bpy.data.materials.new(name)
    material.use_nodes = True
    nodes = material.node_tree.nodes
    nodes.clear()
    bsdf = nodes.new("ShaderNodeBsdfDiffuse")
    bsdf.inputs["Color"].default_value = (*kd, 1.0)
    bsdf.inputs["Roughness"].default_value = 0.0  # Lambert
    out = nodes.new("ShaderNodeOutputMaterial")
    material.node_tree.links.new(bsdf.outputs["BSDF"], out.inputs["Surface"])
    return material


def world_from(environment, up):
    world = bpy.data.worlds.new("lancer")
    world.use_nodes = True
    nodes, links = world.node_tree.nodes, world.node_tree.links
    nodes.clear()
    background = nodes.new("ShaderNodeBackground")
    background.inputs["Strength"].default_value = float(environment.get("strength", 1.0)) if environment else 0.0
    out = nodes.new("ShaderNodeOutputWorld")
    links.new(background.outputs["Background"], out.inputs["Surface"])
    if not environment:
        background.inputs["Color"].default_value = (0, 0, 0, 1)
        return world
    if environment.get("visible") is not True:
        fail("[environment] visible must be true (Cycles' camera sees the world)")
    if "color" in environment:
        background.inputs["Color"].default_value = (*environment["color"], 1.0)
        return world
    # lancer's gradient sky (render/environment_light.cpp): h = dot(direction, up); below the horizon
    # the ground colour, above it horizon (1 - h) + zenith h. The world's Generated coordinate is the
    # ray's direction.
    coords = nodes.new("ShaderNodeTexCoord")
    height = nodes.new("ShaderNodeVectorMath")
    height.operation = "DOT_PRODUCT"
    height.inputs[1].default_value = up
    links.new(coords.outputs["Generated"], height.inputs[0])
    sky = nodes.new("ShaderNodeMixRGB")
    sky.use_clamp = False
    sky.inputs["Color1"].default_value = (*environment["horizon"], 1.0)
    sky.inputs["Color2"].default_value = (*environment["zenith"], 1.0)
    links.new(height.outputs["Value"], sky.inputs["Fac"])
    above = nodes.new("ShaderNodeMath")
    above.operation = "GREATER_THAN"
    above.inputs[1].default_value = 0.0
    links.new(height.outputs["Value"], above.inputs[0])
    pick = nodes.new("ShaderNodeMixRGB")
    pick.inputs["Color1"].default_value = (*environment["ground"], 1.0)
    links.new(above.outputs["Value"], pick.inputs["Fac"])
    links.new(sky.outputs["Color"], pick.inputs["Color2"])
    links.new(pick.outputs["Color"], background.inputs["Color"])
    return world


def add_sun(light, index):
    if light.get("type", "point") != "sun":
        fail(f"[[light]] {index}: only suns are reproduced (type = \"sun\")")
    intensity = light.get("intensity", [1.0, 1.0, 1.0])
    peak = max(intensity)
    data = bpy.data.lights.new(f"sun{index}", "SUN")
    data.color = [c / peak for c in intensity] if peak > 0 else (0, 0, 0)
    data.energy = math.pi * peak  # irradiance: lancer's pi I
    data.angle = math.radians(light.get("angle", 0.53))  # angular diameter, both
    data.cycles.cast_shadow = True
    data.cycles.use_multiple_importance_sampling = True
    obj = bpy.data.objects.new(f"sun{index}", data)
    # A Blender sun shines along its -Z: its +Z points at the sun, lancer's `direction`.
    obj.rotation_mode = "QUATERNION"
    obj.rotation_quaternion = Vector(light["direction"]).normalized().to_track_quat("Z", "Y")
    bpy.context.scene.collection.objects.link(obj)


def add_camera(camera, scene_size):
    if camera.get("projection", "perspective") != "perspective":
        fail("[camera] only the perspective projection is reproduced")
    up = Vector(camera["up"]) if "up" in camera else Vector(AXES[camera.get("up_axis", "y")])
    position, look_at = Vector(camera["position"]), Vector(camera["look_at"])
    forward = (look_at - position).normalized()
    right = forward.cross(up).normalized()
    true_up = right.cross(forward)
    data = bpy.data.cameras.new("camera")
    data.type = "PERSP"
    data.sensor_fit = "VERTICAL"  # lancer's fov is vertical
    data.sensor_height = 24.0
    data.lens = 0.5 * data.sensor_height / math.tan(0.5 * math.radians(camera.get("fov", 40)))
    data.clip_start = 1e-4 * scene_size
    data.clip_end = 1e3 * scene_size
    obj = bpy.data.objects.new("camera", data)
    rotation = Matrix((right, true_up, -forward)).transposed()  # columns: camera x, y, z
    obj.matrix_world = Matrix.Translation(position) @ rotation.to_4x4()
    bpy.context.scene.collection.objects.link(obj)
    bpy.context.scene.camera = obj
    return tuple(up.normalized())


def configure(scene, render, args):
    scene.render.engine = "CYCLES"
    c = scene.cycles
    c.device = "CPU"
    c.samples = args.samples or render.get("samples", 64)
    c.seed = args.seed
    c.use_adaptive_sampling = False
    c.use_denoising = False
    c.time_limit = 0
    bounces = render.get("max_bounces", 8) - 1
    if bounces < 0:
        fail("[render] max_bounces = 0 (emission only) is not reproduced")
    c.max_bounces = c.diffuse_bounces = c.glossy_bounces = c.transmission_bounces = bounces
    c.transparent_max_bounces = bounces
    c.volume_bounces = 0
    c.sample_clamp_direct = 0.0
    c.sample_clamp_indirect = 0.0
    c.blur_glossy = 0.0
    c.caustics_reflective = c.caustics_refractive = True
    c.light_sampling_threshold = 0.0
    c.pixel_filter_type = "BOX"
    c.filter_width = 1.0
    scene.view_layers[0].cycles.use_denoising = False
    scene.render.film_transparent = False
    scene.render.use_motion_blur = False
    scene.render.threads_mode = "FIXED"
    scene.render.threads = args.threads
    scene.render.resolution_x = args.width or render.get("width", 800)
    scene.render.resolution_y = args.height or render.get("height", 600)
    scene.render.resolution_percentage = 100
    scene.render.pixel_aspect_x = scene.render.pixel_aspect_y = 1.0
    scene.view_settings.view_transform = "Standard"
    scene.view_settings.look = "None"
    scene.view_settings.exposure = 0.0
    scene.view_settings.gamma = 1.0
    settings = scene.render.image_settings
    settings.file_format = "OPEN_EXR"
    settings.color_depth = "32"
    settings.color_mode = "RGBA"
    settings.exr_codec = "ZIP"


def main():
    start = time.time()
    args = parse_args()
    with open(args.scene, "rb") as f:
        description = tomllib.load(f)
    folder = os.path.dirname(os.path.abspath(args.scene))
    for table in description:
        if table not in ("render", "camera", "light", "environment", "material", "mesh"):
            fail(f"{args.scene}: [{table}] cannot be reproduced in Cycles by this script")
    render = description.get("render", {})
    check_keys(render, "render", "[render]")
    if render.get("shading", "phong") != "flat" or render.get("integrator", "whitted") != "path":
        fail('[render] needs shading = "flat" and integrator = "path"')

    bpy.ops.wm.read_factory_settings(use_empty=True)
    scene = bpy.context.scene
    configure(scene, render, args)

    materials = {}
    for name, table in description.get("material", {}).items():
        check_keys(table, "material", f"[material.{name}]")
        if any(v != 0 for v in table.get("ks", [0, 0, 0])):
            fail(f"[material.{name}] ks must be zero (diffuse only)")
        materials[name] = diffuse_material(name, table.get("kd", [0.8, 0.8, 0.8]))
    low, high = np.full(3, np.inf), np.full(3, -np.inf)
    for index, mesh in enumerate(description.get("mesh", [])):
        check_keys(mesh, "mesh", f"[[mesh]] {index}")
        positions, triangles = load_mesh(os.path.join(folder, mesh["file"]))
        low, high = np.minimum(low, positions.min(axis=0)), np.maximum(high, positions.max(axis=0))
        mesh_object(f"mesh{index}", positions, triangles, materials[mesh.get("material", "default")])
    for index, light in enumerate(description.get("light", [])):
        check_keys(light, "light", f"[[light]] {index}")
        add_sun(light, index)
    camera = description.get("camera", {})
    check_keys(camera, "camera", "[camera]")
    up = add_camera(camera, float(np.linalg.norm(high - low)))
    environment = description.get("environment")
    if environment is not None:
        check_keys(environment, "environment", "[environment]")
    scene.world = world_from(environment, up)

    ready = time.time()
    bpy.ops.render.render()
    rendered = time.time()
    bpy.data.images["Render Result"].save_render(filepath=os.path.abspath(args.output), scene=scene)
    print(f"cycles_scene.py: {args.output}: {scene.render.resolution_x}x{scene.render.resolution_y}, "
          f"{scene.cycles.samples} samples, seed {args.seed}, {args.threads} threads; "
          f"set-up {ready - start:.2f} s, render {rendered - ready:.2f} s, write {time.time() - rendered:.2f} s")


main()
