# Types of the lancer package (lancer/__init__.py and the compiled lancer._lancer, _lancer.pyi);
# tests/python/test_stubs.py checks that these names and parameters are the package's.
import os
from typing import Any, Literal, Sequence

import numpy as np
import numpy.typing as npt

from ._lancer import Camera as Camera
from ._lancer import InputError as InputError
from ._lancer import LancerWarning as LancerWarning
from ._lancer import Mesh as Mesh
from ._lancer import Scene as Scene
from ._lancer import Volume as Volume
from ._lancer import __version__ as __version__
from ._lancer import color_map as color_map
from ._lancer import color_maps as color_maps
from ._lancer import release_memory as release_memory
from ._lancer import read_msh as read_msh
from ._lancer import read_png as read_png
from ._lancer import read_volume as read_volume

__all__ = ["Camera", "Image", "InputError", "LancerWarning", "Mesh", "Scene", "Volume", "__version__", "animate",
           "color_map", "color_maps", "from_gmsh", "read_msh", "read_png", "read_volume", "release_memory",
           "render"]

_ColorMap = str | Sequence[str | Sequence[float]]
_Planes = str | dict[str, Any] | Sequence[str | dict[str, Any]]

class Image(np.ndarray[Any, np.dtype[Any]]):
    srgb: bool
    stats: dict[str, Any]
    def save(
        self, path: str | os.PathLike[str], quality: int | None = None, lossless: bool = False, dpi: int | None = None
    ) -> None: ...

def from_gmsh(dim: Literal[2, 3] = 2, name: str | None = None) -> Mesh: ...
def render(
    scene: Scene | Mesh,
    width: int | None = None,
    height: int | None = None,
    samples: int | None = None,
    shading: Literal["flat", "gouraud", "phong"] | None = None,
    srgb: bool | None = None,
    transparent_background: bool | None = None,
    edges: bool | None = None,
    threads: int = 0,
    progress: bool = False,
    dtype: Literal["uint8", "float32"] = "uint8",
    sampler: str | None = None,
    max_depth: int | None = None,
    encoding: Literal["srgb", "linear"] | None = None,
    tonemap: Literal["none", "filmic", "aces"] | None = None,
    exposure: float | None = None,
    denoise: bool | None = None,
    integrator: Literal["whitted", "path", "ao"] | None = None,
    noise: float | None = None,
    look: Literal["studio", "sky", "sun"] | None = None,
    *,
    adaptive_noise: float | None = None,
    color_map: _ColorMap | None = None,
    range: tuple[float, float] | None = None,
    log: bool | None = None,
    scale: Literal["linear", "log"] | None = None,
    legend: Literal["right", "bottom", "none"] | None = None,
    isolines: int | None = None,
    bands: int | None = None,
    arrows: str | dict[str, Any] | None = None,
    clip: str | Sequence[str] | None = None,
    slices: _Planes | None = None,
    skin: Literal["shown", "ghost", "edges", "hidden"] | None = None,
    isosurfaces: str | dict[str, Any] | None = None,
    streamlines: str | dict[str, Any] | None = None,
) -> Image: ...
def animate(
    scene: Scene | Mesh,
    output: str | os.PathLike[str],
    frames: int | None = None,
    fps: float | None = None,
    orbit: str | None = None,
    width: int | None = None,
    height: int | None = None,
    samples: int | None = None,
    shading: Literal["flat", "gouraud", "phong"] | None = None,
    srgb: bool | None = None,
    transparent_background: bool | None = None,
    edges: bool | None = None,
    threads: int = 0,
    progress: bool = False,
    loop: int | None = None,
    dither: str | None = None,
    palette: str | None = None,
    sampler: str | None = None,
    max_depth: int | None = None,
    encoding: Literal["srgb", "linear"] | None = None,
    tonemap: Literal["none", "filmic", "aces"] | None = None,
    exposure: float | None = None,
    denoise: bool | None = None,
    over: Literal["steps"] | None = None,
    integrator: Literal["whitted", "path", "ao"] | None = None,
    noise: float | None = None,
    look: Literal["studio", "sky", "sun"] | None = None,
    label: str | None = None,
    *,
    adaptive_noise: float | None = None,
    color_map: _ColorMap | None = None,
    range: tuple[float, float] | None = None,
    log: bool | None = None,
    scale: Literal["linear", "log"] | None = None,
    legend: Literal["right", "bottom", "none"] | None = None,
    isolines: int | None = None,
    bands: int | None = None,
    arrows: str | dict[str, Any] | None = None,
    clip: str | Sequence[str] | None = None,
    slices: _Planes | None = None,
    skin: Literal["shown", "ghost", "edges", "hidden"] | None = None,
    isosurfaces: str | dict[str, Any] | None = None,
    streamlines: str | dict[str, Any] | None = None,
) -> None: ...
