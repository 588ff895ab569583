#!/usr/bin/python3
"""Meshes a .geo of this folder with gmsh and saves it with analytic node and element fields, or
checks a finished fixture; scripts/make_volume_fixtures.sh runs it.
    volume_fields.py mixed GEO OUT.msh     f = x + 2 y + 3 z and r = |x - (0.5, 0.5, 0.5)| as $NodeData
    volume_fields.py cube_hex GEO OUT.msh  f as $NodeData, g = f at each hexahedron's centroid as
                                           $ElementData, the vectors u = (1, 2, 3) and dipole (the
                                           field of a point dipole below the cube) as $NodeData
    volume_fields.py moving GEO OUT.msh    three steps at times 0, 1, 2 of s = x - t / 4 (its surface
                                           s = 0.25 moves from x = 0.25 to 0.75) and of w, the unit
                                           vector along x turned by 30 degrees a step about z
    volume_fields.py check FILE.msh [FIELD ...]  prints the elements and views gmsh reads from FILE;
                                           fails unless it holds the named fields, each on elements
                                           and nodes of FILE's own mesh
The fields are written by gmsh's API (gmsh.view.addModelData, then gmsh.view.write appending to the
mesh), as a user of gmsh writes results on a mesh. Output is MSH 4.1 ASCII."""
import sys

import gmsh
import numpy as np

# A point dipole p along z, half a unit below the cube's bottom face (z = 0), centred under it:
# the field lines leave the top of the dipole and cross the cube bending back down.
DIPOLE_POSITION = np.array([0.5, 0.5, -0.5])
DIPOLE_MOMENT = np.array([0.0, 0.0, 1.0])
DISTANCE_CENTRE = np.array([0.5, 0.5, 0.5])


def linear_field(points):
    return points[:, 0] + 2 * points[:, 1] + 3 * points[:, 2]


def dipole_field(points):
    """E = (3 (p . r^) r^ - p) / |r|^3, the field of a point dipole p (Jackson, eq. 4.13, without
    the 1 / (4 pi eps0))."""
    offset = points - DIPOLE_POSITION
    distance = np.linalg.norm(offset, axis=1, keepdims=True)
    direction = offset / distance
    return (3 * (direction @ DIPOLE_MOMENT)[:, None] * direction - DIPOLE_MOMENT) / distance**3


def mesh_geo(geo):
    gmsh.option.setNumber("General.NumThreads", 1)
    gmsh.option.setNumber("Mesh.RandomSeed", 1)
    gmsh.open(geo)
    gmsh.model.mesh.generate(3)
    tags, coords, _ = gmsh.model.mesh.getNodes()
    return tags, np.asarray(coords).reshape(-1, 3)


def print_element_counts(label):
    counts = []
    for dim in (2, 3):
        for element_type, tags in zip(*gmsh.model.mesh.getElements(dim)[:2]):
            counts.append(f"{gmsh.model.mesh.getElementProperties(element_type)[0]}: {len(tags)}")
    print(f"{label}: " + ", ".join(counts))


def add_node_field(name, node_tags, values):
    view = gmsh.view.add(name)
    values = values.reshape(len(node_tags), -1)
    gmsh.view.addModelData(view, 0, gmsh.model.getCurrent(), "NodeData", node_tags, values,
                           numComponents=values.shape[1])
    return view


def save_with_views(out, views):
    gmsh.option.setNumber("Mesh.MshFileVersion", 4.1)
    gmsh.option.setNumber("Mesh.Binary", 0)
    gmsh.write(out)
    gmsh.option.setNumber("PostProcessing.SaveMesh", 0)  # the mesh is in the file already
    for view in views:
        gmsh.view.write(view, out, append=True)


def make_mixed(geo, out):
    node_tags, points = mesh_geo(geo)
    views = [add_node_field("f", node_tags, linear_field(points)),
             add_node_field("r", node_tags, np.linalg.norm(points - DISTANCE_CENTRE, axis=1))]
    save_with_views(out, views)


def make_cube_hex(geo, out):
    node_tags, points = mesh_geo(geo)
    hexahedron = gmsh.model.mesh.getElementType("Hexahedron", 1)
    hex_tags, hex_nodes = gmsh.model.mesh.getElementsByType(hexahedron)
    row_of_node = np.empty(int(node_tags.max()) + 1, dtype=np.int64)
    row_of_node[node_tags] = np.arange(len(node_tags))
    centroids = points[row_of_node[np.asarray(hex_nodes, dtype=np.int64)].reshape(-1, 8)].mean(axis=1)
    element_view = gmsh.view.add("g")
    gmsh.view.addModelData(element_view, 0, gmsh.model.getCurrent(), "ElementData", hex_tags,
                           linear_field(centroids).reshape(-1, 1), numComponents=1)
    constant = np.tile([1.0, 2.0, 3.0], (len(node_tags), 1))
    views = [add_node_field("f", node_tags, linear_field(points)), element_view,
             add_node_field("u", node_tags, constant), add_node_field("dipole", node_tags, dipole_field(points))]
    save_with_views(out, views)


def make_moving(geo, out):
    node_tags, points = mesh_geo(geo)
    model = gmsh.model.getCurrent()
    scalar, vector = gmsh.view.add("s"), gmsh.view.add("w")
    for step in range(3):
        gmsh.view.addModelData(scalar, step, model, "NodeData", node_tags,
                               (points[:, 0] - step / 4).reshape(-1, 1), time=float(step), numComponents=1)
        angle = np.radians(30 * step)
        turned = np.tile([np.cos(angle), np.sin(angle), 0.0], (len(node_tags), 1))
        gmsh.view.addModelData(vector, step, model, "NodeData", node_tags, turned, time=float(step),
                               numComponents=3)
    save_with_views(out, [scalar, vector])


def check(path, fields):
    gmsh.open(path)
    print_element_counts(path)
    element_tags = set()
    for dim in (2, 3):
        for tags in gmsh.model.mesh.getElements(dim)[1]:
            element_tags.update(int(tag) for tag in tags)
    node_tags = set(int(tag) for tag in gmsh.model.mesh.getNodes()[0])
    found = {}
    for view in gmsh.view.getTags():
        name = gmsh.option.getString(f"View[{gmsh.view.getIndex(view)}].Name")
        data_type, tags, data, _, components = gmsh.view.getModelData(view, 0)
        owners = node_tags if data_type == "NodeData" else element_tags
        if not set(int(tag) for tag in tags) <= owners:
            sys.exit(f"volume_fields.py: {path}: view {name} names {data_type} owners that are not in its mesh")
        values = np.concatenate([np.asarray(row) for row in data])
        found[name] = data_type
        print(f"  {name}: {data_type}, {components} component(s), {len(tags)} entries, "
              f"values in [{values.min():.6g}, {values.max():.6g}]")
    missing = [field for field in fields if field not in found]
    if missing:
        sys.exit(f"volume_fields.py: {path} lacks the fields {', '.join(missing)} (it has {', '.join(found)})")


def main():
    if len(sys.argv) < 3 or sys.argv[1] not in ("mixed", "cube_hex", "moving", "check"):
        sys.exit(__doc__)
    gmsh.initialize()
    gmsh.option.setNumber("General.Terminal", 0)
    if sys.argv[1] == "check":
        check(sys.argv[2], sys.argv[3:])
    elif sys.argv[1] == "mixed":
        make_mixed(sys.argv[2], sys.argv[3])
    elif sys.argv[1] == "moving":
        make_moving(sys.argv[2], sys.argv[3])
    else:
        make_cube_hex(sys.argv[2], sys.argv[3])
    gmsh.finalize()


if __name__ == "__main__":
    main()
