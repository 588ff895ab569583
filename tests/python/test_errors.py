"""Bad input from Python: lancer.InputError carrying the CLI's message and location, and clear
ValueErrors for arrays and arguments, never a crash."""

import numpy as np
import pytest

import lancer
from conftest import data, run_cli

BRACKET = data("examples", "meshes", "bracket.msh")
SQUARE = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]], dtype=float)
TRIANGLES = np.array([[0, 1, 2], [0, 2, 3]])


def test_input_error_is_the_cli_message(tmp_path):
    broken = data("fuzz", "corpus", "msh_reader", "broken_bad_number.msh")
    code, stderr = run_cli("render", broken, "-o", tmp_path / "x.png", check=False)
    assert code == 2
    with pytest.raises(lancer.InputError) as caught:
        lancer.read_msh(str(broken))
    assert str(caught.value) == stderr.strip()
    assert caught.value.file == str(broken)
    assert caught.value.line > 0 and caught.value.column > 0
    assert isinstance(caught.value, ValueError)


def test_scene_error_points_into_the_file(tmp_path):
    scene = tmp_path / "bad.toml"
    scene.write_text('[render]\nwidth = "wide"\n')
    with pytest.raises(lancer.InputError) as caught:
        lancer.Scene.load(str(scene))
    assert caught.value.line == 2
    assert str(caught.value).startswith(f"{scene}:2:")


def test_missing_file():
    with pytest.raises(lancer.InputError, match="no_such.msh"):
        lancer.read_msh("no_such.msh")


@pytest.mark.parametrize(
    "points, faces, message",
    [
        (SQUARE[:, :2], TRIANGLES, r"points must be an \(N, 3\) array"),
        (SQUARE.astype(complex), TRIANGLES, "points must hold real numbers"),
        (np.where(SQUARE == 1, np.nan, SQUARE), TRIANGLES, r"points\[1\] is .*finite"),
        (SQUARE, TRIANGLES[:, :2], r"cells must be an \(M, 3\) or \(M, 4\) array"),
        (SQUARE, TRIANGLES.astype(float), "cells must hold integers"),
        (SQUARE, np.array([[0, 1, 4]]), r"cells\[0\] uses point 4, but points has 4 rows"),
        (SQUARE, np.array([[0, 1, 2], [-1, 2, 3]]), r"cells\[1\] uses point -1"),
    ],
)
def test_bad_arrays(points, faces, message):
    with pytest.raises(ValueError, match=message):
        lancer.Mesh(points, faces)


def test_bad_groups():
    with pytest.raises(ValueError, match=r"groups must be an \(2,\) array"):
        lancer.Mesh(SQUARE, TRIANGLES, groups=[1, 2, 3])
    with pytest.raises(ValueError, match=r"groups\[1\] is -3"):
        lancer.Mesh(SQUARE, TRIANGLES, groups=[1, -3])
    with pytest.raises(ValueError, match="group_names must map integer tags to strings"):
        lancer.Mesh(SQUARE, TRIANGLES, groups=[1, 2], group_names={"one": 1})


def test_mixed_triangles_and_quads():
    mesh = lancer.Mesh(SQUARE, np.array([[0, 1, 2, 3], [0, 1, 2, -1]]), groups=[5, 6], group_names={5: "plate"})
    assert mesh.faces.shape == (2, 4)
    assert list(mesh.faces[1]) == [0, 1, 2, -1]
    assert list(mesh.groups) == [5, 6]
    assert mesh.group_names == {5: "plate"}


def test_bad_render_arguments():
    mesh = lancer.Mesh(SQUARE, TRIANGLES)
    with pytest.raises(lancer.InputError, match="width must be between 1 and 32768, found 0"):
        lancer.render(mesh, width=0)
    with pytest.raises(ValueError, match="shading='smooth': use one of 'flat', 'gouraud', 'phong'"):
        lancer.render(mesh, shading="smooth")
    with pytest.raises(lancer.InputError, match="samples must be a perfect square .* found 5"):
        lancer.render(mesh, samples=5)
    with pytest.raises(ValueError, match="dtype="):
        lancer.render(mesh, dtype="int16")
    with pytest.raises(TypeError, match="lancer.Scene or a lancer.Mesh"):
        lancer.render("part.msh")
    with pytest.raises(ValueError, match="projection='fisheye'"):
        lancer.Camera(projection="fisheye")


def test_nothing_to_draw():
    with pytest.raises(lancer.InputError, match="nothing to draw"):
        lancer.render(lancer.Mesh(SQUARE, np.zeros((0, 3), dtype=int)), width=8, height=8)


def test_bad_output_leaves_no_file(tmp_path):
    image = lancer.render(lancer.Mesh(SQUARE, TRIANGLES), width=8, height=8)
    with pytest.raises(lancer.InputError, match="extension"):
        image.save(tmp_path / "x.tif")
    assert list(tmp_path.iterdir()) == []


def big_strip(faces):
    """A strip of `faces` triangles: big enough to be checked and assembled in many chunks."""
    columns = faces // 2 + 1
    points = np.array([(x, y, 0.0) for x in range(columns) for y in (0, 1)], dtype=float)
    triangles = []
    for x in range(columns - 1):
        a, b, c, d = 2 * x, 2 * x + 1, 2 * x + 2, 2 * x + 3
        triangles += [(a, c, b), (b, c, d)]
    return points, np.array(triangles, dtype=np.int64)


def test_threads_change_nothing_and_the_first_bad_row_is_reported():
    points, faces = big_strip(300_000)
    one, two = lancer.Mesh(points, faces, threads=1), lancer.Mesh(points, faces, threads=2)
    assert np.array_equal(one.faces, two.faces) and np.array_equal(one.points, two.points)
    broken = faces.copy()
    broken[250_123, 2] = len(points)
    broken[170_001, 0] = -7  # the lower row is the one named, whatever the threads
    for threads in (1, 2, 0):
        with pytest.raises(ValueError, match=r"cells\[170001\] uses point -7"):
            lancer.Mesh(points, broken, threads=threads)
    bad_points = points.copy()
    bad_points[200_000, 1] = np.inf
    bad_points[90_000, 2] = np.nan
    with pytest.raises(ValueError, match=r"points\[90000\] is"):
        lancer.Mesh(bad_points, faces, threads=2)
    for call in (lambda: lancer.Mesh(points, faces, threads=-1), lambda: lancer.read_msh(str(BRACKET), threads=5000)):
        with pytest.raises(lancer.InputError, match=r"threads must be between 0 and 1024 \(0: one per usable CPU\)"):
            call()


def test_bad_environment_map_is_an_input_error(tmp_path):
    mesh_path = data("tests", "data", "render", "bracket_coarse.msh")
    for name, content in (("missing.exr", None), ("text.exr", "P3\n2 2\n255\n")):
        if content is not None:
            (tmp_path / name).write_text(content)
        scene = tmp_path / "scene.toml"
        scene.write_text(f'[render]\nintegrator = "path"\n[[mesh]]\nfile = "{mesh_path}"\n'
                         f'[environment]\nmap = "{name}"\n')
        with pytest.raises(lancer.InputError) as caught:
            lancer.render(lancer.Scene.load(str(scene)), width=8, height=8)
        assert name in str(caught.value) and caught.value.line == 6
