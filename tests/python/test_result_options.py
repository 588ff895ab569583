"""lancer.render's result keywords are the command line's options: color_map=, range=, log=/scale=,
legend=, isolines=, bands=, arrows= and clip= give the picture --color-map, --range, --log, --legend,
--isolines, --bands, --arrows and --clip give, and are refused with the same messages."""

import numpy as np
import pytest

import lancer

from conftest import cli_image, data

SQUARE = str(data("tests", "data", "fields", "node_xy_v41_bin.msh"))
VECTORS = str(data("tests", "data", "fields", "element_vector_v41_bin.msh"))
SIZE = {"width": 96, "height": 64}


def test_result_keywords_match_the_cli(tmp_path):
    scene = lancer.Scene.quick_look(lancer.read_msh(SQUARE), color_by="temperature")
    image = np.asarray(lancer.render(scene, color_map="RdBu", range=(0.03, 3), log=True, legend="right",
                                     isolines=4, bands=6, clip="x=0.8", **SIZE))
    expected = cli_image(tmp_path, SQUARE, "--color-by", "temperature", "--color-map", "RdBu", "--range", "0.03:3",
                         "--log", "--legend", "right", "--isolines", 4, "--bands", 6, "--clip", "x=0.8")
    assert np.array_equal(image, expected)
    # scale="log" is log=True; a list of planes is --clip given twice.
    assert np.array_equal(image, np.asarray(lancer.render(scene, color_map="RdBu", range=(0.03, 3), scale="log",
                                                          legend="right", isolines=4, bands=6, clip=["x=0.8"],
                                                          **SIZE)))
    two = np.asarray(lancer.render(scene, clip=["x=0.8", "0,0.5,0,0,1,0"], **SIZE))
    assert np.array_equal(two, cli_image(tmp_path, SQUARE, "--color-by", "temperature", "--clip", "x=0.8", "--clip",
                                         "0,0.5,0,0,1,0"))
    assert not np.array_equal(image, np.asarray(lancer.render(scene, **SIZE)))


@pytest.mark.filterwarnings("ignore:.*gives values for 4 elements")  # the fixture's boundary lines
def test_arrows_of_element_data_match_the_cli(tmp_path):
    image = np.asarray(lancer.render(lancer.read_msh(VECTORS), arrows="temperature", **SIZE))
    assert np.array_equal(image, cli_image(tmp_path, VECTORS, "--arrows", "temperature"))


def test_result_keywords_bad_input():
    mesh = lancer.read_msh(SQUARE)
    coloured = lancer.Scene.quick_look(mesh, color_by="temperature")
    with pytest.raises(lancer.InputError, match=r"range must have min < max, found \[1, 0\]"):
        lancer.render(coloured, range=(1, 0), **SIZE)
    with pytest.raises(lancer.InputError, match=r"range must have min > 0 with scale = \"log\""):
        lancer.render(coloured, range=(0, 3), log=True, **SIZE)
    with pytest.raises(lancer.InputError, match=r"^log: error: color_by field \"temperature\" in .* has values down "
                                                r"to 0 .*but log needs values > 0: .*range=\(0.003, 3\)"):
        lancer.render(coloured, log=True, **SIZE)
    with pytest.raises(lancer.InputError, match="bands 0 is not a number of colour bands from 1 to"):
        lancer.render(coloured, bands=0, **SIZE)
    with pytest.raises(lancer.InputError, match="isolines 0 is not a number of isolines from 1 to 1000"):
        lancer.render(coloured, isolines=0, **SIZE)
    with pytest.raises(lancer.InputError, match="'x=y' is not a cutting plane: use AXIS=VALUE"):
        lancer.render(coloured, clip="x=y", **SIZE)
    with pytest.raises(lancer.InputError, match="a cutting plane needs a finite point and a normal other"):
        lancer.render(coloured, clip="0,0,0,0,0,0", **SIZE)
    with pytest.raises(lancer.InputError, match="arrows field \"nothing\" is not in"):
        lancer.render(coloured, arrows="nothing", **SIZE)
    with pytest.raises(lancer.InputError, match="arrows field \"temperature\" must be a vector of 3 components"):
        lancer.render(coloured, arrows="temperature", **SIZE)
    with pytest.raises(lancer.InputError, match="range goes with a field's colours, and no mesh is coloured: colour "
                                                "it with Scene.quick_look"):
        lancer.render(mesh, range=(0, 1), **SIZE)
    with pytest.raises(lancer.InputError, match="log goes with a field's colours"):
        lancer.render(mesh, log=True, **SIZE)
    with pytest.raises(ValueError, match="legend='left': use 'right', 'bottom' or 'none'"):
        lancer.render(coloured, legend="left", **SIZE)
    with pytest.raises(ValueError, match="color_map='virdis'.*did you mean 'viridis'"):
        lancer.render(coloured, color_map="virdis", **SIZE)
    with pytest.raises(ValueError, match="scale='ln': use 'linear' or 'log'"):
        lancer.render(coloured, scale="ln", **SIZE)
    with pytest.raises(ValueError, match="log and scale disagree"):
        lancer.render(coloured, log=True, scale="linear", **SIZE)
    with pytest.raises(TypeError, match="clip= takes a plane as text"):
        lancer.render(coloured, clip=3, **SIZE)
    with pytest.raises(TypeError):
        lancer.render(coloured, range="0:1", **SIZE)
    with pytest.raises(ValueError, match="legend='left'"):
        lancer.animate(coloured, "x.gif", legend="left", frames=2, **SIZE)


def test_quick_look_bands_and_log_are_renders(tmp_path):
    mesh = lancer.read_msh(SQUARE)
    scene = lancer.Scene.quick_look(mesh, color_by="temperature", color_range=(0.03, 3), bands=6, log=True)
    image = np.asarray(lancer.render(scene, **SIZE))
    plain = lancer.Scene.quick_look(mesh, color_by="temperature", color_range=(0.03, 3))
    assert np.array_equal(image, np.asarray(lancer.render(plain, bands=6, log=True, **SIZE)))
    assert np.array_equal(image, cli_image(tmp_path, SQUARE, "--color-by", "temperature", "--range", "0.03:3",
                                           "--log", "--bands", 6))
    assert np.array_equal(image, np.asarray(lancer.render(
        lancer.Scene.quick_look(mesh, color_by="temperature", color_range=(0.03, 3), bands=6, scale="log"), **SIZE)))
    assert not np.array_equal(image, np.asarray(lancer.render(plain, **SIZE)))
    # Each on its own changes the picture.
    banded = np.asarray(lancer.render(lancer.Scene.quick_look(mesh, color_by="temperature", bands=4), **SIZE))
    assert np.array_equal(banded, np.asarray(lancer.render(
        lancer.Scene.quick_look(mesh, color_by="temperature"), bands=4, **SIZE)))


def test_quick_look_bands_and_log_bad_input():
    mesh = lancer.read_msh(SQUARE)
    with pytest.raises(lancer.InputError, match="^bands: error: bands 0 is not a number of colour bands from 1 to"):
        lancer.Scene.quick_look(mesh, color_by="temperature", bands=0)
    with pytest.raises(lancer.InputError, match="bands goes with a field's colours, and no mesh is coloured"):
        lancer.Scene.quick_look(mesh, bands=4)
    with pytest.raises(lancer.InputError, match="log goes with a field's colours"):
        lancer.Scene.quick_look(mesh, log=True)
    with pytest.raises(ValueError, match="scale='ln': use 'linear' or 'log'"):
        lancer.Scene.quick_look(mesh, color_by="temperature", scale="ln")
    with pytest.raises(ValueError, match="log and scale disagree"):
        lancer.Scene.quick_look(mesh, color_by="temperature", log=True, scale="linear")
    # Values down to 0 on a log scale: refused when the picture is made, as render(log=True) is.
    scene = lancer.Scene.quick_look(mesh, color_by="temperature", log=True)
    with pytest.raises(lancer.InputError, match=r"^log: error: color_by field \"temperature\" in .* has values down "
                                                r"to 0 .*but log needs values > 0"):
        lancer.render(scene, **SIZE)
    # The same message as render(log=True) gives the same scene.
    ranged = {"color_by": "temperature", "color_range": (0, 3)}
    with pytest.raises(lancer.InputError) as from_quick_look:
        lancer.render(lancer.Scene.quick_look(mesh, log=True, **ranged), **SIZE)
    with pytest.raises(lancer.InputError) as from_render:
        lancer.render(lancer.Scene.quick_look(mesh, **ranged), log=True, **SIZE)
    assert str(from_quick_look.value) == str(from_render.value)
