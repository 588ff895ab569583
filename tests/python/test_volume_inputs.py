"""Inside the volume of a list-based .pos view and of a lancer.Mesh made from arrays of tetrahedra
and hexahedra: probes equal the closed form of a linear field, slices and isosurfaces render, and bad
arrays raise lancer.InputError as the array path does for every cell type."""
import os

import numpy as np
import pytest

import lancer

DATA = os.path.join(os.path.dirname(__file__), "..", "data", "pos", "volume")
CUBE_POS = os.path.join(DATA, "cube.pos")  # gmsh-made views f = x + 2y + 3z (two steps), u = (1, 2, 3)
CUBE_MSH = os.path.join(DATA, "cube.msh")


def grid(n):
    """The unit cube's (n+1)^3 grid points and its n^3 cubes as hexahedra (gmsh's corner order)."""
    axis = np.linspace(0, 1, n + 1)
    z, y, x = np.meshgrid(axis, axis, axis, indexing="ij")
    points = np.c_[x.ravel(), y.ravel(), z.ravel()]
    node = lambda i, j, k: (k * (n + 1) + j) * (n + 1) + i  # noqa: E731
    hexes = [[node(i, j, k), node(i + 1, j, k), node(i + 1, j + 1, k), node(i, j + 1, k),
              node(i, j, k + 1), node(i + 1, j, k + 1), node(i + 1, j + 1, k + 1), node(i, j + 1, k + 1)]
             for k in range(n) for j in range(n) for i in range(n)]
    return points, np.array(hexes)


def tetrahedra(hexes):
    """Each hexahedron as the six tetrahedra around its diagonal 0-6 (Kuhn's split: conforming)."""
    paths = [(1, 2), (1, 5), (3, 2), (3, 7), (4, 5), (4, 7)]
    return np.array([[h[0], h[a], h[b], h[6]] for h in hexes for a, b in paths])


def linear(points):
    return points @ np.array([1.0, 2.0, 3.0])


def test_a_pos_view_is_a_volume():
    volume = lancer.read_volume(CUBE_POS)
    assert volume.cells == 184
    assert volume.fields == ["f", "u"]
    points = np.random.default_rng(3).uniform(0.01, 0.99, size=(40, 3))
    np.testing.assert_allclose(volume.probe(points, "f")[:, 0], linear(points), atol=4e-6)
    np.testing.assert_allclose(volume.probe(points, "f", step=1)[:, 0], linear(points) + 10, atol=4e-6)
    on_mesh = lancer.read_volume(CUBE_MSH, views=[CUBE_POS])
    np.testing.assert_allclose(on_mesh.probe(points, "u"), np.tile([1, 2, 3], (40, 1)), atol=1e-6)
    mesh = lancer.read_msh(CUBE_MSH, views=[CUBE_POS])
    np.testing.assert_allclose(mesh.probe(points[:3], "f")[:, 0], linear(points[:3]), atol=4e-6)
    image = lancer.render(lancer.Scene.quick_look(mesh, color_by="f"), slices="z=0.3",
                          isosurfaces={"field": "f", "values": [3]}, width=48, height=36, samples=1)
    assert image.shape == (36, 48, 3)


@pytest.mark.parametrize("kind", ["tetra", "hexahedron"])
def test_a_mesh_from_arrays_keeps_its_volume(kind):
    points, hexes = grid(3)
    cells = tetrahedra(hexes) if kind == "tetra" else hexes
    f = linear(points)
    mesh = lancer.Mesh(points, {kind: cells}, point_data={"f": f, "u": np.tile([1.0, 2.0, 3.0], (len(points), 1))},
                       cell_data={"c": np.arange(len(cells), dtype=float)})
    assert mesh.volume.cells == len(cells)
    assert set(mesh.volume.fields) == {"f", "u", "c"}
    inside = np.random.default_rng(4).uniform(0.01, 0.99, size=(30, 3))
    # Linear on each tetrahedron: exact there, and on the hexahedra's tetrahedra (their centre the mean).
    np.testing.assert_allclose(mesh.probe(inside, "f")[:, 0], linear(inside), atol=4e-6)
    # Element data: the value of the cell that holds the point.
    c = mesh.probe([0.1, 0.1, 0.1], "c")[0, 0]
    assert c == int(c) and 0 <= c < len(cells)
    coloured = lancer.Scene.quick_look(mesh, color_by="f")
    for keywords in ({"slices": "z=0.5"}, {"isosurfaces": "f:2"}, {"streamlines": "u:4"},
                     {"arrows": {"field": "u", "grid": [2, 2, 2]}}):
        image = lancer.render(coloured, width=32, height=24, samples=1, **keywords)
        assert image.shape == (24, 32, 3), keywords
    scene = lancer.Scene()
    scene.add_mesh(mesh, slice=[{"point": [0, 0, 0.5], "normal": [0, 0, 1]}], color_by={"field": "f"})
    assert lancer.render(scene, width=32, height=24, samples=1).shape == (24, 32, 3)
    with pytest.raises(lancer.InputError, match="inside no volume element"):
        mesh.probe([1.5, 0.5, 0.5], "f")


def test_a_mesh_of_faces_has_no_volume():
    points, hexes = grid(1)
    mesh = lancer.Mesh(points, {"quad": hexes[:, :4]})
    assert mesh.volume is None
    with pytest.raises(lancer.InputError, match="has no volume elements"):
        mesh.probe([0.5, 0.5, 0], "f")
    with pytest.raises(lancer.InputError, match="has no volume elements"):
        lancer.render(mesh, slices="z", width=16, height=16)


def test_bad_volume_arrays_say_what_is_wrong():
    points, hexes = grid(1)
    tets = tetrahedra(hexes)
    with pytest.raises(lancer.InputError, match=r"cells\['tetra'\] must be an \(m, 4\) array"):
        lancer.Mesh(points, {"tetra": tets[:, :3]})
    with pytest.raises(lancer.InputError, match=r"must hold integers"):
        lancer.Mesh(points, {"tetra": tets.astype(float)})
    bad = tets.copy()
    bad[2, 1] = 99
    with pytest.raises(lancer.InputError, match=r"cells\['tetra'\]\[2\] uses point 99, but points has 8 rows"):
        lancer.Mesh(points, {"tetra": bad})
    nan_points = points.copy()
    nan_points[5, 0] = np.nan
    with pytest.raises(lancer.InputError, match=r"points\[5\] is \(nan"):
        lancer.Mesh(nan_points, {"tetra": tets})
    with pytest.raises(lancer.InputError, match=r"infinite"):
        lancer.Mesh(points, {"tetra": tets}, point_data={"f": np.full(8, np.inf)})
    with pytest.raises(lancer.InputError, match=r"there are 6 cells"):
        lancer.Mesh(points, {"tetra": tets}, cell_data={"c": np.zeros(5)})
