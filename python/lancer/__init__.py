"""lancer: a CPU ray tracer for gmsh meshes, from Python.

    import lancer
    mesh = lancer.read_msh("part.msh")
    image = lancer.render(mesh, width=640, height=480, samples=4)   # (H, W, 3) uint8, row 0 on top
    image.save("part.png")

No display is needed (no X, no GL). The C++ library does the work; this package is a thin layer.
"""

from ._lancer import (Camera, InputError, LancerWarning, Mesh, Scene, Volume, __version__, color_map, color_maps,
                      read_msh, read_png, read_volume, release_memory)
from . import _lancer
from . import _arrays
from . import _image
from ._image import Image
from ._gmsh import camera_from_gmsh as _camera_from_gmsh, from_gmsh

__all__ = ["Camera", "Image", "InputError", "LancerWarning", "Mesh", "Scene", "Volume", "__version__", "animate",
           "color_map", "color_maps", "from_gmsh", "read_msh", "read_png", "read_volume", "release_memory",
           "render"]

Camera.from_gmsh = staticmethod(_camera_from_gmsh)
# Mesh(points, cells, point_data, cell_data, ...): meshio's arguments, read in Python (_arrays.py).
Mesh.__init__ = _arrays.mesh_init


def _arguments(width, height, samples, shading, srgb, transparent_background, edges, threads, progress,
               sampler, max_depth, encoding=None, tonemap=None, exposure=None, denoise=None, integrator=None,
               noise=None, look=None, results=None, adaptive_noise=None):
    arguments = _lancer._RenderArguments()
    for name, value in (results or {}).items():
        setattr(arguments, name, value)
    arguments.width = width
    arguments.height = height
    arguments.samples = samples
    arguments.shading = shading
    arguments.srgb = srgb
    arguments.transparent_background = transparent_background
    arguments.edges = edges
    arguments.threads = threads
    arguments.progress = progress
    arguments.sampler = sampler
    arguments.max_depth = max_depth
    arguments.encoding = encoding
    arguments.tonemap = tonemap
    arguments.exposure = exposure
    arguments.denoise = denoise
    arguments.integrator = integrator
    arguments.noise = noise
    arguments.adaptive_noise = adaptive_noise
    arguments.look = look
    return arguments


def _results(color_map, range, log, scale, legend, isolines, bands, arrows, clip, slices, skin, isosurfaces,
             streamlines):
    return {"color_map": color_map, "range": range, "log": log, "scale": scale, "legend": legend,
            "isolines": isolines, "bands": bands, "arrows": arrows, "clip": clip, "slices": slices, "skin": skin,
            "isosurfaces": isosurfaces, "streamlines": streamlines}


def render(scene, width=None, height=None, samples=None, shading=None, srgb=None,
           transparent_background=None, edges=None, threads=0, progress=False, dtype="uint8",
           sampler=None, max_depth=None, encoding=None, tonemap=None, exposure=None, denoise=None,
           integrator=None, noise=None, look=None, *, adaptive_noise=None, color_map=None, range=None,
           log=None, scale=None, legend=None, isolines=None, bands=None, arrows=None, clip=None, slices=None,
           skin=None, isosurfaces=None, streamlines=None):
    """Renders a lancer.Scene, or the quick look of a lancer.Mesh (as `lancer render part.msh`).

    integrator: "whitted" (the default), "path" (path tracing) or "ao" (ambient occlusion); noise:
    stop a pixel's sampling once its relative error is below this; adaptive_noise: sample in rounds,
    more where a pixel's displayed error (a fraction of white) is above this, up to samples (as
    --adaptive-noise); look: "studio", "sky" or "sun" (docs/lighting.md).

    None keeps the scene file's own value (for a mesh, the quick look's), as the CLI's options do.
    Returns a lancer.Image: (H, W, 3) uint8, (H, W, 4) with transparent_background, sRGB-encoded by
    default as the PNG files are (encoding="linear": the raw values round(255 * I)), after exposure
    (stops) and tonemap ("none", "filmic", "aces"); with dtype="float32", the linear floating-point
    RGBA radiance the renderer made, (H, W, 4), before exposure and tone curve. denoise=True filters
    the noise (docs/output.md). Releases the GIL; Ctrl-C raises KeyboardInterrupt within a tile's time.

    Results, as the command line's options (docs/python.md), on every mesh coloured by a field
    (Scene.quick_look's color_by=, or a scene file's color_by): color_map (a map's name or a list of
    colours, --color-map), range=(low, high) (--range), log=True or scale="log" (--log), legend
    ("right", "bottom" or "none", --legend), isolines=N (--isolines), bands=N (--bands); and on every
    mesh, arrows="FIELD" (--arrows) and clip="x=0.5" or a list of planes (--clip).

    Inside the volume (docs/volume.md), as --slice, --skin, --isosurfaces and --streamlines:
    slices="z=0.3" ("y": through the volume's centre; "PX,PY,PZ,NX,NY,NZ"; a dict {"point": [x, y, z],
    "normal": [x, y, z]}; or a list of these), skin ("shown", "ghost", "edges", "hidden"),
    isosurfaces="v" or "v:4" or a dict of the scene keys ({"field": "v", "values": [-0.5, 0.5],
    "color_by": "e"}), streamlines="e" or "e:40" or a dict ({"field": "e", "count": 40, "seed_line":
    [[x1, y1, z1], [x2, y2, z2]]}). A Mesh lancer.read_msh read has its volume read from the same file
    the first time a render or a probe draws inside it, then kept with the Mesh for its later renders
    and probes; a Mesh made from arrays without volume cells, or by from_gmsh without dim=3, has none
    (InputError).
    """
    provenance = _image._call_text("lancer.render", render, locals())
    if dtype not in ("uint8", "float32"):
        raise ValueError(f"dtype={dtype!r}: use 'uint8' (encoded, as the image files) or 'float32' (linear)")
    arguments = _arguments(width, height, samples, shading, srgb, transparent_background, edges, threads,
                           progress, sampler, max_depth, encoding, tonemap, exposure, denoise, integrator,
                           noise, look, _results(color_map, range, log, scale, legend, isolines, bands,
                                                 arrows, clip, slices, skin, isosurfaces, streamlines),
                           adaptive_noise)
    array, info = _lancer._render(scene, arguments, dtype == "float32")
    return Image._wrap(array, srgb=info["srgb"], stats=info, provenance=provenance)


def animate(scene, output, frames=None, fps=None, orbit=None, width=None, height=None, samples=None,
            shading=None, srgb=None, transparent_background=None, edges=None, threads=0, progress=False,
            loop=None, dither=None, palette=None, sampler=None, max_depth=None, encoding=None, tonemap=None,
            exposure=None, denoise=None, over=None, integrator=None, noise=None, look=None, label=None, *,
            adaptive_noise=None, color_map=None, range=None, log=None, scale=None, legend=None, isolines=None,
            bands=None, arrows=None, clip=None, slices=None, skin=None, isosurfaces=None, streamlines=None):
    """Writes an orbit of the camera (orbit="camera") or of light K (orbit="light:K") as `lancer
    animate` does: an animated .gif, an animated .png, an .mp4 (H.264) or .webm (VP9) video, or numbered
    frames ("frame_%04d.png").
    over="steps": one frame per time step of the views the scene colours or warps by, in time order
    (frames=N: N frames evenly spaced in time, the steps between blended; one frame per step when the
    times repeat or decrease). label="t = {time:.3g} s" writes each frame's time (the time the file
    gives its step) and {step} into a corner, as --label does.
    None keeps the scene's value (its [animation] table, else 36 frames at 12 fps, the camera).
    adaptive_noise, color_map, range, log, scale, legend, isolines, bands, arrows, clip, slices, skin,
    isosurfaces and streamlines: as render's."""
    provenance = _image._call_text("lancer.animate", animate, locals())
    arguments = _arguments(width, height, samples, shading, srgb, transparent_background, edges, threads,
                           progress, sampler, max_depth, encoding, tonemap, exposure, denoise, integrator,
                           noise, look, _results(color_map, range, log, scale, legend, isolines, bands,
                                                 arrows, clip, slices, skin, isosurfaces, streamlines),
                           adaptive_noise)
    _lancer._animate(scene, str(output), arguments, frames, fps, orbit, loop, dither, palette, over, label,
                     command=provenance)
