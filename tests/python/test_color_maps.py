"""Colour maps against their sources: every matplotlib map lancer offers (and its reversal) within
1/255 of matplotlib's own table, lists of colours as matplotlib's LinearSegmentedColormap.from_list
makes them, and gmsh's maps as gmsh's own code computes them (libgmsh's ColorTable_Recompute, called
through ctypes). lancer itself needs neither at run time: scripts/make_color_maps.py wrote the tables."""

import ctypes

import numpy as np
import pytest

import lancer
from conftest import data

matplotlib = pytest.importorskip("matplotlib", reason="the comparison needs python3-matplotlib")
from matplotlib.colors import LinearSegmentedColormap  # noqa: E402

WANTED = {"viridis", "plasma", "inferno", "magma", "cividis", "turbo", "coolwarm", "RdBu", "jet", "gray", "grey",
          "Blues", "Reds", "RdYlBu", "Spectral", "hot", "bwr", "seismic", "twilight"}


def matplotlib_names():
    return [name for name in lancer.color_maps() if not name.startswith("gmsh:")]


def worst_difference_255(ours, theirs):
    return float(np.abs(np.asarray(ours, dtype=float) - np.asarray(theirs, dtype=float)).max() * 255)


def test_the_maps_people_ask_for_are_there():
    names = lancer.color_maps()
    assert WANTED <= set(names)
    assert [f"gmsh:{n}" for n in range(25)] == [name for name in names if name.startswith("gmsh:")]


@pytest.mark.parametrize("name", matplotlib_names())
def test_every_table_is_matplotlibs_within_1_in_255(name):
    cmap = matplotlib.colormaps["gray" if name == "grey" else name]
    # At t = i / (N - 1) matplotlib's cmap(t) is its table's entry i, and so is lancer's lookup.
    t = np.linspace(0, 1, cmap.N)
    for variant, reference in ((name, cmap), (name + "_r", cmap.reversed())):
        ours = lancer.color_map(variant, cmap.N)
        assert ours.shape == (cmap.N, 3) and ours.dtype == np.float32
        assert worst_difference_255(ours, reference(t)[:, :3]) <= 1.0, variant


def test_lists_are_interpolated_as_from_list():
    for colours in (["#000080", "white", "#800000"], ["black", "#f80", (0.2, 0.6, 1.0), "darkred"]):
        theirs = LinearSegmentedColormap.from_list("list", colours)(np.linspace(0, 1, 256))[:, :3]
        assert worst_difference_255(lancer.color_map(colours), theirs) <= 1.0, colours


def test_unknown_names_and_colours_are_refused_with_the_closest():
    with pytest.raises(ValueError, match=r"color_map='virdis': \"virdis\" is not a colour map \(did you mean "
                                         r"'viridis'\?\): use viridis, plasma"):
        lancer.color_map("virdis")
    with pytest.raises(ValueError, match=r"item 1: \"whte\" is not a colour \(did you mean 'white'\?\)"):
        lancer.color_map(["navy", "whte"])
    with pytest.raises(ValueError, match=r"item 1 is \(2, 0, 0\)"):
        lancer.color_map(["navy", (2, 0, 0)])
    with pytest.raises(ValueError, match="give 2 to 256"):
        lancer.color_map(["navy"])


def test_quick_look_takes_any_map_and_lists():
    mesh = lancer.read_msh(str(data("tests", "data", "fields", "node_xy_v41_bin.msh")))
    pictures = {}
    for colour_map in ("viridis", "RdBu_r", "gmsh:2", ["#000080", "white", "#800000"]):
        scene = lancer.Scene.quick_look(mesh, color_by="temperature", color_map=colour_map)
        pictures[str(colour_map)] = lancer.render(scene, width=24, height=24)
    assert len({picture.tobytes() for picture in pictures.values()}) == 4


class GmshColorTable(ctypes.Structure):
    """gmsh 4.8's GmshColorTable (Post/ColorTable.h)."""
    _fields_ = [("table", ctypes.c_uint * 1024), ("size", ctypes.c_int), ("ipar", ctypes.c_int * 10),
                ("dpar", ctypes.c_double * 10)]


def gmsh_tables():
    """Each map as gmsh itself computes it, with its default parameters; skips without gmsh 4.8's library."""
    gmsh = pytest.importorskip("gmsh")
    library = getattr(gmsh, "lib", None)
    init = getattr(library, "_Z20ColorTable_InitParamiP14GmshColorTable", None)
    recompute = getattr(library, "_Z20ColorTable_RecomputeP14GmshColorTable", None)
    if not gmsh.__version__.startswith("4.8") or init is None or recompute is None:
        pytest.skip(f"gmsh {gmsh.__version__}'s library does not show ColorTable_Recompute")
    gmsh.initialize(["gmsh", "-v", "0"])
    try:
        tables = []
        for number in range(25):
            table = GmshColorTable()
            init(number, ctypes.byref(table))
            recompute(ctypes.byref(table))
            packed = np.array(table.table[:table.size], dtype=np.uint32)  # little-endian: A B G R
            tables.append(np.stack([packed & 255, (packed >> 8) & 255, (packed >> 16) & 255], axis=1))
        return tables
    finally:
        gmsh.finalize()


def test_gmsh_maps_are_gmshs_own_tables():
    for number, table in enumerate(gmsh_tables()):
        ours = lancer.color_map(f"gmsh:{number}", len(table)) * 255
        assert np.abs(ours - table).max() < 1e-3, f"gmsh:{number}"
