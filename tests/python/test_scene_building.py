"""A lancer.Scene built in code (Scene(), add_mesh, add_light, add_material, add_clip, set, camera)
or from a string (Scene.loads) is the scene a file with those keys gives: the same picture, the
same checks, the same messages naming the call; and reader warnings reach Python's warnings as
lancer.LancerWarning."""

import warnings

import numpy as np
import pytest

import lancer

from conftest import data

BRACKET = str(data("tests", "data", "render", "bracket_coarse.msh"))
VECTORS = str(data("tests", "data", "fields", "element_vector_v41_bin.msh"))
CANTILEVER = str(data("tests", "data", "results", "cantilever.msh"))

SCENE_TEXT = f"""
[render]
width = 80
height = 60
background = [0.1, 0.1, 0.2]

[material.red]
kd = [0.8, 0.1, 0.1]
shininess = 16

[[light]]
type = "point"
position = [3, 4, 5]
intensity = [0.9, 0.9, 0.9]

[[mesh]]
file = "{BRACKET}"
material = "red"
rotate = [0, 30, 0]

[camera]
position = [3, 2.5, 4]
look_at = [0, 0.9, 0]
fov = 35
"""


def image(scene):
    return np.asarray(lancer.render(scene))


def built_bracket(mesh):
    scene = lancer.Scene()
    scene.set("render", width=80, height=60, background=(0.1, 0.1, 0.2))
    scene.add_material("red", kd=np.array([0.8, 0.1, 0.1]), shininess=16)
    scene.add_light(type="point", position=[3, 4, 5], intensity=[0.9] * 3)
    scene.add_mesh(mesh, material="red", rotate=(0, 30, 0))
    scene.set("camera", position=[3, 2.5, 4], look_at=[0, 0.9, 0], fov=35)
    return scene


def test_built_loaded_and_parsed_scenes_are_the_file_scene(tmp_path):
    path = tmp_path / "scene.toml"
    path.write_text(SCENE_TEXT)
    expected = image(lancer.Scene.load(str(path)))
    assert len(np.unique(expected.reshape(-1, 3), axis=0)) > 20  # the bracket is in the picture
    assert np.array_equal(image(lancer.Scene.loads(SCENE_TEXT)), expected)
    assert np.array_equal(image(built_bracket(BRACKET)), expected)  # the mesh by its file
    assert np.array_equal(image(built_bracket(lancer.read_msh(BRACKET))), expected)  # and in memory
    assert lancer.Scene.loads(SCENE_TEXT).path == "<string>"


def test_camera_and_changes_after_a_load(tmp_path):
    path = tmp_path / "scene.toml"
    path.write_text(SCENE_TEXT)
    scene = lancer.Scene.load(str(path))
    before = image(scene)
    scene.camera = lancer.Camera(position=(4, 1, 1), look_at=(0, 0.9, 0))
    above = image(scene)
    assert not np.array_equal(above, before)
    scene.add_light(type="point", position=[4, 1, 1], intensity=[0.3] * 3)
    assert tuple(scene.camera.position) == (4, 1, 1)  # a Camera set in Python stays over later changes
    assert not np.array_equal(image(scene), above)
    scene.set("camera", position=[3, 2.5, 4])  # the [camera] keys say the camera again
    assert tuple(scene.camera.position) == (3, 2.5, 4)


def test_field_coloured_mesh_with_results_and_clip():
    mesh = lancer.read_msh(CANTILEVER)
    scene = lancer.Scene()
    scene.set("render", width=96, height=64)
    scene.add_light(type="sun", direction=[-1, -1, -1])
    scene.add_mesh(mesh, material={"kd": [0.5, 0.5, 0.5]}, warp={"field": "displacement", "factor": 2},
                   color_by={"field": "stress", "component": "von_mises", "legend": "right"},
                   arrows={"field": "displacement", "max_count": 30})
    scene.add_clip(point=[0, 0, 0], normal=[0, 0, 1])
    scene.set("render", step=2)
    assert "mesh[0]" in scene.to_toml()
    picture = image(scene)
    assert picture.std() > 0


@pytest.mark.parametrize(
    "call, error, message",
    [
        (lambda s: s.add_mesh(BRACKET, color_by={"field": "T", "map": "virdis"}), lancer.InputError,
         r"add_mesh: error: mesh\[0\]\.color_by\.map: \"virdis\" is not a colour map \(did you mean 'viridis'\?\)"),
        (lambda s: s.add_mesh(BRACKET, smooth_angel=30), lancer.InputError,
         r"add_mesh: error: unknown key 'smooth_angel' in mesh\[0\] \(did you mean 'smooth_angle'\?\)"),
        (lambda s: s.add_mesh(BRACKET, material="gold"), lancer.InputError, "names material 'gold', which is not defined"),
        (lambda s: s.add_mesh(BRACKET, file="x.msh"), TypeError, "not file="),
        (lambda s: s.add_mesh(3), TypeError, "add_mesh takes a lancer.Mesh or a mesh file's path"),
        (lambda s: s.add_mesh(BRACKET, translate={1, 2}), TypeError, r"add_mesh\(translate=: .* is not a str"),
        (lambda s: s.add_light(type="pointy"), lancer.InputError, r"add_light: error: light\[0\]\.type must be"),
        (lambda s: s.add_material("m", kd=[2, 0, 0]), lancer.InputError, "add_material: error: material.m.kd"),
        (lambda s: s.add_clip(point=[0, 0, 0]), lancer.InputError, r"add_clip: error: .*normal"),
        (lambda s: s.set("rendr", width=3), ValueError, r"did you mean 'render'\?"),
        (lambda s: s.set("render", widht=3), lancer.InputError, r"set: error: unknown key 'widht' in \[render\]"),
        (lambda s: s.set("render", width=0), lancer.InputError, r"set: error: render.width"),
    ],
)
def test_bad_keys_are_refused_as_in_a_file(call, error, message):
    scene = lancer.Scene()
    with pytest.raises(error, match=message):
        call(scene)
    assert scene.to_toml() == ""  # a refused change leaves the scene as it was


def test_loads_errors_name_string_and_line():
    with pytest.raises(lancer.InputError, match=r"^<string>:3:9: error: render.width must be an integer") as raised:
        lancer.Scene.loads("\n[render]\nwidth = 'x'\n")
    assert (raised.value.file, raised.value.line) == ("<string>", 3)
    with pytest.raises(lancer.InputError, match=r"^<string>:1:"):
        lancer.Scene.loads("[render\n")


def test_a_mesh_in_memory_cannot_draw_inside_a_volume_and_a_quick_look_cannot_change():
    # A Mesh read from a file of faces alone says what its path says; one made from arrays of faces
    # has no file to turn to.
    plane = [{"point": [0, 0, 0], "normal": [0, 0, 1]}]
    for mesh in (BRACKET, lancer.read_msh(BRACKET)):
        scene = lancer.Scene()
        scene.add_mesh(mesh, slice=plane)
        with pytest.raises(lancer.InputError, match=r"bracket_coarse.msh' has no volume elements \(tetrahedra"):
            lancer.render(scene, width=16, height=16)
    scene = lancer.Scene()
    scene.add_mesh(lancer.Mesh(np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0.0]]), np.array([[0, 1, 2]])), slice=plane)
    with pytest.raises(lancer.InputError, match="is a mesh in memory without volume elements"):
        lancer.render(scene, width=16, height=16)
    with pytest.raises(ValueError, match="a quick look is the scene of one mesh"):
        lancer.Scene.quick_look(lancer.read_msh(BRACKET)).add_light(type="point", position=[0, 0, 1])


def test_reader_warnings_are_lancer_warnings_once():
    assert issubclass(lancer.LancerWarning, UserWarning)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        mesh = lancer.read_msh(VECTORS)
        lancer.render(mesh, width=16, height=16)  # said when read, not again
    messages = [str(w.message) for w in caught]
    assert len(messages) == 1 and "warning: " in messages[0] and "gives values for 4 elements" in messages[0]
    assert caught[0].category is lancer.LancerWarning and caught[0].filename == __file__
    with warnings.catch_warnings():
        warnings.simplefilter("error", lancer.LancerWarning)
        with pytest.raises(lancer.LancerWarning, match="gives values for 4 elements"):
            lancer.read_msh(VECTORS)
    scene = lancer.Scene()
    scene.add_mesh(VECTORS)  # read when rendered: its warnings come then
    with pytest.warns(lancer.LancerWarning, match="gives values for 4 elements"):
        lancer.render(scene, width=16, height=16)
