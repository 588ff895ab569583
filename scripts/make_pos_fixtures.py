#!/usr/bin/python3
"""Writes the list-based .pos fixtures in tests/data/pos/ with the tools that write them in practice:
gmsh's Python API (python3-gmsh) and GetDP (Debian's getdp).

gmsh_lists.pos (gmsh.view.addListData, gmsh.view.write): views "scalar", "vector" and "tensor", each
    with two elements of every shape (SP, SL, ST, SQ, SS, SH, SI, SY; VP, ...; TP, ...) at two steps
    (gmsh writes TIME{0,1}), and text annotations (T2, T3) in "scalar". The elements are gmsh's reference
    elements (gmsh.model.mesh.getElementProperties), shifted; every value is value(x, y, z, step,
    component) below at its node, so a test can check each value against the coordinates read with it.
second_order.pos: views "scalar2", "vector2", "tensor2" with SL2, ST2, SQ2, SS2, SH2, SI2, SY2 (the
    reference elements of MSH types 8-14) at two steps, TIME{0.5,1.5}, values as above. gmsh 4.8 refuses
    to write second-order lists ("Cannot export datasets with interpolation matrices"), so this script
    writes them in gmsh's own writer format (PViewDataListIO.cpp, writeElementPOS) and has gmsh read them
    back to check that it takes them as they are meant (all but SY2, on which gmsh 4.8 crashes).
binary_view.pos, ascii_view.pos: a small view saved by gmsh in its older $PostFormat format, binary
    and ASCII (PostProcessing.Format = 1 and 0 in a .geo run after the view), which lancer refuses with
    a recipe; the script runs that recipe on binary_view.pos and checks that it gives the view back.
magnet/az.pos, magnet/b_a.pos, magnet/magnet.msh: GetDP's magnet demo (its own demo, as shipped in
    /usr/share/doc/getdp/examples), on a mesh coarsened to keep the files small:
        gmsh magnet.geo -2 -clscale 4 -format msh22 -o magnet.msh
        getdp magnet.pro -msh magnet.msh -solve Magnetostatics_a -pos a
    (the templates in ../templates; GetDP without gmsh support reads MSH 2.2 only).
heat/t.pos, heat/steps.pos, heat/heat.msh: transient heat on a plate of triangles and quadrangles
    (heat/heat.geo, heat/heat.pro, committed), four steps at t = 0, 0.01, 0.02, 0.03:
        gmsh heat.geo -2 -format msh22 -o heat.msh
        getdp heat.pro -msh heat.msh -solve Transient -pos Map
    t.pos: views "T" (ST, SQ) and "gradT" (VT, VQ) with every step and GetDP's TIME list after the
    elements; steps.pos: one view "T" per step, appended by the time loop (no TIME).
layers/v.pos, layers/e.pos, layers/layers.msh: two dielectric layers in a unit cube, a volume mesh
    of two physical volumes with their interface, top and bottom as physical surfaces (layers/layers.geo,
    layers/layers.pro, committed; GetDP's template Lib_Electrostatics_v.pro), solved exactly:
        gmsh layers.geo -3 -format msh22 -o layers.msh
        getdp layers.pro -msh layers.msh -solve Electrostatics_v -pos Map
    v.pos: the potential on the tetrahedra (SS); e.pos: the field on the tetrahedra (VS) and on the
    interface's triangles (VT, the field within them: 0).
Run: /usr/bin/python3 scripts/make_pos_fixtures.py
"""
import os
import shutil
import subprocess
import sys
import tempfile

import gmsh

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tests", "data", "pos")
GETDP_EXAMPLES = "/usr/share/doc/getdp/examples"
SHAPES = "PLTQSHIY"  # point, line, triangle, quadrangle, tetrahedron, hexahedron, prism, pyramid
FIRST_ORDER_TYPES = [15, 1, 2, 3, 4, 5, 6, 7]
SECOND_ORDER_TYPES = [None, 8, 9, 10, 11, 12, 13, 14]
KINDS = [("S", 1, "scalar"), ("V", 3, "vector"), ("T", 9, "tensor")]
STEPS = 2


def value(x, y, z, step, component):
    """The value at a node: dyadic numbers only, so that floats and doubles hold it exactly."""
    return x + 2 * y + 4 * z + 16 * step + component / 8


def reference_nodes(element_type, shift):
    """gmsh's reference element of `element_type`, its nodes in gmsh's order, moved by `shift`."""
    _, dim, _, count, local, _ = gmsh.model.mesh.getElementProperties(element_type)
    per_node = max(dim, 1)
    nodes = []
    for n in range(count):
        p = [0.0, 0.0, 0.0]
        for d in range(dim):
            p[d] = local[per_node * n + d]
        nodes.append([p[i] + shift[i] for i in range(3)])
    return nodes


def element_values(nodes, components):
    return [value(*p, step, c) for step in range(STEPS) for p in nodes for c in range(components)]


def gmsh_lists(path):
    views = []
    for letter, components, name in KINDS:
        view = gmsh.view.add(name)
        for shape, element_type in enumerate(FIRST_ORDER_TYPES):
            data = []
            for k in range(2):
                nodes = reference_nodes(element_type, (4.0 * shape, 3.0 * k, 0.5 * k))
                # gmsh.view.addListData takes all x, then all y, then all z; gmsh writes node by node.
                data += [p[i] for i in range(3) for p in nodes] + element_values(nodes, components)
            gmsh.view.addListData(view, letter + SHAPES[shape], 2, data)
        if name == "scalar":
            gmsh.view.addListDataString(view, [10.0, 20.0], ["a 2D label"])
            gmsh.view.addListDataString(view, [1.0, 2.0, 3.0], ["a 3D label", "its second step"])
        views.append(view)
    for i, view in enumerate(views):
        gmsh.view.write(view, path, append=i > 0)


def format_element(code, nodes, values):
    """One element as gmsh's writeElementPOS prints it (%.16g, coordinates node by node)."""
    coords = ",".join("%.16g,%.16g,%.16g" % tuple(p) for p in nodes)
    return "%s(%s){%s};\n" % (code, coords, ",".join("%.16g" % v for v in values))


def second_order(path):
    expected = {}
    with open(path, "w") as out:
        for letter, components, name in KINDS:
            out.write('View "%s2" {\nTIME{0.5,1.5};\n' % name)
            for shape, element_type in enumerate(SECOND_ORDER_TYPES):
                if element_type is None:
                    continue
                nodes = reference_nodes(element_type, (4.0 * shape, 0.0, 1.0))
                out.write(format_element(letter + SHAPES[shape] + "2", nodes, element_values(nodes, components)))
                if SHAPES[shape] != "Y":
                    expected.setdefault(name + "2", []).append(3 * len(nodes) + STEPS * len(nodes) * components)
            out.write("};\n")
    # gmsh reads each list back with every node of its second-order element; gmsh 4.8 stops with a
    # floating point exception on a second-order pyramid (SY2, 14 nodes as PViewDataListIO.cpp reads
    # them), so the check leaves those out.
    with tempfile.TemporaryDirectory() as tmp:
        check = os.path.join(tmp, "check.pos")
        with open(path) as source, open(check, "w") as out:
            out.writelines(line for line in source if not line[1:].startswith("Y2("))
        gmsh.merge(check)
    for tag in gmsh.view.getTags():
        name = gmsh.option.getString("View[%d].Name" % gmsh.view.getIndex(tag))
        if name not in expected:
            continue
        _, counts, data = gmsh.view.getListData(tag)
        assert list(counts) == [1] * len(expected[name]), (name, counts)
        assert [len(d) for d in data] == expected[name], (name, [len(d) for d in data])
        gmsh.view.remove(tag)


def old_formats(folder):
    view = gmsh.view.add("old format")
    nodes = reference_nodes(2, (0, 0, 0))
    gmsh.view.addListData(view, "ST", 1, [p[i] for i in range(3) for p in nodes] + element_values(nodes, 1))
    with tempfile.TemporaryDirectory() as tmp:
        source = os.path.join(tmp, "view.pos")
        gmsh.view.write(view, source)
        for name, fmt in (("binary_view.pos", 1), ("ascii_view.pos", 0)):
            save = os.path.join(tmp, "save.geo")
            with open(save, "w") as out:
                out.write('PostProcessing.Format = %d; Save View[0] "%s";\n' % (fmt, os.path.join(folder, name)))
            run(["gmsh", source, save, "-"], tmp)
        # The recipe lancer's message gives: it must give the view back as text.
        with open(os.path.join(tmp, "save.geo"), "w") as out:
            out.write('PostProcessing.Format = 2; Save View[0] "binary_view_text.pos";\n')
        run(["gmsh", os.path.join(folder, "binary_view.pos"), "save.geo", "-"], tmp)
        with open(os.path.join(tmp, "binary_view_text.pos")) as text, open(source) as original:
            assert text.read() == original.read(), "the conversion recipe does not give the view back"
    gmsh.view.remove(view)


def run(command, cwd):
    result = subprocess.run(command, cwd=cwd, capture_output=True, text=True)
    if result.returncode != 0 or "Error" in result.stdout + result.stderr:
        sys.exit("%s failed in %s:\n%s%s" % (" ".join(command), cwd, result.stdout, result.stderr))


def getdp_magnet(folder):
    with tempfile.TemporaryDirectory() as tmp:
        shutil.copytree(os.path.join(GETDP_EXAMPLES, "templates"), os.path.join(tmp, "templates"))
        demos = os.path.join(tmp, "demos")
        shutil.copytree(os.path.join(GETDP_EXAMPLES, "demos"), demos)
        run(["gmsh", "magnet.geo", "-2", "-clscale", "4", "-format", "msh22", "-o", "magnet.msh"], demos)
        run(["getdp", "magnet.pro", "-msh", "magnet.msh", "-solve", "Magnetostatics_a", "-pos", "a"], demos)
        os.makedirs(folder, exist_ok=True)
        for name in ("az.pos", "b_a.pos", "magnet.msh"):
            shutil.copy(os.path.join(demos, name), os.path.join(folder, name))


def getdp_heat(folder):
    with tempfile.TemporaryDirectory() as tmp:
        for name in ("heat.geo", "heat.pro"):
            shutil.copy(os.path.join(folder, name), tmp)
        run(["gmsh", "heat.geo", "-2", "-format", "msh22", "-o", "heat.msh"], tmp)
        run(["getdp", "heat.pro", "-msh", "heat.msh", "-solve", "Transient", "-pos", "Map"], tmp)
        for name in ("t.pos", "steps.pos", "heat.msh"):
            shutil.copy(os.path.join(tmp, name), os.path.join(folder, name))


def getdp_layers(folder):
    template = os.path.join(GETDP_EXAMPLES, "templates", "Lib_Electrostatics_v.pro")
    with tempfile.TemporaryDirectory() as tmp:
        for name in ("layers.geo", "layers.pro"):
            shutil.copy(os.path.join(folder, name), tmp)
        shutil.copy(template, tmp)
        run(["gmsh", "layers.geo", "-3", "-format", "msh22", "-o", "layers.msh"], tmp)
        run(["getdp", "layers.pro", "-msh", "layers.msh", "-solve", "Electrostatics_v", "-pos", "Map"], tmp)
        for name in ("v.pos", "e.pos", "layers.msh"):
            shutil.copy(os.path.join(tmp, name), os.path.join(folder, name))


def main():
    os.makedirs(ROOT, exist_ok=True)
    gmsh.initialize()
    gmsh.option.setNumber("General.Terminal", 0)
    gmsh_lists(os.path.join(ROOT, "gmsh_lists.pos"))
    second_order(os.path.join(ROOT, "second_order.pos"))
    old_formats(ROOT)
    gmsh.finalize()
    getdp_magnet(os.path.join(ROOT, "magnet"))
    getdp_heat(os.path.join(ROOT, "heat"))
    getdp_layers(os.path.join(ROOT, "layers"))


if __name__ == "__main__":
    main()
