"""lancer.render's slices=, skin=, isosurfaces= and streamlines= are the command line's --slice,
--skin, --isosurfaces (--isovalues) and --streamlines (--seed-line): the same picture, byte for byte,
whether given as the options' text or as dicts of the scene file's keys; refused with the same
messages. A Mesh lancer.read_msh read has its volume read from its file; one made from arrays has none."""

import shutil

import numpy as np
import pytest

import lancer

from conftest import cli_image, data, run_cli

CAPACITOR = str(data("tests", "data", "volume", "capacitor.msh"))
HEXAHEDRA = str(data("tests", "data", "volume", "cube_hex.msh"))
MIXED = str(data("tests", "data", "volume", "mixed.msh"))
TETRAHEDRA = str(data("tests", "data", "element_node", "tet_v41_bin.msh"))
SURFACE = str(data("tests", "data", "fields", "node_xy_v41_bin.msh"))
SQUARE_VECTOR = str(data("tests", "data", "fields", "node_vector_v41_bin.msh"))
SPHERE_SKIN = str(data("tests", "data", "msh", "sphere_v41_bin.msh"))
SIZE = {"width": 96, "height": 64}


def test_slices_match_the_cli(tmp_path):
    mesh = lancer.read_msh(CAPACITOR)
    coloured = lancer.Scene.quick_look(mesh, color_by="v")
    image = np.asarray(lancer.render(coloured, slices="y", legend="right", **SIZE))
    assert np.array_equal(image, cli_image(tmp_path, CAPACITOR, "--color-by", "v", "--slice", "y", "--legend", "right"))
    assert not np.array_equal(image, np.asarray(lancer.render(coloured, legend="right", **SIZE)))
    # A dict of a [[mesh.slice]]'s keys is the plane's text; a list is --slice given again.
    two = np.asarray(lancer.render(coloured, slices=[{"point": [0, 0, 0.1], "normal": [0, 0, 1]}, "x=0"],
                                   skin="edges", **SIZE))
    assert np.array_equal(two, cli_image(tmp_path, CAPACITOR, "--color-by", "v", "--slice", "0,0,0.1,0,0,1", "--slice",
                                         "x=0", "--skin", "edges"))
    # Element data on hexahedra; a mixed mesh without fields, in the material's colour.
    hexahedra = np.asarray(lancer.render(lancer.Scene.quick_look(lancer.read_msh(HEXAHEDRA), color_by="g"),
                                         slices="0.5,0.5,0.5,1,1,1", skin="hidden", **SIZE))
    assert np.array_equal(hexahedra, cli_image(tmp_path, HEXAHEDRA, "--color-by", "g", "--slice", "0.5,0.5,0.5,1,1,1",
                                               "--skin", "hidden"))
    mixed = np.asarray(lancer.render(lancer.read_msh(MIXED), slices="z", **SIZE))
    assert np.array_equal(mixed, cli_image(tmp_path, MIXED, "--slice", "z"))


def test_a_scene_file_takes_the_keywords(tmp_path):
    # A scene file's meshes are read with their volumes by the scene's own build.
    scene_file = tmp_path / "capacitor.toml"
    scene_file.write_text(f'[[mesh]]\nfile = "{CAPACITOR}"\ncolor_by = {{ field = "v" }}\n')
    image = np.asarray(lancer.render(lancer.Scene.load(str(scene_file)), slices="z", streamlines="e:5", **SIZE))
    assert np.array_equal(image, cli_image(tmp_path, scene_file, "--slice", "z", "--streamlines", "e:5"))


def test_coloured_cut_caps_match_the_cli(tmp_path):
    # clip= through a field-coloured Mesh read from a file shows the field on the cut, as --clip does.
    scene = lancer.Scene.quick_look(lancer.read_msh(CAPACITOR), color_by="v")
    image = np.asarray(lancer.render(scene, clip="y=0", **SIZE))
    assert np.array_equal(image, cli_image(tmp_path, CAPACITOR, "--color-by", "v", "--clip", "y=0"))


def test_isosurfaces_match_the_cli(tmp_path):
    mesh = lancer.read_msh(CAPACITOR)
    image = np.asarray(lancer.render(mesh, isosurfaces="v:4", legend="right", **SIZE))
    assert np.array_equal(image, cli_image(tmp_path, CAPACITOR, "--isosurfaces", "v:4", "--legend", "right"))
    values = np.asarray(lancer.render(mesh, isosurfaces={"field": "v", "values": [-0.5, 0.5]}, **SIZE))
    assert np.array_equal(values, cli_image(tmp_path, CAPACITOR, "--isosurfaces", "v", "--isovalues", "-0.5,0.5"))
    on_coloured = np.asarray(lancer.render(lancer.Scene.quick_look(mesh, color_by="e"),
                                           isosurfaces={"field": "v", "values": [-0.5, 0.5]}, **SIZE))
    assert np.array_equal(on_coloured, cli_image(tmp_path, CAPACITOR, "--color-by", "e", "--isosurfaces", "v",
                                                 "--isovalues", "-0.5,0.5"))
    # The scene keys the command line has no option for: the surfaces in another field's colours.
    by_e = np.asarray(lancer.render(mesh, isosurfaces={"field": "v", "values": [-0.5, 0.5], "color_by": "e"},
                                    **SIZE))
    assert not np.array_equal(by_e, values)
    # Node data on tetrahedra.
    tetrahedra = np.asarray(lancer.render(lancer.read_msh(TETRAHEDRA), isosurfaces="f:3", **SIZE))
    assert np.array_equal(tetrahedra, cli_image(tmp_path, TETRAHEDRA, "--isosurfaces", "f:3"))


def test_streamlines_match_the_cli(tmp_path):
    mesh = lancer.read_msh(CAPACITOR)
    image = np.asarray(lancer.render(mesh, streamlines="e:20", **SIZE))
    assert np.array_equal(image, cli_image(tmp_path, CAPACITOR, "--streamlines", "e:20"))
    line = np.asarray(lancer.render(mesh, streamlines={"field": "e", "count": 10,
                                                       "seed_line": [[-0.5, 0, 0], [0.5, 0, 0]]}, **SIZE))
    assert np.array_equal(line, cli_image(tmp_path, CAPACITOR, "--streamlines", "e:10", "--seed-line",
                                          "-0.5,0,0,0.5,0,0"))
    assert not np.array_equal(image, line)


def test_a_mesh_keeps_its_volume(tmp_path):
    # The volume is read once, from the file read_msh read, and kept with the Mesh: a copy of the
    # file removed after the first render still renders, from the Scene and from new quick looks.
    copy = tmp_path / "capacitor.msh"
    shutil.copy(CAPACITOR, copy)
    scene = lancer.Scene.quick_look(lancer.read_msh(str(copy)), color_by="v")
    first = np.asarray(lancer.render(scene, slices="z", **SIZE))
    copy.unlink()
    assert np.array_equal(first, np.asarray(lancer.render(scene, slices="z", **SIZE)))
    mesh = scene.mesh
    assert np.array_equal(np.asarray(lancer.render(lancer.Scene.quick_look(mesh, color_by="v"), slices="z", **SIZE)),
                          first)
    assert mesh.probe([0, 0, 0], "v").shape == (1, 1)  # probes share it


def test_a_scene_draws_inside_a_read_mesh_as_inside_its_file(tmp_path):
    # Scene.add_mesh(lancer.read_msh(path)) draws the slices, isosurfaces, field lines and coloured
    # caps that add_mesh(path) draws, from the volume the Mesh keeps: read once, then kept.
    copy = tmp_path / "capacitor.msh"
    shutil.copy(CAPACITOR, copy)
    mesh = lancer.read_msh(str(copy))
    keys = {"color_by": {"field": "v"}, "slice": [{"point": [0, 0, 0.1], "normal": [0, 0, 1]}],
            "isosurfaces": {"field": "v", "values": [0.5]}, "streamlines": {"field": "e", "count": 6}}
    by_path, by_mesh = lancer.Scene(), lancer.Scene()
    by_path.add_mesh(str(copy), **keys)
    by_mesh.add_mesh(mesh, **keys)
    # render's keywords, and a coloured cap, on scenes of the path and of the Mesh.
    plain_path, plain_mesh = lancer.Scene(), lancer.Scene()
    plain_path.add_mesh(str(copy), color_by={"field": "v"})
    plain_mesh.add_mesh(mesh, color_by={"field": "v"})
    expected = [np.asarray(lancer.render(by_path, **SIZE))]
    expected += [np.asarray(lancer.render(plain_path, **keywords, **SIZE)) for keywords in ({"slices": "z"}, {"clip": "y=0"})]
    for kept in (False, True):  # the file there, then gone
        if kept:
            copy.unlink()
        assert np.array_equal(np.asarray(lancer.render(by_mesh, **SIZE)), expected[0])
        assert np.array_equal(np.asarray(lancer.render(plain_mesh, slices="z", **SIZE)), expected[1])
        assert np.array_equal(np.asarray(lancer.render(plain_mesh, clip="y=0", **SIZE)), expected[2])
    assert mesh.volume.cells > 0  # the probes' volume is the one the renders read


def test_probes_read_the_file_once(tmp_path):
    copy = tmp_path / "cube.msh"
    shutil.copy(HEXAHEDRA, copy)
    mesh = lancer.read_msh(str(copy))
    point = [0.3, 0.4, 0.5]
    first = mesh.probe(point, "f")
    copy.unlink()
    assert np.array_equal(mesh.probe(point, "f"), first)
    assert mesh.volume is mesh.volume and mesh.volume.cells == 216
    assert np.allclose(first, 0.3 + 2 * 0.4 + 3 * 0.5, atol=1e-5)
    # A render of the mesh draws inside the volume its probes read.
    lancer.render(mesh, slices="z", **SIZE)
    # Another Mesh of the same file reads it again: gone, it says so.
    shutil.copy(HEXAHEDRA, copy)
    again = lancer.read_msh(str(copy))
    copy.unlink()
    with pytest.raises(lancer.InputError, match="cube.msh"):
        again.probe(point, "f")


def test_animate_draws_what_render_draws_inside_the_volume(tmp_path):
    # An orbit's first frame is the render from the scene's camera: each volume keyword draws the same.
    scene = lancer.Scene.quick_look(lancer.read_msh(CAPACITOR), color_by="v")
    for keywords in ({"slices": "y", "skin": "edges"}, {"isosurfaces": {"field": "v", "values": [-0.5, 0.5]}},
                     {"streamlines": {"field": "e", "count": 6, "radius": "3px"}, "legend": "right"},
                     {"arrows": {"field": "e", "grid": [3, 3, 3]}}, {"clip": "y=0"}):
        lancer.animate(scene, tmp_path / "turn_%02d.png", frames=2, **keywords, **SIZE)
        frame = np.asarray(lancer.read_png(str(tmp_path / "turn_00.png")))[..., :3]
        assert np.array_equal(frame, np.asarray(lancer.render(scene, **keywords, **SIZE))), keywords
    # Over steps, a frame is that step's render: a slice through the moving cube at step 1.
    moving = lancer.read_msh(str(data("tests", "data", "volume", "moving.msh")))
    lancer.animate(lancer.Scene.quick_look(moving, color_by="s", color_range=(-1, 1)), tmp_path / "step_%02d.png",
                   over="steps", slices="y", skin="hidden", **SIZE)
    frame = np.asarray(lancer.read_png(str(tmp_path / "step_01.png")))[..., :3]
    step = lancer.render(lancer.Scene.quick_look(moving, color_by="s", color_range=(-1, 1), step=1), slices="y",
                         skin="hidden", **SIZE)
    assert np.array_equal(frame, np.asarray(step))
    # Refused with render's messages, before anything is written.
    with pytest.raises(lancer.InputError, match=r"^slices: error: 'w' is not a plane"):
        lancer.animate(scene, tmp_path / "bad.gif", slices="w", **SIZE)
    with pytest.raises(TypeError, match="isosurfaces= takes 'FIELD', 'FIELD:COUNT' or a dict"):
        lancer.animate(scene, tmp_path / "bad.gif", isosurfaces=3, **SIZE)
    with pytest.raises(lancer.InputError, match=r"streamlines of 'v': it has 1 component"):
        lancer.animate(scene, tmp_path / "bad.gif", streamlines="v", **SIZE)
    assert not (tmp_path / "bad.gif").exists()


def test_pixel_tubes_beside_a_legend_over_steps_match_the_render_of_the_step(tmp_path):
    # Field lines 3 px thick beside a right legend: the single render frames the model beside the
    # legend and sizes the tubes for that framing. An animation over steps colours them over every
    # step (|w| over the moving cube's three steps): its frame is the render of the step with that
    # range, the model framed beside that legend, not beside the one step's.
    moving = lancer.read_msh(str(data("tests", "data", "volume", "moving.msh")))
    keywords = {"streamlines": {"field": "w", "count": 3, "radius": "3px",
                                "seed_line": [[0.2, 0.3, 0.3], [0.2, 0.7, 0.7]]},
                "legend": "right", "width": 160, "height": 96}
    lancer.animate(moving, tmp_path / "steps_%02d.png", over="steps", **keywords)
    frame = np.asarray(lancer.read_png(str(tmp_path / "steps_00.png")))[..., :3]
    magnitudes = [np.sqrt((moving.field("w", k).astype(np.float64) ** 2).sum(axis=1)) for k in range(3)]
    over_steps = (min(m.min() for m in magnitudes), max(m.max() for m in magnitudes))
    single = np.asarray(lancer.render(lancer.Scene.quick_look(moving, step=0), range=over_steps, **keywords))
    assert np.array_equal(frame, single)
    without = np.asarray(lancer.render(lancer.Scene.quick_look(moving, step=0),
                                       **{**keywords, "legend": "none", "range": over_steps}))
    assert not np.array_equal(single, without)


def test_volume_keywords_bad_input():
    mesh = lancer.read_msh(CAPACITOR)
    with pytest.raises(lancer.InputError, match=r"^slices: error: 'w' is not a plane: use AXIS \(x, y or z: through "
                                                r"the volume's centre\), AXIS=VALUE"):
        lancer.render(mesh, slices="w", **SIZE)
    with pytest.raises(lancer.InputError, match="slices: error: a slice needs a finite point and a normal other than"):
        lancer.render(mesh, slices="0,0,0,0,0,0", **SIZE)
    with pytest.raises(lancer.InputError, match=r"\[slices\] has no 'normal'; add normal = \[x, y, z\]"):
        lancer.render(mesh, slices={"point": [0, 0, 0]}, **SIZE)
    with pytest.raises(lancer.InputError, match=r"slices\[1\].normal must be an array of 3 numbers"):
        lancer.render(mesh, slices=["z", {"normal": [0, 0]}], **SIZE)
    with pytest.raises(lancer.InputError, match=r"unknown key 'colour' in \[slices\]"):
        lancer.render(mesh, slices={"normal": [0, 0, 1], "colour": 1}, **SIZE)
    with pytest.raises(TypeError, match="slices= takes a plane as text"):
        lancer.render(mesh, slices=3, **SIZE)
    with pytest.raises(TypeError, match="slices=: 3 is not a plane"):
        lancer.render(mesh, slices=["z", 3], **SIZE)
    with pytest.raises(ValueError, match="skin='glass' is not a skin style: use 'shown', 'ghost', 'edges' or 'hidden'"):
        lancer.render(mesh, slices="z", skin="glass", **SIZE)

    with pytest.raises(lancer.InputError, match="isosurfaces: error: 'v:0' is not FIELD\\[:COUNT\\]: COUNT is a whole "
                                                "number from 1 to 100"):
        lancer.render(mesh, isosurfaces="v:0", **SIZE)
    with pytest.raises(lancer.InputError, match=r"give the field: isosurfaces FIELD\[:COUNT\]"):
        lancer.render(mesh, isosurfaces=":3", **SIZE)
    with pytest.raises(TypeError, match="isosurfaces= takes 'FIELD', 'FIELD:COUNT' or a dict"):
        lancer.render(mesh, isosurfaces=3, **SIZE)
    with pytest.raises(lancer.InputError, match=r"\[isosurfaces\] gives both count and values: keep one"):
        lancer.render(mesh, isosurfaces={"field": "v", "count": 3, "values": [1]}, **SIZE)
    with pytest.raises(lancer.InputError, match=r"unknown key 'colour' in \[isosurfaces\] \(did you mean 'color'\?\)"):
        lancer.render(mesh, isosurfaces={"field": "v", "colour": [1, 0, 0]}, **SIZE)
    with pytest.raises(lancer.InputError, match="isosurfaces of 'nothing': .*capacitor.msh has no such field inside "
                                                r"its volume \(its fields: v, e\)"):
        lancer.render(mesh, isosurfaces="nothing", **SIZE)
    with pytest.raises(lancer.InputError, match="isosurfaces of 'e': it has 3 components"):
        lancer.render(mesh, isosurfaces="e", **SIZE)

    with pytest.raises(lancer.InputError, match="streamlines: error: 'e:0' is not FIELD\\[:COUNT\\]: COUNT is a whole "
                                                "number from 1 to 100000"):
        lancer.render(mesh, streamlines="e:0", **SIZE)
    with pytest.raises(lancer.InputError, match=r"streamlines of 'v': it has 1 component, and field lines follow a "
                                                r"vector"):
        lancer.render(mesh, streamlines="v", **SIZE)
    with pytest.raises(lancer.InputError, match=r"streamlines.seed_line must be an array of 2 points"):
        lancer.render(mesh, streamlines={"field": "e", "seed_line": [[0, 0, 0]]}, **SIZE)
    with pytest.raises(lancer.InputError, match=r"streamlines.direction must be \"both\", \"forward\" or \"backward\""):
        lancer.render(mesh, streamlines={"field": "e", "direction": "up"}, **SIZE)
    with pytest.raises(TypeError, match=r"streamlines=: the dict's keys are the scene file's key names"):
        lancer.render(mesh, streamlines={"field": "e", 3: 1}, **SIZE)


def test_a_mesh_without_volume_elements_says_so():
    surface = lancer.read_msh(SURFACE)
    with pytest.raises(lancer.InputError, match=r"^slices: error: '.*node_xy_v41_bin.msh' has no volume elements "
                                                r"\(tetrahedra, hexahedra, prisms, pyramids\)"):
        lancer.render(surface, slices="z", **SIZE)
    # Field lines alone name their keyword too: across a flat surface, the field must be there; a
    # surface that is not flat has nothing for them to follow.
    with pytest.raises(lancer.InputError, match="^streamlines: error: streamlines of 'u': .* has no such field on its "
                                                "2D domain"):
        lancer.render(surface, streamlines="u", **SIZE)
    with pytest.raises(lancer.InputError, match="^streamlines: error: .* has no volume elements and its faces are "
                                                "not in one plane"):
        lancer.render(lancer.read_msh(SPHERE_SKIN), streamlines="u", **SIZE)
    arrays = lancer.Mesh(np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0.0]]), np.array([[0, 1, 2]]))
    with pytest.raises(lancer.InputError, match="^isosurfaces: error: '<arrays>' has no volume elements .*a mesh made "
                                                "from arrays without volume cells, or by gmsh, is its surface alone; "
                                                "give lancer.Mesh its tetrahedra .* or read the .msh file with "
                                                "lancer.read_msh"):
        lancer.render(arrays, isosurfaces="v", **SIZE)


def test_the_command_line_names_the_option_of_field_lines_without_a_volume(tmp_path):
    code, stderr = run_cli("render", SPHERE_SKIN, "--streamlines", "u", "-q", "-o", tmp_path / "no.png", check=False)
    assert code == 2
    assert stderr.startswith("--streamlines: error: ") and "has no volume elements" in stderr, stderr
    assert not (tmp_path / "no.png").exists()


def test_streamlines_across_a_2d_mesh_match_the_cli(tmp_path):
    # A flat mesh's field lines are traced across its faces: seeds on a rectangle, tubes sized in pixels.
    square = lancer.read_msh(SQUARE_VECTOR)
    keys = {"field": "temperature", "count": 6, "seed_rectangle": [[0.1, 0.1, 0], [0.8, 0, 0], [0, 0.3, 0]],
            "radius": "2px"}
    image = np.asarray(lancer.render(square, streamlines=keys, **SIZE))
    assert np.array_equal(image, cli_image(tmp_path, SQUARE_VECTOR, "--streamlines", "temperature:6",
                                           "--seed-rectangle", "0.1,0.1,0,0.8,0,0,0,0.3,0",
                                           "--streamline-radius", "2px"))
    assert not np.array_equal(image, np.asarray(lancer.render(square, **SIZE)))
    # A flat mesh made from arrays: a rotation on a 2 x 2 grid of quads.
    xy = np.array([[x, y, 0.0] for y in (0, 0.5, 1) for x in (0, 0.5, 1)])
    quads = np.array([[0, 1, 4, 3], [1, 2, 5, 4], [3, 4, 7, 6], [4, 5, 8, 7]])
    rotation = np.column_stack([0.5 - xy[:, 1], xy[:, 0] - 0.5, np.zeros(len(xy))])
    arrays = lancer.Mesh(xy, [("quad", quads)], point_data={"v": rotation})
    turning = np.asarray(lancer.render(arrays, streamlines={"field": "v", "seed_points": [[0.8, 0.5, 0]]}, **SIZE))
    assert not np.array_equal(turning, np.asarray(lancer.render(arrays, **SIZE)))
    with pytest.raises(lancer.InputError, match=r"streamlines.radius must be a length in model units \(0.01\) or in "
                                                r"pixels greater than 0"):
        lancer.render(square, streamlines={"field": "temperature", "radius": "-2px"}, **SIZE)
    with pytest.raises(lancer.InputError, match=r"streamlines.seed_rectangle is a corner and the two edges from it"):
        lancer.render(square, streamlines={"field": "temperature",
                                           "seed_rectangle": [[0, 0, 0], [0, 0, 0], [0, 1, 0]]}, **SIZE)
