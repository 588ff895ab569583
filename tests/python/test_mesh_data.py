"""lancer.Mesh(points, cells, point_data, cell_data) in meshio's names: fields from numpy arrays are
the fields a .msh file gives (color_by, warp, isolines, arrows, legends, steps draw the same
picture), meshio's cell blocks and volume cells are taken, and bad arrays are refused naming the
argument (TypeError: not the kind of thing; lancer.InputError, a ValueError: wrong shape or value)."""

import numpy as np
import pytest

import lancer

from conftest import data

CANTILEVER = str(data("tests", "data", "results", "cantilever.msh"))

# A unit square in two triangles, and a 2 x 1 strip of quads.
SQUARE = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]], dtype=float)
TRIANGLES = np.array([[0, 1, 2], [0, 2, 3]])


def arrays_of(mesh):
    """The cantilever's fields as meshio-style data: node fields per point, element fields per face,
    every step, with their times."""
    point_data, cell_data, times = {}, {}, None
    for name in mesh.fields:
        steps = mesh.steps(name)
        values = np.stack([mesh.field(name, step=s) for s, _ in steps])
        times = [t for _, t in steps] if len(steps) > 1 else times
        (point_data if values.shape[1] == len(mesh.points) else cell_data)[name] = values
    return point_data, cell_data, times


@pytest.mark.filterwarnings("ignore:.*isolines of element data")
def test_fields_from_arrays_draw_what_the_file_draws():
    mesh = lancer.read_msh(CANTILEVER)
    point_data, cell_data, times = arrays_of(mesh)
    assert point_data and cell_data and times  # node and element fields, several steps
    again = lancer.Mesh(mesh.points, mesh.faces, point_data=point_data, cell_data=cell_data, times=times,
                        groups=mesh.groups, group_names=mesh.group_names)
    assert again.fields == mesh.fields
    for name in mesh.fields:
        assert again.steps(name) == mesh.steps(name)
    looks = [dict(color_by="stress", component="von_mises", warp=("displacement", 2.0), undeformed="edges",
                  step=3, legend="right"),
             dict(color_by="temperature", isolines={"field": "temperature", "count": 6},
                  arrows={"field": "displacement", "max_count": 40})]
    for look in looks:
        expected = lancer.render(lancer.Scene.quick_look(mesh, **look), width=96, height=64)
        actual = lancer.render(lancer.Scene.quick_look(again, **look), width=96, height=64)
        assert np.array_equal(np.asarray(actual), np.asarray(expected)), look


def test_steps_as_a_list_or_an_array_and_their_times():
    values = np.array([[0.0, 1, 2, 3], [3, 2, 1, 0]])
    as_array = lancer.Mesh(SQUARE, TRIANGLES, point_data={"T": values}, times=[0.5, 1.5])
    as_list = lancer.Mesh(SQUARE, TRIANGLES, point_data={"T": list(values)})
    assert as_array.steps("T") == [(0, 0.5), (1, 1.5)]
    assert as_list.steps("T") == [(0, 0.0), (1, 1.0)]
    assert np.array_equal(as_list.field("T", step=1)[:, 0], values[1])


def test_vectors_tensors_and_2d_vectors():
    mesh = lancer.Mesh(SQUARE, TRIANGLES, point_data={"u": np.ones((4, 2)), "s": np.ones((4, 3, 3))},
                       cell_data={"J": [np.array([[1.0, 0, 0], [0, 2, 0]])]})
    assert mesh.field("u").shape == (4, 3) and np.all(mesh.field("u")[:, 2] == 0)
    assert mesh.field("s").shape == (4, 9)
    assert mesh.field("J").tolist() == [[1, 0, 0], [0, 2, 0]]


def test_meshio_cell_blocks_and_volumes():
    # A unit cube of one hexahedron and the same cube as 6 tetrahedra, side by side; lines skipped.
    cube = np.array([[x, y, z] for z in (0, 1) for y in (0, 1) for x in (0, 1)], dtype=float)
    points = np.concatenate([cube, cube + [2, 0, 0]])
    hexahedron = np.array([[0, 1, 3, 2, 4, 5, 7, 6]])
    tetrahedra = 8 + np.array([[0, 1, 3, 7], [0, 3, 2, 7], [0, 2, 6, 7], [0, 6, 4, 7], [0, 4, 5, 7], [0, 5, 1, 7]])
    lines = np.array([[0, 1]])
    cells = [("line", lines), ("hexahedron", hexahedron), ("tetra", tetrahedra)]
    cell_data = {"k": [np.array([9.0]), np.array([1.0]), np.arange(6.0)],
                 "gmsh:physical": [np.array([0]), np.array([1]), np.full(6, 2)]}
    mesh = lancer.Mesh(points, cells, cell_data=cell_data, group_names={"box": [1, 3], "tets": [2, 3]})
    assert sorted(set(mesh.groups)) == [1, 2]
    assert mesh.group_names == {1: "box", 2: "tets"}
    assert len(mesh.faces[mesh.groups == 1]) == 6  # the hexahedron's skin: six quads
    assert np.all(mesh.field("k")[mesh.groups == 1] == 1)
    as_dict = lancer.Mesh(points, {"hexahedron": hexahedron, "tetra": tetrahedra})
    assert len(as_dict.faces) == len(mesh.faces)
    image = np.asarray(lancer.render(lancer.Scene.quick_look(mesh, color_by="k"), width=48, height=32))
    assert image.std() > 0


class CellBlock:
    """What meshio.CellBlock offers: .type and .data."""

    def __init__(self, kind, data):
        self.type, self.data = kind, data


def test_meshio_cell_block_objects_and_second_order():
    points = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0.5, 0, 0], [0.5, 0.5, 0], [0, 0.5, 0]], dtype=float)
    mesh = lancer.Mesh(points, [CellBlock("triangle6", np.array([[0, 1, 2, 3, 4, 5]]))],
                       point_data={"T": points[:, 0]})
    assert len(mesh.faces) == 4  # a 6-node triangle is drawn as four
    assert mesh.fields == ["T"]


@pytest.mark.parametrize(
    "arguments, error, message",
    [
        (dict(points=SQUARE[:, :2]), lancer.InputError, r"points must be an \(N, 3\).*zero z column"),
        (dict(points=np.where(SQUARE == 1, np.nan, SQUARE)), lancer.InputError, r"points\[1\] is .*finite"),
        (dict(point_data={"T": np.zeros(3)}), lancer.InputError,
         r"point_data\['T'\] has shape \(3,\), but there are 4 points"),
        (dict(point_data={"T": np.zeros((4, 4))}), lancer.InputError, r"point_data\['T'\] has 4 components"),
        (dict(point_data={"T": np.array(["a"] * 4)}), lancer.InputError, r"point_data\['T'\] must hold numbers"),
        (dict(point_data={"T": [np.zeros(4), np.zeros((4, 3))]}), lancer.InputError, "every step of a field"),
        (dict(point_data={"T": np.array([0, np.inf, 0, 0])}), lancer.InputError, r"point_data\['T'\]\[1\] is infinite"),
        (dict(point_data={"T": np.zeros((2, 4))}, times=[0.0]), lancer.InputError, "times gives 1 times"),
        (dict(point_data=np.zeros(4)), TypeError, "point_data must be a dict"),
        (dict(point_data={3: np.zeros(4)}), TypeError, "a field's name is a str"),
        (dict(cell_data={"J": [np.zeros(2), np.zeros(2)]}), lancer.InputError,
         r"cell_data\['J'\] is a list of 2, but cells has 1 block"),
        (dict(cell_data={"J": np.zeros(3)}), lancer.InputError, r"cell_data\['J'\] has shape \(3,\), but there are 2 cells"),
        (dict(cells=np.array([[0, 1, 4]]), point_data={"T": np.zeros(4)}), lancer.InputError,
         r"cells\[0\] uses point 4, but points has 4 rows"),
        (dict(cells={"triangle": np.array([[0, 1, 2], [0, 2, -1]])}), lancer.InputError,
         r"cells\['triangle'\]\[1\] uses point -1"),
        (dict(cells={"triangle": np.array([[0, 1, 2, 3]])}), lancer.InputError,
         r"cells\['triangle'\] must be an \(m, 3\) array"),
        (dict(cells={"polygon": np.array([[0, 1, 2, 3]])}), lancer.InputError, "does not take meshio's 'polygon'"),
        (dict(cells={"triangle": TRIANGLES.astype(float)}), lancer.InputError, "must hold integers"),
        (dict(cells=7), lancer.InputError, "cells must be an"),
        (dict(cells="triangle"), TypeError, "cells must be an array"),
        (dict(cells={"triangle": TRIANGLES}, groups=[1, 2, 3]), lancer.InputError, r"groups must be an \(2,\) array"),
        (dict(cells={"triangle": TRIANGLES}, groups=[1, -2]), lancer.InputError, r"groups\[1\] is -2"),
        (dict(cells={"triangle": TRIANGLES}, group_names={"one": 1}), lancer.InputError,
         "group_names must map integer tags to strings"),
        (dict(point_data={"T": np.zeros(4)}, cell_data={"T": np.zeros(2)}), lancer.InputError,
         "both have a field 'T'"),
    ],
)
def test_bad_arrays_name_the_argument(arguments, error, message):
    arguments = {"points": SQUARE, "cells": TRIANGLES, **arguments}
    with pytest.raises(error, match=message) as raised:
        lancer.Mesh(**arguments)
    if error is lancer.InputError:
        assert raised.value.file == "lancer.Mesh" and str(raised.value).startswith("lancer.Mesh: error: ")


def test_nan_is_no_value_and_the_array_form_keeps_its_errors():
    mesh = lancer.Mesh(SQUARE, TRIANGLES, point_data={"T": np.array([0, np.nan, 1, 2])})
    assert np.isnan(mesh.field("T")[1, 0])
    with pytest.raises(lancer.InputError, match=r"cells\[0\] uses point 4"):
        lancer.Mesh(SQUARE, np.array([[0, 1, 4]]))
    assert issubclass(lancer.InputError, ValueError)
