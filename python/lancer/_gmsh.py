"""lancer.from_gmsh: the current model of a live gmsh session (the `gmsh` Python module) as a
lancer.Mesh, without writing a file. gmsh is imported only when this is called."""

import contextlib

import numpy as np

from . import _lancer


@contextlib.contextmanager
def _errors_raise(gmsh):
    """gmsh's API aborts the process on an error (General.AbortOnError = 2, its default in a script:
    getModelData of a list-based view kills the interpreter); within this, errors raise exceptions,
    and the user's setting comes back after."""
    try:
        saved = gmsh.option.getNumber("General.AbortOnError")
    except Exception:  # a gmsh without the option: nothing to change
        yield
        return
    gmsh.option.setNumber("General.AbortOnError", 0)
    try:
        yield
    finally:
        gmsh.option.setNumber("General.AbortOnError", saved)


def _gmsh():
    try:
        import gmsh
    except ImportError as error:
        raise ImportError("lancer.from_gmsh needs the gmsh Python module (Debian: apt-get install "
                          "python3-gmsh)") from error
    # gmsh 4.8 (Debian 12) has no gmsh.isInitialized(); there an uninitialized gmsh has no nodes.
    initialized = getattr(gmsh, "isInitialized", None)
    if initialized is not None and not initialized():
        raise RuntimeError("gmsh is not initialized: call gmsh.initialize() and make a model first")
    return gmsh


def _entities_to_take(gmsh, dims):
    """(dim, tag, physical) of the entities gmsh itself would save with Mesh.SaveAll = 0: those in a
    physical group when the model has any (of any dimension), else all of them."""
    has_physicals = len(gmsh.model.getPhysicalGroups()) > 0
    taken = []
    for dim in dims:
        for _, tag in gmsh.model.getEntities(dim):
            physicals = gmsh.model.getPhysicalGroupsForEntity(dim, tag)
            if has_physicals and len(physicals) == 0:
                continue
            taken.append((dim, tag, int(physicals[0]) if len(physicals) else 0))
    return taken


def _view_fields(gmsh, tag_to_index, node_count):
    """Every step of every view holding model data (gmsh.view.getModelData): node data as values per
    mesh node (NaN where the view gives none), element data as (element tags, values), element-node
    data as (element tags, nodes per element, values), each with its step index and time; and the
    tags of the views without model data (list-based views, read from .pos files)."""
    node_fields, element_fields, element_node_fields, list_views = [], [], [], []
    for view in gmsh.view.getTags():
        index = gmsh.view.getIndex(view)
        name = gmsh.option.getString(f"View[{index}].Name")
        steps = int(gmsh.option.getNumber(f"View[{index}].NbTimeStep"))
        for step in range(max(steps, 1)):
            try:
                data_type, tags, data, time, components = gmsh.view.getModelData(view, step)
            except Exception:  # a list-based view (no model data), or a step without data
                if step == 0 and view not in list_views:
                    list_views.append(view)
                continue
            components = int(components)
            if data_type not in ("NodeData", "ElementData", "ElementNodeData") or components <= 0 or len(tags) == 0:
                continue
            if data_type == "ElementNodeData":
                counts = np.array([len(d) // components for d in data], dtype=np.int64)
                values = np.concatenate([np.asarray(d, dtype=float)[:n * components] for d, n in zip(data, counts)])
                element_node_fields.append((name, components, np.asarray(tags, dtype=np.int64), counts, values,
                                            step, float(time)))
                continue
            rows = np.array([np.asarray(d, dtype=float)[:components] for d in data]).reshape(len(tags), components)
            tags = np.asarray(tags, dtype=np.int64)
            if data_type == "ElementData":
                element_fields.append((name, components, tags, rows.reshape(-1), step, float(time)))
                continue
            values = np.full((node_count, components), np.nan)
            known = (tags >= 0) & (tags < len(tag_to_index))
            slots = np.full(len(tags), -1, dtype=np.int64)
            slots[known] = tag_to_index[tags[known]]
            values[slots[slots >= 0]] = rows[slots >= 0]
            node_fields.append((name, components, values.reshape(-1), step, float(time)))
    return node_fields, element_fields, element_node_fields, list_views


def from_gmsh(dim=2, name=None):
    """The mesh of gmsh's current model: dim=2 its surfaces, dim=3 also its volumes, whose skin and
    interfaces become faces as the .msh reader makes them. Physical groups and their names come
    along, and every step of each view with node, element or element-node data
    (gmsh.view.addModelData, a merged .msh result) becomes a field for color_by and warp, as the .msh
    reader makes one of $NodeData, $ElementData and $ElementNodeData. List-based views (a merged .pos,
    gmsh.view.addListData) are put on the mesh by their elements' coordinates as `lancer render
    mesh.msh view.pos` puts a file's, each step an element-node field (their steps timed 0, 1, ...:
    gmsh's API gives no list view's times). With dim=3 the volume elements stay as mesh.volume, with
    the model-based views' fields, for slices, isosurfaces, field lines and probes (list-based views
    colour the skin only). Call it after gmsh.model.mesh.generate(dim)."""
    if dim not in (2, 3):
        raise ValueError(f"dim={dim!r}: use 2 (surfaces) or 3 (surfaces and volumes)")
    gmsh = _gmsh()
    with _errors_raise(gmsh):
        return _from_gmsh(gmsh, dim, name)


def _from_gmsh(gmsh, dim, name):
    node_tags, coords, _ = gmsh.model.mesh.getNodes()
    if len(node_tags) == 0:
        raise ValueError(f"the current gmsh model ('{gmsh.model.getCurrent()}') has no mesh nodes: call "
                         f"gmsh.model.mesh.generate({dim}) first (after gmsh.initialize() and making the model)")
    node_tags = np.asarray(node_tags, dtype=np.int64)
    points = np.asarray(coords, dtype=np.float64).reshape(-1, 3)
    tag_to_index = np.full(int(node_tags.max()) + 1, -1, dtype=np.int64)
    tag_to_index[node_tags] = np.arange(len(node_tags))

    blocks = []
    for entity_dim, entity, physical in _entities_to_take(gmsh, (2, 3) if dim == 3 else (2,)):
        types, element_tags, element_nodes = gmsh.model.mesh.getElements(entity_dim, entity)
        for element_type, tags, nodes in zip(types, element_tags, element_nodes):
            indices = tag_to_index[np.asarray(nodes, dtype=np.int64)]
            blocks.append((int(element_type), entity_dim, physical, entity, indices,
                           np.asarray(tags, dtype=np.int64)))
    if not blocks and dim == 2 and any(d == 3 for d, _ in gmsh.model.getPhysicalGroups()):
        raise ValueError("the gmsh model's physical groups are volumes: use from_gmsh(dim=3) after "
                         "gmsh.model.mesh.generate(3), or add physical surfaces")
    if not blocks:
        raise ValueError(f"the gmsh model '{gmsh.model.getCurrent()}' has no {'surface or volume' if dim == 3 else 'surface'} "
                         f"elements{' in its physical groups' if gmsh.model.getPhysicalGroups() else ''}: call "
                         f"gmsh.model.mesh.generate({dim}) first")
    group_names = {}
    for group_dim, tag in gmsh.model.getPhysicalGroups():
        group_name = gmsh.model.getPhysicalName(group_dim, tag)
        if group_name:
            group_names[(group_dim, tag)] = group_name
    node_fields, element_fields, element_node_fields, list_views = _view_fields(gmsh, tag_to_index,
                                                                                 len(node_tags))
    mesh = _lancer._mesh_from_elements(points, blocks, group_names, name or f"gmsh:{gmsh.model.getCurrent()}",
                                       node_fields, element_fields, element_node_fields,
                                       keep_volume=(dim == 3))
    if list_views:
        _lancer._add_list_views(mesh, _list_views(gmsh, list_views), f"gmsh:{gmsh.model.getCurrent()} views")
    return mesh


def _list_views(gmsh, tags):
    """(name, [(element code, element count, data), ...]) of each list-based view, as
    gmsh.view.getListData gives them: per element, its nodes' x, y and z, then its values per step."""
    views = []
    for view in tags:
        name = gmsh.option.getString(f"View[{gmsh.view.getIndex(view)}].Name")
        codes, counts, data = gmsh.view.getListData(view)
        views.append((name, [(code, int(count), np.asarray(values, dtype=float))
                             for code, count, values in zip(codes, counts, data)]))
    return views


# The General.* options that make gmsh's view (lancer/scene/results/gmsh_view.hpp reads the same ones).
_VIEW_OPTIONS = ["Trackball", "TrackballQuaternion0", "TrackballQuaternion1", "TrackballQuaternion2",
                 "TrackballQuaternion3", "RotationX", "RotationY", "RotationZ", "TranslationX", "TranslationY",
                 "TranslationZ", "ScaleX", "ScaleY", "ScaleZ", "Orthographic", "ClipFactor",
                 "DisplayBorderFactor", "MinX", "MinY", "MinZ", "MaxX", "MaxY", "MaxZ"]


def camera_from_gmsh():
    """The camera of gmsh's current view, from the live General.* options (what the GUI shows, or
    what a script set): rotation, translation, scale and projection, orthographic by default as in
    gmsh. The model is framed by its bounding box when rendered, as gmsh frames it."""
    gmsh = _gmsh()
    options = {}
    with _errors_raise(gmsh):
        for name in _VIEW_OPTIONS:
            try:
                options[name] = gmsh.option.getNumber("General." + name)
            except Exception:  # an option this gmsh does not have: lancer uses gmsh 4.8's default
                pass
    return _lancer._camera_from_gmsh_options(options)
