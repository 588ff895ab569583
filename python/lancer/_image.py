"""lancer.Image: what render returns, a numpy array that knows how it was encoded."""

import numpy as np

from . import _lancer


class Image(np.ndarray):
    """(H, W, 3) or (H, W, 4) uint8 as the image files hold it (row 0 on top), or linear float32
    RGBA with render(..., dtype="float32"). A numpy array in every other way."""

    @classmethod
    def _wrap(cls, array, srgb, stats=None):
        image = array.view(cls)
        image.srgb = bool(srgb)
        image.stats = stats or {}
        return image

    def __array_finalize__(self, obj):
        self.srgb = getattr(obj, "srgb", False)
        self.stats = getattr(obj, "stats", {})

    def save(self, path):
        """Writes .png, .bmp, .ppm or .gif by extension: for a uint8 image the bytes `lancer render
        -o` writes for the same render (a PNG from an sRGB render is marked sRGB)."""
        array = np.asarray(self)
        if array.dtype != np.uint8 and array.dtype.kind != "f":
            raise ValueError(f"cannot save an image of dtype {array.dtype}: use uint8 or float")
        _lancer._write_image(str(path), np.ascontiguousarray(array), self.srgb)

    def _repr_png_(self):
        """PNG bytes, so that Jupyter shows the picture."""
        import os
        import tempfile

        with tempfile.TemporaryDirectory() as folder:
            path = os.path.join(folder, "image.png")
            self.save(path)
            with open(path, "rb") as file:
                return file.read()
