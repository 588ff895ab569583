"""lancer.Mesh from numpy arrays, in meshio's names: points, cells (an (M, 3) or (M, 4) array,
meshio's list of (type, array) or CellBlocks, or a dict {type: array}), point_data and cell_data
({name: values}, several steps as a list or an (S, ...) array). Checked here (kinds, shapes, dtypes,
index ranges, finite values; a TypeError for an argument of the wrong kind, lancer.InputError for
wrong shapes and values), then made by the library's assembler as the .msh reader makes a mesh, so
that point_data and cell_data are fields as a file's $NodeData and $ElementData are: color_by, warp,
isolines, arrows, legends and steps take them alike."""

import numpy as np

from . import _lancer

_WHERE = "lancer.Mesh"
_MAX_INDEX = 2**31 - 1  # lancer's 32-bit indices

# meshio's cell types: gmsh's element type, its dimension, and where meshio's node order (VTK's)
# differs from gmsh's, gmsh's nodes as a permutation of meshio's (gmsh's manual, "Node ordering";
# meshio's gmsh writer permutes the same way).
_CELL_TYPES = {
    "vertex": (15, 0, None),
    "line": (1, 1, None),
    "line3": (8, 1, None),
    "triangle": (2, 2, None),
    "triangle6": (9, 2, None),
    "quad": (3, 2, None),
    "quad8": (16, 2, None),
    "quad9": (10, 2, None),
    "tetra": (4, 3, None),
    "tetra10": (11, 3, [0, 1, 2, 3, 4, 5, 6, 7, 9, 8]),
    "hexahedron": (5, 3, None),
    "hexahedron20": (17, 3, [0, 1, 2, 3, 4, 5, 6, 7, 8, 11, 16, 9, 17, 10, 18, 19, 12, 15, 13, 14]),
    "hexahedron27": (12, 3, [0, 1, 2, 3, 4, 5, 6, 7, 8, 11, 16, 9, 17, 10, 18, 19, 12, 15, 13, 14,
                             24, 22, 20, 21, 23, 25, 26]),
    "wedge": (6, 3, None),
    "wedge15": (18, 3, [0, 1, 2, 3, 4, 5, 6, 8, 12, 7, 13, 14, 9, 11, 10]),
    "pyramid": (7, 3, None),
    "pyramid13": (19, 3, [0, 1, 2, 3, 4, 5, 8, 9, 6, 10, 7, 11, 12]),
}
_NODES = {"vertex": 1, "line": 2, "line3": 3, "triangle": 3, "triangle6": 6, "quad": 4, "quad8": 8, "quad9": 9,
          "tetra": 4, "tetra10": 10, "hexahedron": 8, "hexahedron20": 20, "hexahedron27": 27, "wedge": 6,
          "wedge15": 15, "pyramid": 5, "pyramid13": 13}

# meshio's bookkeeping in the data of a mesh it read from a .msh file: the physical and elementary
# tags become the groups and entities; the rest describes the file, not a result.
_GMSH_GROUPS = {"gmsh:physical": "groups", "gmsh:geometrical": "entities"}


def input_error(message, where=_WHERE):
    """A lancer.InputError as the library raises one: str() "where: error: message", with .file,
    .line, .column, .byte_offset and .message."""
    error = _lancer.InputError(f"{where}: error: {message}")
    error.file, error.line, error.column, error.byte_offset, error.message = where, 0, 0, -1, message
    return error


def _shape(array):
    return "(" + ", ".join(map(str, array.shape)) + ("," if array.ndim == 1 else "") + ")"


def _numbers(value, label, kinds="fiu", what="numbers"):
    """value as a numpy array of numbers: a TypeError for what is no array at all (a dict, None, a
    str), an InputError for an array of something else (text, objects, complex numbers)."""
    if value is None or isinstance(value, (str, bytes, dict)):
        raise TypeError(f"{label} must be an array of {what}, not {type(value).__name__}")
    try:
        array = np.asarray(value)
    except ValueError as error:  # ragged lists
        raise input_error(f"{label} is not a rectangular array ({error})") from None
    if array.dtype.kind not in kinds:
        raise input_error(f"{label} must hold {what}; got dtype {array.dtype}")
    return array


# Cells ------------------------------------------------------------------------------------------

def _is_block_list(cells):
    """meshio's cells: CellBlocks (.type, .data) or (type, array) pairs, rather than rows of indices."""
    if not isinstance(cells, (list, tuple)) or len(cells) == 0:
        return False
    first = cells[0]
    return hasattr(first, "type") and hasattr(first, "data") or (
        isinstance(first, (list, tuple)) and len(first) == 2 and isinstance(first[0], str))


def _cell_blocks(cells):
    """[(label, type, (m, k) int64 array)] of the cells in order; `faces`: True for the (M, 3) / (M, 4)
    array form (rows with -1 last are triangles)."""
    if isinstance(cells, dict):
        items = [(f"cells[{kind!r}]", kind, data) for kind, data in cells.items()]
    elif _is_block_list(cells):
        items = []
        for b, block in enumerate(cells):
            if hasattr(block, "type") and hasattr(block, "data"):
                kind, data = block.type, block.data
            elif isinstance(block, (list, tuple)) and len(block) == 2:
                kind, data = block
            else:
                raise TypeError(f"cells[{b}] must be a (type, array) pair or a meshio CellBlock, "
                                f"not {type(block).__name__}")
            items.append((f"cells[{b}] ({kind!r})", kind, data))
    else:
        faces = _numbers(cells, "cells", "iu", "integers (0-based point indices)")
        if faces.ndim != 2 or faces.shape[1] not in (3, 4):
            raise input_error(f"cells must be an (M, 3) or (M, 4) array of 0-based point indices, a list of "
                              f"(type, array) or a dict {{type: array}}; got shape {_shape(faces)}")
        return [("cells", "faces", faces.astype(np.int64, copy=False))], True
    blocks = []
    for label, kind, data in items:
        if not isinstance(kind, str):
            raise TypeError(f"{label}: a cell type is a str such as 'triangle', not {type(kind).__name__}")
        if kind not in _CELL_TYPES:
            raise input_error(f"{label}: lancer does not take meshio's '{kind}' cells from arrays (it takes "
                              f"{', '.join(_CELL_TYPES)}); write the mesh to .msh (meshio.write('x.msh', mesh, "
                              f"file_format='gmsh')) and read it with lancer.read_msh")
        array = _numbers(data, label, "iu", "integers (0-based point indices)")
        nodes = _NODES[kind]
        if array.size == 0:
            array = array.reshape(0, nodes)
        if array.ndim != 2 or array.shape[1] != nodes:
            raise input_error(f"{label} must be an (m, {nodes}) array ({nodes} nodes per {kind}); "
                              f"got shape {_shape(array)}")
        blocks.append((label, kind, array.astype(np.int64, copy=False)))
    return blocks, False


def _check_indices(label, array, point_count, faces):
    used = (array >= 0) if faces else np.ones(array.shape, dtype=bool)
    if faces and array.shape[1] == 4:
        used[:, :3] = True  # only the last column may be -1 (a triangle)
    bad = used & ((array < 0) | (array >= point_count))
    if bad.any():
        row, column = np.argwhere(bad)[0]
        raise input_error(f"{label}[{row}] uses point {array[row, column]}, but points has {point_count} rows "
                          f"(indices are 0-based{'; -1 last makes a triangle' if faces and array.shape[1] == 4 else ''})")


# Data -------------------------------------------------------------------------------------------

def _components(label, step, count):
    """One step's values as (count, C) float64, C 1, 3 (2: a vector in the plane, z = 0) or 9 (3x3)."""
    array = _numbers(step, label).astype(np.float64, copy=False)
    if array.ndim == 3 and array.shape[1:] == (3, 3):
        array = array.reshape(len(array), 9)
    if array.ndim == 1:
        array = array.reshape(-1, 1)
    if array.ndim != 2 or array.shape[0] != count:
        raise input_error(f"{label} has shape {_shape(np.asarray(step))}: give ({count},) values, "
                          f"({count}, C) or ({count}, 3, 3)")
    if array.shape[1] == 2:
        array = np.column_stack([array, np.zeros(count)])
    if array.shape[1] not in (1, 3, 9):
        raise input_error(f"{label} has {array.shape[1]} components: lancer shows scalars (1), vectors (3, or "
                          f"2 in the plane) and tensors (9, or 3 x 3)")
    infinite = np.isinf(array)
    if infinite.any():
        row = np.argwhere(infinite)[0][0]
        raise input_error(f"{label}[{row}] is infinite: give finite values, or NaN where there is none")
    return np.ascontiguousarray(array)


def _steps(label, value, count):
    """The steps of one item of point_data or cell_data: [(label, values)], each (count, ...)."""
    if isinstance(value, (list, tuple)):
        if len(value) == 0:
            raise input_error(f"{label} is an empty list: give one array per step")
        return [(f"{label}[{k}]", step) for k, step in enumerate(value)]
    array = _numbers(value, label)
    if array.ndim >= 1 and array.shape[0] == count:
        return [(label, array)]
    if array.ndim >= 2 and array.shape[1] == count:
        return [(f"{label}[{k}]", array[k]) for k in range(array.shape[0])]
    raise input_error(f"{label} has shape {_shape(array)}, but there are {count} "
                      f"{'points' if label.startswith('point') else 'cells'}: give ({count}, ...) values, "
                      f"or (S, {count}, ...) or a list for S steps")


def _named(data, argument):
    if data is None:
        return []
    if not isinstance(data, dict):
        raise TypeError(f"{argument} must be a dict {{name: values}}, not {type(data).__name__}"
                        + (" (groups= and entities= are keyword arguments)" if argument == "point_data" else ""))
    for name in data:
        if not isinstance(name, str):
            raise TypeError(f"{argument}: a field's name is a str, not {name!r}")
        if not name:
            raise input_error(f"{argument} has a field with an empty name")
    return list(data.items())


def _times(times, steps):
    if times is None:
        return [float(k) for k in range(steps)]
    array = _numbers(times, "times").astype(np.float64).reshape(-1)
    if not np.isfinite(array).all():
        raise input_error(f"times holds {array[~np.isfinite(array)][0]}: give finite times")
    if len(array) < steps:
        raise input_error(f"times gives {len(array)} times, but a field has {steps} steps: give one time per step")
    return [float(t) for t in array]


def _point_fields(point_data, count):
    fields = []
    for name, value in _named(point_data, "point_data"):
        if name.startswith("gmsh:"):
            continue  # meshio's gmsh:dim_tags: where the file put the node
        steps = [_components(label, step, count) for label, step in _steps(f"point_data[{name!r}]", value, count)]
        _same_components(f"point_data[{name!r}]", steps)
        fields.append((name, steps))
    return fields


def _same_components(label, steps):
    if any(step.shape[1] != steps[0].shape[1] for step in steps):
        raise input_error(f"{label}: its steps have {sorted({s.shape[1] for s in steps})} components; "
                          f"every step of a field has the same")


def _cell_values(name, value, sizes):
    """cell_data[name] as steps of (M, C) arrays over every cell in order: one array per block
    (meshio) or one over all cells, each of one step or S."""
    label, total = f"cell_data[{name!r}]", sum(sizes)
    if isinstance(value, (list, tuple)):
        if len(value) != len(sizes):
            raise input_error(f"{label} is a list of {len(value)}, but cells has {len(sizes)} block(s): give one "
                              f"array per cell block (meshio's cell_data), or one array over all {total} cells")
        per_block = [_steps(f"{label}[{b}]", item, size) for b, (item, size) in enumerate(zip(value, sizes))]
        if len({len(steps) for steps in per_block}) > 1:
            raise input_error(f"{label}: its blocks give {sorted({len(s) for s in per_block})} steps: give "
                              f"every block the same")
        steps = []
        for k in range(len(per_block[0])):
            parts = [_components(*per_block[b][k], sizes[b]) for b in range(len(sizes))]
            _same_components(label, parts)
            steps.append(np.concatenate(parts) if parts else np.zeros((0, 1)))
    else:
        steps = [_components(step_label, step, total) for step_label, step in _steps(label, value, total)]
    _same_components(label, steps)
    return steps


def _tags(value, label, sizes):
    """groups / entities: one non-negative integer per cell, as one array or a list per block."""
    if value is None:
        return None
    if isinstance(value, (list, tuple)) and len(value) == len(sizes) and all(
            isinstance(v, np.ndarray) and v.ndim == 1 for v in value):
        value = np.concatenate(value) if value else np.zeros(0, dtype=np.int64)  # one array per block
    array = _numbers(value, label, "iu", "integers (tags)")
    if array.ndim != 1 or len(array) != sum(sizes):
        raise input_error(f"{label} must be an ({sum(sizes)},) array, one tag per cell; got shape {_shape(array)}")
    bad = (array < 0) | (array > _MAX_INDEX)
    if bad.any():
        i = int(np.argmax(bad))
        raise input_error(f"{label}[{i}] is {array[i]}: tags are 0 (none) or positive 32-bit integers")
    return array.astype(np.int64)


def _group_names(names):
    """{tag: name}, or meshio's field_data {name: [tag, dimension]}: [(tag, dimension or None, name)]."""
    if names is None:
        return []
    if not isinstance(names, dict):
        raise TypeError(f"group_names must be a dict {{tag: name}}, not {type(names).__name__}")
    groups = []
    for key, value in names.items():
        if isinstance(key, str) and np.ndim(value) == 1 and len(value) == 2:
            tag, dimension = (int(v) for v in value)
            groups.append((tag, dimension, key))
        elif isinstance(key, (int, np.integer)) and isinstance(value, str):
            groups.append((int(key), None, value))
        else:
            raise input_error(f"group_names must map integer tags to strings ({{5: 'plate'}}; or be meshio's "
                              f"field_data {{'plate': [5, 2]}}); got {key!r}: {value!r}")
        if not 0 < groups[-1][0] <= _MAX_INDEX:
            raise input_error(f"group_names has tag {groups[-1][0]}: physical tags are positive 32-bit integers")
    return groups


# The constructor --------------------------------------------------------------------------------

def mesh_init(self, points, cells, point_data=None, cell_data=None, *, groups=None, group_names=None,
              entities=None, times=None, name="<arrays>", threads=0):
    """points (N, 3) float; cells an (M, 3) or (M, 4) int array of 0-based point indices (a row with
    -1 last is a triangle), meshio's list of (type, array) pairs or CellBlocks, or a dict {type:
    array} (triangles, quads, tetrahedra, hexahedra, prisms, pyramids, first and second order; lines
    and vertices are skipped; volume cells are drawn by their skin and kept as the mesh's volume, for
    slices, isosurfaces, field lines, grid arrows and Mesh.probe); point_data {name: (N,), (N, 3) or (N, 3, 3)
    values, or a list or (S, N, ...) array of S steps}; cell_data {name: values per cell, one array
    per cell block (meshio) or one over all cells, S steps likewise}; times: the time of each step
    (default 0, 1, 2, ...); groups (M,) physical tags (0: none); group_names {tag: name} (or meshio's
    field_data); entities (M,) gmsh elementary tags (default: the groups). meshio's cell_data
    'gmsh:physical' and 'gmsh:geometrical' are the groups and entities. NaN in a field: no value
    there (grey). threads: for the checks and the assembly (0: every core)."""
    point_fields_given = point_data is not None and len(_named(point_data, "point_data")) > 0
    cell_items = _named(cell_data, "cell_data")
    blocks, faces_form = _cell_blocks(cells)
    if faces_form and not point_fields_given and not cell_items:
        # The array form alone: the library's parallel checks and assembly (a million faces in ms).
        _init(self, points, blocks[0][2], groups, _tag_names(group_names), entities, name, threads)
        return
    if not isinstance(name, str):
        raise TypeError(f"name must be a str, not {type(name).__name__}")
    points = _numbers(points, "points", "fiu", "real numbers (float64)")
    if points.ndim != 2 or points.shape[1] != 3:
        hint = "; add a zero z column to 2-D points: np.c_[points, np.zeros(len(points))]" if (
            points.ndim == 2 and points.shape[1] == 2) else ""
        raise input_error(f"points must be an (N, 3) array of coordinates; got shape {_shape(points)}{hint}")
    points = np.ascontiguousarray(points, dtype=np.float64)
    if not np.isfinite(points).all():
        row = int(np.argwhere(~np.isfinite(points))[0][0])
        raise input_error(f"points[{row}] is ({', '.join(f'{v:g}' for v in points[row])}): every coordinate "
                          f"must be finite")
    if len(points) > _MAX_INDEX:
        raise input_error(f"{len(points)} points are more than lancer's 32-bit indices allow")
    for label, kind, array in blocks:
        _check_indices(label, array, len(points), faces_form)
    if faces_form:
        blocks = _split_faces(blocks[0][2])
    sizes = [len(array) for _, _, array in blocks]
    if sum(sizes) > _MAX_INDEX:
        raise input_error(f"{sum(sizes)} cells are more than lancer's 32-bit indices allow")

    for key, argument in _GMSH_GROUPS.items():
        if cell_data is not None and key in cell_data:
            if (groups if argument == "groups" else entities) is not None:
                raise input_error(f"cell_data[{key!r}] and {argument}= both give the cells' tags: keep one")
            value = cell_data[key]
            if argument == "groups":
                groups = value
            else:
                entities = value
    physical = _tags(groups, "groups", sizes)
    entity = _tags(entities, "entities", sizes) if entities is not None else physical
    named = _group_names(group_names)

    fields = _point_fields(point_data, len(points))
    element_fields = [(n, _cell_values(n, v, sizes)) for n, v in cell_items if not n.startswith("gmsh:")]
    for n, _ in element_fields:
        if any(n == other for other, _ in fields):
            raise input_error(f"point_data and cell_data both have a field {n!r}: give each field one name")
    most_steps = max([len(steps) for _, steps in fields + element_fields], default=1)
    step_times = _times(times, most_steps)

    # Blocks for the assembler: gmsh's types and node order, one per (type, group, entity), cells
    # tagged 1..M in the order given (element fields name them so).
    first_tag = np.cumsum([0] + sizes)
    element_blocks, dimension_of_tag, surface_cells = [], {}, np.zeros(sum(sizes), dtype=bool)
    for b, (label, kind, array) in enumerate(blocks):
        gmsh_type, dimension, order = _CELL_TYPES[kind]
        if dimension < 2 or len(array) == 0:
            continue  # points and lines: not surfaces, as the reader skips them
        surface_cells[first_tag[b]:first_tag[b + 1]] = True
        if order is not None:
            array = array[:, order]
        tags = np.arange(first_tag[b], first_tag[b + 1], dtype=np.int64) + 1
        p = physical[first_tag[b]:first_tag[b + 1]] if physical is not None else np.zeros(len(array), np.int64)
        e = entity[first_tag[b]:first_tag[b + 1]] if entity is not None else p
        key = (p << 32) | e  # (group, entity) as one number: tags are below 2^31
        if len(key) and (key == key[0]).all():
            runs = [(key[0], slice(None))]  # one group and entity: the block as it is
        else:
            keys, inverse = np.unique(key, return_inverse=True)
            runs = [(k, inverse == i) for i, k in enumerate(keys)]
        for k, rows in runs:
            group, ent = int(k) >> 32, int(k) & 0xFFFFFFFF
            element_blocks.append((gmsh_type, dimension, group, ent,
                                   np.ascontiguousarray(array[rows]).reshape(-1), tags[rows]))
            if group:
                dimension_of_tag.setdefault(group, set()).add(dimension)
    names = {}
    for tag, dimension, group_name in named:
        for d in ([dimension] if dimension is not None else sorted(dimension_of_tag.get(tag, {2}))):
            names[(d, tag)] = group_name
    node_fields = [(n, steps[0].shape[1], step.reshape(-1), k, step_times[k])
                   for n, steps in fields for k, step in enumerate(steps)]
    cell_tags = np.flatnonzero(surface_cells).astype(np.int64) + 1
    cell_fields = [(n, steps[0].shape[1], cell_tags, np.ascontiguousarray(step[surface_cells]).reshape(-1), k,
                    step_times[k])
                   for n, steps in element_fields for k, step in enumerate(steps)]
    _init(self, _lancer._ElementBlocks(), points, element_blocks, names, name, node_fields, cell_fields)


def _split_faces(faces):
    """An (M, 3) or (M, 4) face array as triangle and quad blocks, rows keeping their numbers."""
    if faces.shape[1] == 3:
        return [("cells", "triangle", faces)]
    triangles = faces[:, 3] == -1
    # One block per kind would renumber the rows; cell numbers follow the rows, so the blocks are
    # runs of one kind, in order.
    blocks, start = [], 0
    while start < len(faces):
        end = start + 1
        while end < len(faces) and triangles[end] == triangles[start]:
            end += 1
        if triangles[start]:
            blocks.append(("cells", "triangle", faces[start:end, :3]))
        else:
            blocks.append(("cells", "quad", faces[start:end]))
        start = end
    return blocks


def _tag_names(group_names):
    """group_names for the array form's constructor: {tag: name} (meshio's field_data converted)."""
    if group_names is None or not isinstance(group_names, dict):
        return group_names
    return {tag: name for tag, _, name in _group_names(group_names)}


_init = _lancer.Mesh.__init__
