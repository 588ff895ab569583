"""The Python examples run and write what they say (examples/python/)."""

import os
import subprocess
import sys

import lancer
from conftest import SOURCE_DIR, data


def run_example(name, *arguments):
    environment = dict(os.environ)
    # The examples run from the source folder: the package's folder must not be relative to here.
    environment["PYTHONPATH"] = os.pathsep.join(os.path.abspath(part) for part in sys.path if part)
    result = subprocess.run([sys.executable, str(SOURCE_DIR / "examples" / "python" / name), *map(str, arguments)],
                            cwd=SOURCE_DIR, env=environment, capture_output=True, text=True)
    assert result.returncode == 0, result.stderr


def test_gmsh_model_renders_without_a_mesh_file(tmp_path):
    out = tmp_path / "flange.png"
    run_example("gmsh_model.py", out)
    image = lancer.read_png(str(out))
    assert image.shape == (480, 640, 4)
    assert list(tmp_path.iterdir()) == [out]  # no .msh written


def test_turntable_writes_a_gif(tmp_path):
    out = tmp_path / "turn.gif"
    run_example("turntable.py", data("tests", "data", "render", "bracket_coarse.msh"), out)
    assert out.read_bytes()[:6] == b"GIF89a"


def test_progress_goes_to_stderr(capfd):
    lancer.render(lancer.read_msh(str(data("tests", "data", "render", "ball.msh"))), width=64, height=48,
                  progress=True)
    assert "100.0%" in capfd.readouterr().err
