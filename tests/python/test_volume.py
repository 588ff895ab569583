"""lancer.read_volume and Volume.probe against the closed form of the gmsh-made cube's linear fields
(f = x + 2y + 3z at nodes, u = (0.1 x, 0.2 y, 0) at element nodes), and the errors they raise."""
import os

import numpy as np
import pytest

import lancer

CUBE = os.path.join(os.path.dirname(__file__), "..", "data", "element_node", "tet_v41_bin.msh")


def test_probe_gives_the_linear_field_inside_the_cube():
    volume = lancer.read_volume(CUBE)
    assert volume.cells == 101
    assert set(volume.fields) == {"f", "g", "jump", "jumpe", "u"}
    rng = np.random.default_rng(5)
    points = rng.uniform(0.01, 0.99, size=(50, 3))
    f = volume.probe(points, "f")
    assert f.shape == (50, 1)
    np.testing.assert_allclose(f[:, 0], points @ [1, 2, 3], atol=2e-6)
    g1 = volume.probe(points, "g", step=1)
    np.testing.assert_allclose(g1[:, 0], 2 * (points @ [1, 2, 3]), atol=4e-6)
    u = volume.probe(points[0], "u")
    assert u.shape == (1, 3)
    np.testing.assert_allclose(u[0], [0.1 * points[0, 0], 0.2 * points[0, 1], 0], atol=1e-7)


def test_probe_says_what_is_wrong():
    volume = lancer.read_volume(CUBE)
    with pytest.raises(lancer.InputError, match="inside no volume element"):
        volume.probe([2, 0, 0], "f")
    with pytest.raises(lancer.InputError, match="no field 'nope'"):
        volume.probe([0.5, 0.5, 0.5], "nope")
    with pytest.raises(lancer.InputError, match="no step 3 of 'g'"):
        volume.probe([0.5, 0.5, 0.5], "g", step=3)
    with pytest.raises(ValueError, match=r"\(N, 3\)"):
        volume.probe([[0.5, 0.5]], "f")
    with pytest.raises(lancer.InputError):
        lancer.read_volume(os.path.join(os.path.dirname(CUBE), "missing.msh"))
