"""lancer.from_gmsh: a live gmsh model gives the mesh (and the image) its .msh file gives."""

import subprocess
import sys

import numpy as np
import pytest

import lancer

from conftest import data

import gmsh  # python3-gmsh: CMake checks it is there when the tests are built


@pytest.fixture
def session():
    gmsh.initialize(["lancer-test"], readConfigFiles=False)
    gmsh.option.setNumber("General.Terminal", 0)
    yield gmsh
    gmsh.finalize()


def make_box(dim):
    gmsh.model.add("box")
    gmsh.model.occ.addBox(0, 0, 0, 1, 2, 3)
    gmsh.model.occ.synchronize()
    gmsh.option.setNumber("Mesh.MeshSizeMax", 0.5)
    if dim == 2:
        gmsh.model.addPhysicalGroup(2, [1, 2], 7)
        gmsh.model.setPhysicalName(2, 7, "ends")
        gmsh.model.addPhysicalGroup(2, [3, 4, 5, 6], 8)
    else:
        gmsh.model.addPhysicalGroup(3, [1], 1)
        gmsh.model.setPhysicalName(3, 1, "solid")
    gmsh.model.mesh.generate(dim)


@pytest.mark.parametrize("dim", [2, 3])
def test_live_model_is_its_file(session, tmp_path, dim):
    make_box(dim)
    live = lancer.from_gmsh(dim=dim)
    path = tmp_path / "box.msh"
    gmsh.option.setNumber("Mesh.Binary", 1)  # the coordinates exactly (text keeps 16 digits)
    gmsh.write(str(path))
    saved = lancer.read_msh(str(path))
    assert live.faces.shape == saved.faces.shape and live.faces.shape[0] > 0
    assert np.array_equal(live.faces, saved.faces)
    assert np.array_equal(live.points, saved.points)
    assert np.array_equal(live.groups, saved.groups)
    assert live.group_names == saved.group_names
    assert np.array_equal(lancer.render(live, width=48, height=36), lancer.render(saved, width=48, height=36))


def box_with_height_view():
    """The meshed box with a view "height" of node data (each node's z), read by from_gmsh."""
    make_box(2)
    tags, coords, _ = gmsh.model.mesh.getNodes()
    view = gmsh.view.add("height")
    gmsh.view.addModelData(view, 0, "box", "NodeData", list(tags), [[z] for z in coords[2::3]])
    return lancer.from_gmsh()


def test_view_node_data_becomes_a_field(session):
    mesh = box_with_height_view()
    assert mesh.fields == ["height"]
    # The world z of every vertex (float32, as lancer keeps field values).
    assert np.allclose(mesh.field("height")[:, 0], mesh.points[:, 2], atol=1e-5)
    with pytest.raises(KeyError, match="no field 'pressure'; its fields: 'height'"):
        mesh.field("pressure")


def surface_tag_data(dim):
    """An ElementData view giving each element of the model the tag of the entity that holds it."""
    view = gmsh.view.add("entity")
    tags, values = [], []
    for entity_dim, entity in gmsh.model.getEntities(dim):
        for element_tags in gmsh.model.mesh.getElements(entity_dim, entity)[1]:
            tags += list(element_tags)
            values += [[float(entity)]] * len(element_tags)
    gmsh.view.addModelData(view, 0, "box", "ElementData", tags, values)
    return view


def test_a_volume_model_keeps_its_volume_and_its_node_fields(session):
    make_box(3)
    tags, coords, _ = gmsh.model.mesh.getNodes()
    view = gmsh.view.add("height")
    gmsh.view.addModelData(view, 0, "box", "NodeData", list(tags), [[z] for z in coords[2::3]])
    mesh = lancer.from_gmsh(dim=3)
    assert mesh.volume is not None and mesh.volume.cells > 0
    inside = np.array([[0.5, 1.0, 1.5], [0.2, 0.3, 2.9], [0.9, 1.9, 0.1]])
    np.testing.assert_allclose(mesh.probe(inside, "height")[:, 0], inside[:, 2], atol=1e-5)
    with pytest.raises(lancer.InputError, match="inside no volume element"):
        mesh.probe([2.0, 1.0, 1.0], "height")


def test_view_element_data_becomes_a_face_field(session):
    make_box(2)
    surface_tag_data(2)
    mesh = lancer.from_gmsh()
    assert mesh.fields == ["entity"]
    values = mesh.field("entity")
    assert values.shape == (len(mesh.faces), 1)
    assert np.array_equal(values[:, 0], mesh.entities.astype(np.float32))  # each face its element's value


@pytest.mark.parametrize("dim", [2, 3])
def test_view_fields_are_the_files_fields(session, tmp_path, dim):
    """A model with a node view and an element view gives from_gmsh the fields the .msh reader
    gives when gmsh saves the mesh and appends the views ($NodeData, $ElementData)."""
    make_box(dim)
    tags, coords, _ = gmsh.model.mesh.getNodes()
    height = gmsh.view.add("height")
    gmsh.view.addModelData(height, 0, "box", "NodeData", list(tags), [[z] for z in coords[2::3]])
    entity = surface_tag_data(dim)
    path = tmp_path / "box.msh"
    gmsh.option.setNumber("Mesh.Binary", 1)
    gmsh.write(str(path))
    gmsh.view.write(height, str(path), append=True)
    gmsh.view.write(entity, str(path), append=True)
    live, saved = lancer.from_gmsh(dim=dim), lancer.read_msh(str(path))
    assert live.fields == saved.fields == ["height", "entity"]
    for name in live.fields:
        assert np.array_equal(live.field(name), saved.field(name), equal_nan=True), name
    assert not np.any(np.isnan(live.field("entity")))  # every face came from an element the view names


def test_bad_element_field_arrays_are_value_errors():
    points = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0]], dtype=float)
    block = (2, 2, 0, 1, np.array([0, 1, 2]), np.array([5]))
    make = lancer._lancer._mesh_from_elements
    mesh = make(points, [block], {}, "t", [], [("p", 1, np.array([5]), np.array([2.5]))])
    assert mesh.field("p")[0, 0] == 2.5
    unnamed = make(points, [block], {}, "t", [], [("p", 1, np.array([6]), np.array([2.5]))])
    assert np.isnan(unnamed.field("p")[0, 0])  # no record names the element: no value
    with pytest.raises(ValueError, match="element field 'p' has 2 values for 1 elements of 1 components"):
        make(points, [block], {}, "t", [], [("p", 1, np.array([5]), np.array([1.0, 2.0]))])
    with pytest.raises(ValueError, match="element field 'p' has an infinite value for element 5"):
        make(points, [block], {}, "t", [], [("p", 1, np.array([5]), np.array([np.inf]))])
    with pytest.raises(ValueError, match="element tags holds -1"):
        make(points, [(2, 2, 0, 1, np.array([0, 1, 2]), np.array([-1]))], {}, "t", [], [])
    with pytest.raises(ValueError, match="2 element tags for 1 type-2 elements"):
        make(points, [(2, 2, 0, 1, np.array([0, 1, 2]), np.array([1, 2]))], {}, "t", [], [])
    with pytest.raises(ValueError, match="node field 'h' has an infinite value at node index 1"):
        make(points, [block], {}, "t", [("h", 1, np.array([0.0, np.inf, 1.0]))], [])


def test_without_a_mesh(session):
    gmsh.model.add("empty")
    gmsh.model.occ.addBox(0, 0, 0, 1, 1, 1)
    gmsh.model.occ.synchronize()
    with pytest.raises(ValueError, match=r"no mesh nodes: call gmsh.model.mesh.generate\(2\)"):
        lancer.from_gmsh()
    with pytest.raises(ValueError, match="dim=4"):
        lancer.from_gmsh(dim=4)


def test_gmsh_is_not_imported_by_import_lancer():
    import subprocess
    import sys

    code = "import sys, lancer; print('gmsh' in sys.modules)"
    result = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert result.stdout.strip() == "False"


def test_a_field_from_gmsh_colours_the_quick_look(session):
    mesh = box_with_height_view()
    plain = lancer.render(lancer.Scene.quick_look(mesh), width=64, height=48)
    coloured = lancer.render(lancer.Scene.quick_look(mesh, color_by="height", color_map="magma"),
                             width=64, height=48)
    assert coloured.shape == plain.shape
    assert np.count_nonzero(np.any(coloured != plain, axis=2)) > 200  # the faces took the map's colours
    # A fixed range gives another picture than the field's own range.
    ranged = lancer.render(lancer.Scene.quick_look(mesh, color_by="height", color_map="magma",
                                                   color_range=(-10.0, 10.0)), width=64, height=48)
    assert np.any(ranged != coloured)
    with pytest.raises(lancer.InputError, match="height"):  # names the fields the mesh has
        lancer.render(lancer.Scene.quick_look(mesh, color_by="temperature"), width=16, height=12)
    with pytest.raises(ValueError,
                       match=r"color_map='rainbw': \"rainbw\" is not a colour map \(did you mean 'rainbow'"):
        lancer.Scene.quick_look(mesh, color_by="height", color_map="rainbw")
    with pytest.raises(ValueError, match="color_range"):
        lancer.Scene.quick_look(mesh, color_by="height", color_range=(1.0, 1.0))


def test_element_node_data_is_what_the_file_gives(session):
    # gmsh opens the .msh with its views (scripts/make_element_node_fixtures.py): $ElementNodeData
    # read through gmsh's API must be the reader's, corner for corner.
    path = str(data("tests", "data", "element_node", "tet_v41_bin.msh"))
    gmsh.open(path)
    live, read = lancer.from_gmsh(dim=3), lancer.read_msh(path)
    for name in ("g", "jump", "u"):
        assert live.field(name).shape == read.field(name).shape
        assert np.allclose(live.field(name), read.field(name), equal_nan=True)
    assert live.steps("g") == [(0, 0.0), (1, 0.5)]


def test_list_based_views_are_the_pos_files_on_the_mesh(tmp_path):
    # GetDP's magnet results merged into gmsh as list-based views: from_gmsh reads them through
    # gmsh.view.getListData and puts them on the mesh as read_msh(views=[...]) puts the files, value
    # for value. In a subprocess: gmsh's API aborts the process on getModelData of a list-based view
    # unless General.AbortOnError is 0, which from_gmsh sets around its calls and restores.
    folder = data("tests", "data", "pos", "magnet")
    script = tmp_path / "merge.py"
    script.write_text(f"""
import warnings
import numpy as np
import gmsh
import lancer
gmsh.initialize(["gmsh", "-v", "0"])
gmsh.open({str(folder / "magnet.msh")!r})
gmsh.merge({str(folder / "az.pos")!r})
gmsh.merge({str(folder / "b_a.pos")!r})
with warnings.catch_warnings(record=True) as caught:
    warnings.simplefilter("always")
    live = lancer.from_gmsh()
read = lancer.read_msh({str(folder / "magnet.msh")!r}, views=[{str(folder / "az.pos")!r}, {str(folder / "b_a.pos")!r}])
print(len(caught), sorted(live.fields) == sorted(read.fields), gmsh.option.getNumber("General.AbortOnError"))
for name in read.fields:
    print(name, live.field(name).shape == read.field(name).shape,
          bool(np.array_equal(live.field(name), read.field(name), equal_nan=True)))
# A list-based view away from the mesh: the error `lancer render magnet.msh far.pos` gives.
gmsh.view.addListData(gmsh.view.add("far"), "ST", 1, [10, 11, 10, 0, 0, 1, 0, 0, 0, 1, 2, 3])
try:
    lancer.from_gmsh()
except lancer.InputError as error:
    print("refused", 'view "far" matches no face of' in str(error))
""")
    result = subprocess.run([sys.executable, str(script)], capture_output=True, text=True)
    assert result.returncode == 0, result.stderr
    lines = result.stdout.splitlines()
    assert lines[0].split() == ["0", "True", "2.0"]
    assert sorted(line.split()[0] for line in lines[1:-1]) == ["az", "b"]
    assert all(line.split()[1:] == ["True", "True"] for line in lines[1:-1]), lines
    assert lines[-1] == "refused True"
