"""List-based .pos views from Python: lancer.read_msh reads one as a mesh, and puts views on a mesh
(views=), as the command line does (GetDP's magnet demo, tests/data/pos/magnet/)."""

import numpy as np
import pytest

import lancer
from conftest import data

MAGNET = data("tests", "data", "pos", "magnet")


def test_a_view_alone_is_a_mesh_with_its_field():
    mesh = lancer.read_msh(str(MAGNET / "az.pos"))
    assert len(mesh.faces) == 279
    az = mesh.field("az")
    assert az.shape == (279, 4, 1)
    assert np.isfinite(az[:, :3]).all()


def test_views_go_on_a_mesh_with_the_values_the_cli_reads():
    mesh = lancer.read_msh(str(MAGNET / "magnet.msh"), views=[str(MAGNET / "az.pos"), str(MAGNET / "b_a.pos")])
    assert "az" in mesh.fields and "b" in mesh.fields
    b = mesh.field("b")
    assert b.shape == (279, 4, 3)
    assert np.isfinite(b[:, :3]).all()
    # The same views read alone give the same values at the same corners (one element per face).
    alone = lancer.read_msh(str(MAGNET / "b_a.pos"))
    assert np.array_equal(np.sort(b[:, :3].ravel()), np.sort(alone.field("b")[:, :3].ravel()))
    image = np.asarray(lancer.render(lancer.Scene.quick_look(mesh, color_by="b"), width=32, height=24))
    assert image.shape[:2] == (24, 32)


def test_a_view_on_another_mesh_raises_the_clis_message():
    with pytest.raises(lancer.InputError, match='view "T" matches no face of .*magnet.msh'):
        lancer.read_msh(str(MAGNET / "magnet.msh"), views=[str(data("tests", "data", "pos", "heat", "t.pos"))])
