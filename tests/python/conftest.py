"""Shared helpers for the Python tests: where the CLI and the fixtures are (CTest sets
LANCER_CLI and LANCER_SOURCE_DIR; PYTHONPATH points at build/python), and a CLI runner."""

import os
import pathlib
import subprocess

import pytest

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


@pytest.fixture
def cli():
    return run_cli
