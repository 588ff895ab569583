"""Arrows through the volume from Python: render's and quick_look's arrows= take a dict of the scene
file's keys, grid included, and draw what --arrows FIELD --arrow-grid NX,NY,NZ draws, byte for byte;
bad grids and scalar fields are refused with the scene keys' messages."""

import numpy as np
import pytest

import lancer

from conftest import cli_image, data

HEXAHEDRA = str(data("tests", "data", "volume", "cube_hex.msh"))
SIZE = {"width": 64, "height": 64}


def test_grid_arrows_match_the_cli(tmp_path):
    mesh = lancer.read_msh(HEXAHEDRA)
    expected = cli_image(tmp_path, HEXAHEDRA, "--arrows", "u", "--arrow-grid", "3,3,2", **SIZE)
    arrows = {"field": "u", "grid": [3, 3, 2]}
    rendered = np.asarray(lancer.render(lancer.Scene.quick_look(mesh), arrows=arrows, **SIZE))
    assert np.array_equal(rendered, expected)
    keyword = np.asarray(lancer.render(lancer.Scene.quick_look(mesh, arrows=arrows), **SIZE))
    assert np.array_equal(keyword, expected)
    # The skin alone differs: the arrows are drawn.
    assert not np.array_equal(np.asarray(lancer.render(lancer.Scene.quick_look(mesh), **SIZE)), expected)


def test_bad_grids_and_scalar_fields(tmp_path):
    scene = lancer.Scene.quick_look(lancer.read_msh(HEXAHEDRA))
    with pytest.raises(lancer.InputError, match=r"arrows\.grid\[0\] must be an integer from 1 to 100000"):
        lancer.render(scene, arrows={"field": "u", "grid": [0, 2, 2]}, **SIZE)
    with pytest.raises(lancer.InputError, match="more than the 100000 arrows a mesh may have"):
        lancer.render(scene, arrows={"field": "u", "grid": [1000, 1000, 1000]}, **SIZE)
    with pytest.raises(lancer.InputError, match="must be a vector of 3 components"):
        lancer.render(scene, arrows={"field": "f", "grid": [2, 2, 2]}, **SIZE)
    with pytest.raises(ValueError, match="give the name of a vector field"):
        lancer.render(scene, arrows="", **SIZE)
