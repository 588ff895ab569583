"""Results from Python: quick_look with warp= and component=, lancer.animate(over="steps"), every step
of every view from a live gmsh session, and the same errors as the CLI (tests/data/results/ is made by
scripts/make_result_fixtures.py)."""

import numpy as np
import pytest

import lancer

import gmsh

from conftest import data, picture_bytes, run_cli

CANTILEVER = str(data("tests", "data", "results", "cantilever.msh"))


def test_quick_look_warp_matches_the_cli(tmp_path):
    mesh = lancer.read_msh(CANTILEVER)
    scene = lancer.Scene.quick_look(mesh, color_by="stress", component="von_mises", warp=("displacement", 2.0),
                                    undeformed="edges", step=3)
    image = np.asarray(lancer.render(scene, width=96, height=64))
    run_cli("render", CANTILEVER, "--warp", "displacement:2", "--color-by", "stress:von_mises", "--undeformed",
            "edges", "--step", "3", "--width", 96, "--height", 64, "-q", "-o", tmp_path / "cli.png")
    assert np.array_equal(image, np.asarray(lancer.read_png(str(tmp_path / "cli.png")))[..., :3])
    unwarped = np.asarray(lancer.render(lancer.Scene.quick_look(mesh, color_by="stress", step=3), width=96, height=64))
    assert not np.array_equal(image, unwarped)


def test_animate_over_steps_matches_the_cli(tmp_path):
    mesh = lancer.read_msh(CANTILEVER)
    scene = lancer.Scene.quick_look(mesh, color_by="temperature", warp="displacement")
    lancer.animate(scene, tmp_path / "py_%02d.png", over="steps", frames=5, width=64, height=48)
    run_cli("animate", CANTILEVER, "--over", "steps", "--frames", 5, "--color-by", "temperature", "--warp",
            "displacement", "--width", 64, "--height", 48, "-q", "-o", tmp_path / "cli_%02d.png")
    for k in range(5):
        assert picture_bytes(tmp_path / f"py_{k:02d}.png") == picture_bytes(tmp_path / f"cli_{k:02d}.png")
    assert not (tmp_path / "py_05.png").exists()


def test_bad_results_input_raises_input_error():
    mesh = lancer.read_msh(CANTILEVER)
    with pytest.raises(lancer.InputError, match="has 9 components per node: a warp needs a vector of 3"):
        lancer.render(lancer.Scene.quick_look(mesh, warp="stress"), width=16, height=16)
    with pytest.raises(lancer.InputError, match="has no step 8"):
        lancer.render(lancer.Scene.quick_look(mesh, color_by="temperature", step=8), width=16, height=16)
    with pytest.raises(lancer.InputError, match="von_mises needs a tensor of 9 components"):
        lancer.render(lancer.Scene.quick_look(mesh, color_by="displacement", component="von_mises"), width=16,
                      height=16)
    with pytest.raises(ValueError, match="component='w'"):
        lancer.Scene.quick_look(mesh, color_by="displacement", component="w")
    with pytest.raises(ValueError, match="over='time'"):
        lancer.animate(lancer.Scene.quick_look(mesh, color_by="temperature"), "x.gif", over="time")


def test_from_gmsh_keeps_every_step_of_every_view():
    gmsh.initialize(["lancer-test"], readConfigFiles=False)
    try:
        gmsh.option.setNumber("General.Terminal", 0)
        gmsh.open(CANTILEVER)
        live = lancer.from_gmsh()
    finally:
        gmsh.finalize()
    read = lancer.read_msh(CANTILEVER)
    assert live.fields == read.fields
    assert len(live.fields) == 3
    scene = lancer.Scene.quick_look(live, color_by="stress", component="von_mises", warp="displacement", step=2)
    assert np.array_equal(np.asarray(lancer.render(scene, width=48, height=32)),
                          np.asarray(lancer.render(lancer.Scene.quick_look(read, color_by="stress",
                                                                           component="von_mises",
                                                                           warp="displacement", step=2),
                                                   width=48, height=32)))


def test_steps_and_field_at_a_step():
    mesh = lancer.read_msh(CANTILEVER)
    assert mesh.steps("displacement") == [(0, 0.0), (1, 0.5), (2, 1.0), (3, 1.5)]
    tip = mesh.field("displacement", step=3)[:, 1].min()
    assert tip == pytest.approx(-1.5, abs=1e-6)
    with pytest.raises(KeyError, match="has no step 9"):
        mesh.field("displacement", step=9)


def test_quick_look_isolines_arrows_and_legend():
    """isolines=, arrows= and the legend keywords take what the scene file's keys take, checked by the
    scene loader's own readers: each changes the picture, legend='none' is the picture without one."""
    mesh = lancer.read_msh(CANTILEVER)
    colours = {"field": "stress", "component": "von_mises", "title": "von Mises stress", "units": "MPa"}

    def picture(**keywords):
        scene = lancer.Scene.quick_look(mesh, step=3, warp="displacement", **keywords)
        return np.asarray(lancer.render(scene, width=160, height=90))

    plain = picture(color_by=colours)
    assert np.array_equal(plain, picture(color_by=colours, legend="none"))
    assert np.array_equal(plain, picture(color_by="stress", component="von_mises"))
    lines = picture(color_by=colours, isolines={"field": "stress", "component": "von_mises", "count": 6,
                                                "color": [0, 0, 0], "width": 2})
    assert not np.array_equal(plain, lines)
    assert np.array_equal(picture(color_by=colours, isolines="stress"),
                          picture(color_by=colours, isolines={"field": "stress"}))
    right = picture(color_by=colours, legend="right")
    bottom = picture(color_by={**colours, "legend": "bottom"})
    assert not np.array_equal(plain[:, -30:], right[:, -30:])  # a bar along the right edge
    assert not np.array_equal(plain[-20:], bottom[-20:])  # along the bottom
    arrows = picture(color_by=colours, arrows={"field": "displacement", "max_count": 20, "color": [1, 0, 0]})
    assert not np.array_equal(plain, arrows)
    assert np.array_equal(arrows, picture(color_by=colours, arrows={"field": "displacement", "max_count": 20,
                                                                    "color": (1, 0, 0)}))


def test_quick_look_result_keywords_bad_input():
    mesh = lancer.read_msh(CANTILEVER)
    with pytest.raises(lancer.InputError, match=r"quick_look: error: isolines.count must be an integer"):
        lancer.Scene.quick_look(mesh, isolines={"field": "stress", "count": "many"})
    with pytest.raises(lancer.InputError, match=r"unknown key 'feld' in \[isolines\].*'field'"):
        lancer.Scene.quick_look(mesh, isolines={"feld": "stress"})
    with pytest.raises(lancer.InputError, match=r"color_by.bands"):
        lancer.Scene.quick_look(mesh, color_by={"field": "stress", "bands": -1})
    with pytest.warns(UserWarning, match="isolines of element data \"temperature\" follow its mean at each vertex"):
        lancer.render(lancer.Scene.quick_look(mesh, isolines="temperature"), width=16, height=16)
    with pytest.raises(lancer.InputError, match="arrows field \"stress\" must be a vector of 3 components"):
        lancer.render(lancer.Scene.quick_look(mesh, arrows="stress"), width=16, height=16)
    with pytest.raises(TypeError, match=r"isolines= takes a field's name or a dict"):
        lancer.Scene.quick_look(mesh, isolines=3)
    with pytest.raises(TypeError, match=r"arrows=: .* is not a str, number, bool, list or dict"):
        lancer.Scene.quick_look(mesh, arrows={"field": "displacement", "color": object()})
    with pytest.raises(TypeError, match=r"color_by= takes a field's name or a dict"):
        lancer.Scene.quick_look(mesh, color_by=["stress"])
    with pytest.raises(ValueError, match=r"legend='left': use 'right', 'bottom' or 'none'"):
        lancer.Scene.quick_look(mesh, color_by="stress", legend="left")
    with pytest.raises(ValueError, match=r"give color_by= too"):
        lancer.Scene.quick_look(mesh, legend="right")
    with pytest.raises(ValueError, match=r"holds its own 'map', 'range' and 'component'"):
        lancer.Scene.quick_look(mesh, color_by={"field": "stress"}, color_map="magma")


def test_element_node_data_per_face_corner():
    # gmsh-made (scripts/make_element_node_fixtures.py): "g" holds "f" = x + 2y + 3z at every element's nodes.
    mesh = lancer.read_msh(str(data("tests", "data", "element_node", "tet_v41_bin.msh")))
    g, f = mesh.field("g"), mesh.field("f")
    faces = np.asarray(mesh.faces)
    assert g.shape == (len(faces), 4, 1)
    assert np.allclose(g[:, :3, 0], f[faces[:, :3], 0], atol=1e-5)
    assert np.isnan(g[:, 3, 0]).all()  # triangles have no fourth corner
    assert mesh.field("g", step=1).shape == g.shape
