"""The examples of docs/python.md marked `<!-- tested: ... -->` run as written (in order, in one
namespace, in an empty folder) and write the pictures they say."""

import os
import re

import numpy as np

import lancer
from conftest import data

MARK = "<!-- tested: tests/python/test_python_docs.py"


def marked_blocks():
    text = data("docs", "python.md").read_text()
    return re.findall(re.escape(MARK) + r"[^\n]*\n```python\n(.*?)```", text, flags=re.S)


def test_marked_examples_run(tmp_path):
    blocks = marked_blocks()
    assert len(blocks) == 2
    namespace = {}
    here = os.getcwd()
    os.chdir(tmp_path)
    try:
        for block in blocks:
            exec(compile(block, "docs/python.md", "exec"), namespace)
    finally:
        os.chdir(here)
    for name, size in (("plate.png", (320, 480)), ("two_plates.png", (320, 480)), ("ids.png", (120, 160))):
        picture = lancer.read_png(str(tmp_path / name))
        assert picture.shape[:2] == size
        assert len(np.unique(picture.reshape(-1, 4), axis=0)) > 50, name  # a coloured field, not a blank
