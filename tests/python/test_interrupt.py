"""Ctrl-C during a render: KeyboardInterrupt within a tile's time, and the module still works."""

import os
import signal
import threading
import time

import pytest

import lancer
from conftest import data

SPHERE = data("tests", "data", "render", "sphere_fine.msh")


def test_sigint_stops_a_long_render():
    mesh = lancer.read_msh(str(SPHERE))
    # Long enough (minutes on two cores) that finishing instead of stopping cannot pass the bound below.
    arguments = dict(width=4000, height=3000, samples=64, sampler="stratified", threads=2)
    timer = threading.Timer(0.5, os.kill, (os.getpid(), signal.SIGINT))
    started = time.monotonic()
    timer.start()
    with pytest.raises(KeyboardInterrupt):
        lancer.render(mesh, **arguments)
    elapsed = time.monotonic() - started
    timer.join()
    assert elapsed < 10, f"the render stopped {elapsed:.1f} s after it began (the signal came at 0.5 s)"
    # The interrupted render left nothing behind: the next one works.
    assert lancer.render(mesh, width=16, height=12).shape == (12, 16, 3)
