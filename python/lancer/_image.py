"""lancer.Image: what render returns, a numpy array that knows how it was encoded."""

import inspect

import numpy as np

from . import _lancer


def _call_text(name, function, arguments):
    """How a picture was made, for its file's metadata: "lancer.render('part.msh', width=640)", the
    arguments that differ from the function's defaults (`arguments`: its locals() on entry)."""
    words = []
    for parameter in inspect.signature(function).parameters.values():
        if parameter.name not in arguments:
            continue
        value = arguments[parameter.name]
        if parameter.default is not inspect.Parameter.empty and value is parameter.default:
            continue
        if parameter.default is not inspect.Parameter.empty and type(value) is type(parameter.default) \
                and value == parameter.default:
            continue
        shown = repr(value) if isinstance(value, (str, int, float, bool, tuple, list, type(None))) \
            else f"<{type(value).__module__}.{type(value).__name__}>"
        if len(shown) > 200:
            shown = shown[:200] + "..."
        words.append(shown if parameter.default is inspect.Parameter.empty else f"{parameter.name}={shown}")
    return f"{name}({', '.join(words)})"


class Image(np.ndarray):
    """(H, W, 3) or (H, W, 4) uint8 as the image files hold it (row 0 on top), or linear float32
    RGBA with render(..., dtype="float32"). A numpy array in every other way."""

    @classmethod
    def _wrap(cls, array, srgb, stats=None, provenance=""):
        image = array.view(cls)
        image.srgb = bool(srgb)
        image.stats = stats or {}
        image.provenance = provenance
        return image

    def __array_finalize__(self, obj):
        self.srgb = getattr(obj, "srgb", False)
        self.stats = getattr(obj, "stats", {})
        self.provenance = getattr(obj, "provenance", "")

    def save(self, path, quality=None, lossless=False, dpi=None):
        """Writes .png, .jpg/.jpeg, .webp, .bmp, .ppm, .gif or .exr by extension, the pixels `lancer
        render -o` writes for the same render (a PNG from an sRGB render is marked sRGB).
        quality: JPEG and lossy WebP, 1 to 100 (default 90); lossless=True: WebP without loss; dpi: the
        print resolution the file records. The file also records lancer's version and the call that made
        the picture (`provenance`, e.g. "lancer.render('part.msh', width=640)")."""
        array = np.asarray(self)
        if array.dtype != np.uint8 and array.dtype.kind != "f":
            raise ValueError(f"cannot save an image of dtype {array.dtype}: use uint8 or float")
        _lancer._write_image(str(path), np.ascontiguousarray(array), self.srgb, quality, bool(lossless), dpi,
                             self.provenance or "lancer.Image.save")

    def _repr_png_(self):
        """PNG bytes, so that Jupyter shows the picture."""
        import os
        import tempfile

        with tempfile.TemporaryDirectory() as folder:
            path = os.path.join(folder, "image.png")
            self.save(path)
            with open(path, "rb") as file:
                return file.read()
