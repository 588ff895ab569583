"""Shared helpers for the Python tests: where the CLI and the fixtures are (CTest sets
LANCER_CLI and LANCER_SOURCE_DIR; PYTHONPATH points at build/python), a CLI runner and
the CLI's picture as an array, for renders that must equal it."""

import os
import pathlib
import struct
import subprocess

import numpy as np
import pytest

import lancer

SOURCE_DIR = pathlib.Path(os.environ.get("LANCER_SOURCE_DIR", pathlib.Path(__file__).parents[2])).resolve()
CLI = os.environ.get("LANCER_CLI", str(SOURCE_DIR / "build" / "lancer"))


def data(*parts):
    return SOURCE_DIR.joinpath(*parts)


def run_cli(*arguments, check=True):
    """Runs the lancer command; returns (exit code, stderr)."""
    result = subprocess.run([CLI, *map(str, arguments)], capture_output=True, text=True)
    if check and result.returncode != 0:
        raise AssertionError(f"lancer {' '.join(map(str, arguments))} failed ({result.returncode}): {result.stderr}")
    return result.returncode, result.stderr


def cli_image(tmp_path, *arguments, width=96, height=64):
    """The RGB pixels `lancer render ARGUMENTS` draws at width x height, as a numpy array: what a
    Python render of the same picture must equal."""
    run_cli("render", *arguments, "--width", width, "--height", height, "-q", "-o", tmp_path / "cli.png")
    return np.asarray(lancer.read_png(str(tmp_path / "cli.png")))[..., :3]


def png_chunks(path):
    """A PNG's chunks as (type, data) pairs, in the file's order (PNG 1.2 section 3.2)."""
    data_bytes = pathlib.Path(path).read_bytes()
    assert data_bytes[:8] == b"\x89PNG\r\n\x1a\n", path
    chunks, at = [], 8
    while at + 12 <= len(data_bytes):
        (length,) = struct.unpack(">I", data_bytes[at:at + 4])
        chunks.append((data_bytes[at + 4:at + 8].decode("latin-1"), data_bytes[at + 8:at + 8 + length]))
        at += 12 + length
    return chunks


def picture_bytes(path):
    """The file's bytes less a PNG's text chunks (lancer's version and the call or command line that
    made the picture), which differ between the CLI and Python for the same picture."""
    data_bytes = pathlib.Path(path).read_bytes()
    if data_bytes[:8] != b"\x89PNG\r\n\x1a\n":
        return data_bytes
    kept, at = [data_bytes[:8]], 8
    while at + 12 <= len(data_bytes):
        (length,) = struct.unpack(">I", data_bytes[at:at + 4])
        if data_bytes[at + 4:at + 8] not in (b"tEXt", b"iTXt", b"zTXt"):
            kept.append(data_bytes[at:at + 12 + length])
        at += 12 + length
    return b"".join(kept)


@pytest.fixture
def cli():
    return run_cli
