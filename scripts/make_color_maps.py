"""Writes src/lancer/image/color_map_tables.cpp and color_tables/: the colour maps lancer draws fields with, as tables of
8-bit display colours, so that lancer needs no matplotlib at run time.

- matplotlib's maps, each at its own resolution (256 colours; twilight 510): the colours matplotlib
  itself looks up, `cmap(np.arange(cmap.N))`, rounded to 8 bits.
- gmsh's maps by View.ColormapNumber (0 to 24), as gmsh 4.8 computes them (Post/ColorTable.cpp,
  ColorTable_Recompute, with the default parameters: no bias, curvature, rotation, beta, swap or
  inversion): 255 colours, each channel truncated to an integer as gmsh does; 20 to 24 are the 256
  colours of matplotlib's (and Google's) tables, truncated the same way. The formulas are written
  again here from gmsh's; tests/python/test_color_maps.py checks the tables against gmsh's own code.
- The CSS colour names matplotlib knows (matplotlib.colors.CSS4_COLORS), for lists of colours.

Run with Debian's interpreter, which has python3-matplotlib:
    /usr/bin/python3 scripts/make_color_maps.py
It also draws each map as a strip for docs/fields.md, docs/images/color_maps/NAME.png (256 x 12
pixels, gmsh:N as gmsh_N.png), from the same 8-bit tables.
"""

import math
import pathlib

import matplotlib
import matplotlib._cm_listed as listed
import matplotlib.image
import matplotlib.colors as mcolors
import numpy as np

ROOT = pathlib.Path(__file__).resolve().parents[1]
OUTPUT = ROOT / "src" / "lancer" / "image" / "color_map_tables.cpp"
TABLES = ROOT / "src" / "lancer" / "image" / "color_tables"
STRIPS = ROOT / "docs" / "images" / "color_maps"

# The matplotlib maps lancer offers, in the order its messages list them.
MATPLOTLIB_MAPS = [
    # perceptually uniform sequential
    "viridis", "plasma", "inferno", "magma", "cividis",
    # sequential
    "Blues", "Greens", "Greys", "Oranges", "Purples", "Reds", "YlOrRd", "YlGnBu", "hot", "copper",
    "gray", "cubehelix",
    # diverging
    "coolwarm", "bwr", "seismic", "RdBu", "RdYlBu", "RdYlGn", "Spectral", "PiYG", "PRGn", "BrBG", "PuOr",
    # rainbow and cyclic
    "turbo", "jet", "rainbow", "hsv", "twilight",
]

GMSH_MAP_NAMES = ["black", "vis5d", "jet", "lucie", "rainbow", "emc2000", "incandescent", "hot", "pink",
                  "grayscale", "french", "hsv", "spectrum", "bone", "spring", "summer", "autumn", "winter",
                  "cool", "copper", "magma", "inferno", "plasma", "viridis", "turbo"]

LICENCES = """\
// Sources and licences of the tables (matplotlib's LICENSE directory has the texts):
// - viridis, plasma, inferno, magma: Nathaniel J. Smith, Stefan van der Walt and (viridis) Eric Firing,
//   released under CC0 (public domain dedication).
// - cividis: Jamie R. Nunez, Christopher R. Anderton and Ryan S. Renslow (2018), as matplotlib ships it.
// - turbo: Anton Mikhailov, Google LLC (2019), Apache License 2.0, as matplotlib ships it.
// - Blues, Greens, Greys, Oranges, Purples, Reds, YlOrRd, YlGnBu, RdBu, RdYlBu, RdYlGn, Spectral, PiYG,
//   PRGn, BrBG, PuOr: ColorBrewer, Cynthia A. Brewer, Pennsylvania State University, under the
//   Apache-style licence of matplotlib's LICENSE_COLORBREWER.
// - coolwarm: Kenneth Moreland, "Diverging Color Maps for Scientific Visualization" (2009).
// - twilight: Bastian Bechtold (2018), as matplotlib ships it.
// - cubehelix: Dave Green (2011); hot, copper, gray, jet, hsv, rainbow, bwr, seismic: matplotlib's own
//   definitions. Everything above is matplotlib's data under its PSF-style licence (Copyright (c)
//   2012- Matplotlib Development Team; All Rights Reserved); lancer's change: rounded to 8 bits.
// - gmsh:0 to gmsh:24: the values of gmsh's colour-table formulas (gmsh 4.8, Post/ColorTable.cpp,
//   C. Geuzaine and J.-F. Remacle; its maps 20 to 24 are the matplotlib and Google tables above).
"""


def hex_triples(rgb):
    """[(r, g, b), ...] of integers 0..255 as "rrggbb..."."""
    return "".join(f"{r:02x}{g:02x}{b:02x}" for r, g, b in rgb)


def matplotlib_table(name):
    cmap = matplotlib.colormaps[name]
    colours = cmap(np.arange(cmap.N))[:, :3]  # an integer looks the table up, uninterpolated
    return [tuple(int(round(float(c) * 255)) for c in colour) for colour in colours]


# gmsh's ColorTable_Recompute, one channel triple per s in [0, 1] (bias, curvature and rotation 0).
def _gray(s):
    return 0.0 if s < 0.0 else (s if s < 1.0 else 1.0)


def _hot_r(s):
    return 0.0 if s < 0.0 else (8.0 / 3.0 * s if s < 3.0 / 8.0 else 1.0)


def _hot_g(s):
    return 0.0 if s < 3.0 / 8.0 else (8.0 / 3.0 * (s - 3.0 / 8.0) if s < 6.0 / 8.0 else 1.0)


def _hot_b(s):
    return 0.0 if s < 6.0 / 8.0 else (8.0 / 2.0 * (s - 6.0 / 8.0) if s < 1.0 else 1.0)


def _cubic(a, b, c, d, x):
    return a + b * x + c * x * x + d * x * x * x


def _hsv_to_rgb(h, s, v):
    if s < 5.0e-6:
        return v, v, v
    i = int(h)
    f = h - float(i)
    p1, p2, p3 = v * (1.0 - s), v * (1.0 - s * f), v * (1.0 - s * (1.0 - f))
    return {0: (v, p3, p1), 1: (p2, v, p1), 2: (p1, v, p3), 3: (p1, p2, v), 4: (p3, p1, v),
            5: (v, p1, p2)}.get(i, (v, v, v))


def _jet(s):
    ii = min(max(s * 128.0, 0.0), 128.0)
    rr = 0.0 if ii <= 46 else (-0.03125 * (ii - 111) + 1.0 if ii >= 111 else (1.0 if ii >= 78 else 0.03125 * (ii - 46)))
    gg = (0.0 if ii <= 14 or ii >= 111 else
          -0.03125 * (ii - 111) if ii >= 79 else 0.03125 * (ii - 14) if ii <= 46 else 1.0)
    bb = 0.0 if ii >= 79 else (-0.03125 * (ii - 79) if ii >= 47 else (0.03125 * (ii - 14) + 1.0 if ii <= 14 else 1.0))
    return int(rr * 255.0), int(gg * 255.0), int(bb * 255.0)


def _lucie(s):
    if s <= 0.0:
        return 0, 0, 255
    if s <= 0.40:
        return 0, int(s * 637.5), int(255.0 - s * 637.5)
    if s <= 0.60:
        return int(1275.0 * (s - 0.4)), 255, 0
    if s <= 1.0:
        return 255, int(255.0 - 637.5 * (s - 0.6)), 0
    return 255, 0, 0


def _rainbow(s):
    if s <= 0.0:
        return 0, 0, 255
    if s <= 0.25:
        return 0, int(s * (255.0 / 0.25)), 255
    if s <= 0.50:
        return 0, 255, int(255.0 - (255.0 / 0.25) * (s - 0.25))
    if s <= 0.75:
        return int((s - 0.5) * (255.0 / 0.25)), 255, 0
    if s <= 1.0:
        return 255, int(255.0 - (255.0 / 0.25) * (s - 0.75)), 0
    return 255, 0, 0


def _emc2000(s):
    if s <= 0.0:
        return 0, 0, 0
    if s <= 0.2:
        return int(57 * (1 - 100 * (s - 0.1) * (s - 0.1))), 0, int(s * (255.0 / 0.2))
    if s <= 0.3624:
        return 0, int((s - 0.2) * (255.0 / 0.1624)), 255
    if s <= 0.50:
        return 0, 255, int(255.0 - (255.0 / 0.1376) * (s - 0.3624))
    if s <= 0.6376:
        return int((s - 0.5) * (255.0 / 0.1376)), 255, 0
    if s <= 0.8:
        return 255, int(255.0 - (255.0 / 0.1624) * (s - 0.6376)), 0
    if s <= 1.0:
        return 255, int((255.0 / 0.2) * (s - 0.8)), int(-3187.66 * s * s + 7012.76 * s - 3570.61)
    return 255, 255, 255


def _french(s):
    ii = min(max(s, 0.0), 1.0)
    rr = 2 * (0.75 - ii) + 1.0 if ii >= 0.75 else (1.0 if ii >= 0.5 else (4.0 * (ii - 0.25) if ii >= 0.25 else 0.0))
    gg = (1.33333 * ii if ii <= 0.25 else 0.33333 + 2.66667 * (ii - 0.25) if ii <= 0.5 else
          1 - 2.66667 * (ii - 0.5) if ii <= 0.75 else 1.33333 * (1.0 - ii))
    bb = 2 * ii + 0.5 if ii <= 0.25 else (1.0 if ii <= 0.5 else (4 * (0.75 - ii) if ii <= 0.75 else 0.0))
    return int(rr * 255.0), int(gg * 255.0), int(bb * 255.0)


def _channels255(r, g, b):
    return int(255.0 * r), int(255.0 * g), int(255.0 * b)


GMSH_FORMULAS = {
    0: lambda s: (0, 0, 0),
    1: lambda s: (int(128.0 + 127.0 * math.atan(7.0 * (1.4 * (s - 0.5))) / 1.57),
                  int(128.0 + 127.0 * (2 * math.exp(-7 * (1.4 * (s - 0.5)) * (1.4 * (s - 0.5))) - 1)),
                  int(128.0 + 127.0 * math.atan(-7.0 * (1.4 * (s - 0.5))) / 1.57)),
    2: _jet,
    3: _lucie,
    4: _rainbow,
    5: _emc2000,
    6: lambda s: (int(255.0 * _cubic(-0.0506169, 2.81633, -1.87033, 0.0524573, s)),
                  int(255.0 * _cubic(0.0485868, -1.26109, 6.3074, -4.12498, s)),
                  int(255.0 * _cubic(0.364662, 1.50814, -7.36756, 6.51847, s))),
    7: lambda s: _channels255(_hot_r(s), _hot_g(s), _hot_b(s)),
    8: lambda s: _channels255(math.sqrt((2.0 * _gray(s) + _hot_r(s)) / 3.0),
                              math.sqrt((2.0 * _gray(s) + _hot_g(s)) / 3.0),
                              math.sqrt((2.0 * _gray(s) + _hot_b(s)) / 3.0)),
    9: lambda s: (0, 0, 0) if s <= 0.0 else (int(255 * 1.0 * s),) * 3 if s <= 1.0 else (255, 255, 255),
    10: _french,
    11: lambda s: _channels255(*_hsv_to_rgb(6.0 * s + 1.0e-10, 1.0, 1.0)),
    12: lambda s: _channels255(*_hsv_to_rgb(5.0 * s + 1.0e-10, 1.0, 1.0)),
    13: lambda s: (int(255.0 * (7.0 * _gray(s) + _hot_b(s)) / 8.0), int(255.0 * (7.0 * _gray(s) + _hot_g(s)) / 8.0),
                   int(255.0 * (7.0 * _gray(s) + _hot_r(s)) / 8.0)),
    14: lambda s: _channels255(1.0, _gray(s), 1.0 - _gray(s)),
    15: lambda s: _channels255(_gray(s), 0.5 + _gray(s) / 2.0, 0.4),
    16: lambda s: _channels255(1.0, _gray(s), 0.0),
    17: lambda s: _channels255(0.0, _gray(s), 0.5 + (1.0 - _gray(s)) / 2.0),
    18: lambda s: _channels255(_gray(s), 1.0 - _gray(s), 1.0),
    19: lambda s: _channels255(min(1.0, _gray(s) * 1.25), min(1.0, _gray(s) * 0.7812), min(1.0, _gray(s) * 0.4975)),
}
GMSH_DATA = {20: listed._magma_data, 21: listed._inferno_data, 22: listed._plasma_data,
             23: listed._viridis_data, 24: listed._turbo_data}


def gmsh_table(number):
    def clamp(x):
        return 0 if x < 0 else (255 if x > 255 else x)

    if number in GMSH_DATA:
        return [tuple(clamp(int(255.0 * c)) for c in colour) for colour in GMSH_DATA[number]]
    size = 255  # gmsh's View.NbColors default
    return [tuple(clamp(c) for c in GMSH_FORMULAS[number](i / (size - 1))) for i in range(size)]


def cpp_table(name, rgb):
    text = hex_triples(rgb)
    per_line = 16 * 6
    lines = [text[i:i + per_line] for i in range(0, len(text), per_line)]
    body = "\n".join(f'     "{line}"' for line in lines)
    return f'    {{"{name}",\n{body}}},'


def write_strip(name, rgb):
    """The map from its low end (left) to its high end, 256 pixels wide: what the legend bar shows."""
    table = np.asarray(rgb, dtype=float) / 255
    t = np.linspace(0, 1, 256) * (len(table) - 1)
    index = np.minimum(t.astype(int), len(table) - 2)
    f = (t - index)[:, None]
    row = table[index] * (1 - f) + table[index + 1] * f  # interpolated as lancer looks a map up
    STRIPS.mkdir(parents=True, exist_ok=True)
    matplotlib.image.imsave(STRIPS / f"{name.replace(':', '_')}.png", np.repeat(row[None, :, :], 12, axis=0),
                            metadata={"Software": None})


def generated_header(sources):
    return [
        "// Generated by scripts/make_color_maps.py from " + sources + ";",
        "// do not edit: change the script and run it again (/usr/bin/python3 scripts/make_color_maps.py).",
    ]


def table_part(function, comment, tables, licences=True):
    """One source of tables: a function returning a span of them (color_table_parts.hpp)."""
    return [
        *generated_header("matplotlib " + matplotlib.__version__ + " and gmsh 4.8's colour-table formulas"),
        "//",
        f"// {comment}",
        *(["//", LICENCES.rstrip("\n")] if licences else []),
        "",
        "#include <array>",
        "",
        "#include \"lancer/image/color_tables/color_table_parts.hpp\"",
        "",
        "namespace lancer::color_tables {",
        "",
        "// clang-format off",
        f"std::span<const ColorTable> {function}() {{",
        f"  static constexpr std::array<ColorTable, {len(tables)}> kTables = {{{{",
        *[cpp_table(name, rgb) for name, rgb in tables],
        "  }};",
        "  return kTables;",
        "}",
        "// clang-format on",
        "",
        "}  // namespace lancer::color_tables",
        "",
    ]


def main():
    matplotlib_tables = [(name, matplotlib_table(name)) for name in MATPLOTLIB_MAPS]
    split = MATPLOTLIB_MAPS.index("coolwarm")
    gmsh_tables = [(f"gmsh:{n}", gmsh_table(n)) for n in range(len(GMSH_MAP_NAMES))]
    css = sorted((name, colour.lstrip("#").lower()) for name, colour in mcolors.CSS4_COLORS.items())
    gmsh_names = [f"//   gmsh:{n}: {name}" for n, name in enumerate(GMSH_MAP_NAMES)]
    parts = {
        "matplotlib_sequential.cpp": table_part(
            "matplotlibSequential", "matplotlib's uniform and sequential maps, in the order messages list them.",
            matplotlib_tables[:split]),
        "matplotlib_diverging.cpp": table_part(
            "matplotlibDivergingAndCyclic", "matplotlib's diverging, rainbow and cyclic maps, in that order.",
            matplotlib_tables[split:]),
        "gmsh_maps.cpp": table_part(
            "gmshMaps", "gmsh's maps by View.ColormapNumber:\n" + "\n".join(gmsh_names), gmsh_tables),
        "css_colors.cpp": [
            *generated_header("matplotlib " + matplotlib.__version__ + "'s CSS4_COLORS"),
            "",
            "#include <array>",
            "",
            "#include \"lancer/image/color_tables/color_table_parts.hpp\"",
            "",
            "namespace lancer::color_tables {",
            "",
            "// clang-format off",
            "std::span<const NamedColor> cssColorNames() {",
            f"  static constexpr std::array<NamedColor, {len(css)}> kColors = {{{{",
            *[f'    {{"{name}", "{colour}"}},' for name, colour in css],
            "  }};",
            "  return kColors;",
            "}",
            "// clang-format on",
            "",
            "}  // namespace lancer::color_tables",
            "",
        ],
    }
    TABLES.mkdir(parents=True, exist_ok=True)
    for name, lines in parts.items():
        (TABLES / name).write_text("\n".join(lines))
    count = len(matplotlib_tables) + len(gmsh_tables)
    OUTPUT.write_text("\n".join([
        *generated_header("the tables' sizes"),
        "",
        "#include \"lancer/image/color_map_tables.hpp\"",
        "",
        "#include <algorithm>",
        "#include <array>",
        "",
        "#include \"lancer/image/color_tables/color_table_parts.hpp\"",
        "",
        "namespace lancer {",
        "",
        "std::span<const ColorTable> colorTables() {",
        "  // One list in the order messages give: matplotlib's maps, then gmsh:0 to gmsh:24.",
        f"  static const std::array<ColorTable, {count}> kTables = [] {{",
        f"    std::array<ColorTable, {count}> all{{}};",
        "    auto end = std::ranges::copy(color_tables::matplotlibSequential(), all.begin()).out;",
        "    end = std::ranges::copy(color_tables::matplotlibDivergingAndCyclic(), end).out;",
        "    std::ranges::copy(color_tables::gmshMaps(), end);",
        "    return all;",
        "  }();",
        "  return kTables;",
        "}",
        "",
        "std::span<const NamedColor> cssColors() { return color_tables::cssColorNames(); }",
        "",
        "}  // namespace lancer",
        "",
    ]))
    for name, rgb in matplotlib_tables + gmsh_tables:
        write_strip(name, rgb)
    print(f"wrote {OUTPUT} and {TABLES} ({count} maps, {len(css)} colour names)")


if __name__ == "__main__":
    main()
