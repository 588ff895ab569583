"""The module's large blocks (a mesh's arrays, the scene's, the accelerator's) are kept after a
render for the next one of the session, which takes them again instead of mapping and faulting in
fresh memory; lancer.release_memory() gives them back to the system."""

import numpy as np

import lancer
from lancer import _lancer


def wavy_grid(n):
    """A grid of n x n vertices, 2 (n - 1)^2 triangles: arrays of a megabyte and more."""
    x, y = np.meshgrid(np.linspace(0.0, 1.0, n), np.linspace(0.0, 1.0, n))
    points = np.stack([x.ravel(), y.ravel(), 0.1 * np.sin(6 * x.ravel()) * np.cos(5 * y.ravel())], axis=1)
    corner = (np.arange(n - 1)[:, None] * n + np.arange(n - 1)[None, :]).ravel()
    triangles = np.concatenate([np.stack([corner, corner + 1, corner + n + 1], axis=1),
                                np.stack([corner, corner + n + 1, corner + n], axis=1)])
    return lancer.Mesh(points, triangles)


def test_later_renders_take_the_blocks_of_the_first_and_they_go_back_on_request():
    mesh = wavy_grid(260)
    first = np.asarray(lancer.render(mesh, width=16, height=16))
    before = _lancer._memory_stats()
    assert before["retained_bytes"] > 0
    for _ in range(3):
        again = np.asarray(lancer.render(mesh, width=16, height=16))
        assert np.array_equal(first, again)
    after = _lancer._memory_stats()
    reused = after["reused_blocks"] - before["reused_blocks"]
    mapped = after["mapped_blocks"] - before["mapped_blocks"]
    assert reused > 2 * mapped
    # What is kept does not pile up: the peak moves only as much as the build's two threads order
    # their blocks differently from one render to the next.
    assert after["peak_mapped_bytes"] < 1.5 * before["peak_mapped_bytes"]
    assert lancer.release_memory() == after["retained_bytes"]
    assert _lancer._memory_stats()["retained_bytes"] == 0
    assert lancer.release_memory() == 0
