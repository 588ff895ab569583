"""STL, OBJ and PLY from Python: lancer.read_msh opens them as the command line does (the mesh
door picks the reader by content), with groups from STL solids and OBJ groups, PLY vertex
properties as fields, and a broken file raising lancer.InputError with its line."""

import numpy as np
import pytest

import lancer
from conftest import data

SURFACE = data("tests", "data", "surface")


def test_stl_solids_are_groups():
    mesh = lancer.read_msh(str(SURFACE / "box_groups.stl"))
    assert sorted(mesh.group_names.values()) == ["bottom", "walls"]
    assert set(np.unique(mesh.groups)) == set(mesh.group_names)
    assert len(mesh.points) == len(mesh.faces) // 2 + 2  # one closed surface, corners welded


def test_a_ply_property_is_a_field_and_colours_the_picture():
    mesh = lancer.read_msh(str(SURFACE / "plate_temperature_bin.ply"))
    assert "temperature" in mesh.fields
    temperature = mesh.field("temperature")
    assert temperature.shape == (len(mesh.points), 1)
    image = np.asarray(lancer.render(lancer.Scene.quick_look(mesh, color_by="temperature"), width=32, height=24))
    assert image.shape == (24, 32, 3)


def test_an_obj_index_out_of_range_raises_input_error(tmp_path):
    path = tmp_path / "part.obj"
    path.write_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n")
    with pytest.raises(lancer.InputError) as error:
        lancer.read_msh(str(path))
    assert str(error.value) == f"{path}:4:7: error: vertex index 4 is out of range: the file defines 3 vertices"
    assert error.value.line == 4
