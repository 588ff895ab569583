"""The gmsh view at sizes other than the window's, framed as gmsh prints it: for each print of
tests/data/gmsh_print (made by scripts/make_gmsh_print_fixtures.sh: a view set up in a 160x120
graphics area and exported by gmsh's Print at Print.Width x Print.Height, of a wide and a tall model
and the bracket, orthographic and perspective), lancer's silhouette at the print's size covers the
same pixels as gmsh's (intersection over union at least 0.97), through the CLI and the Python camera."""

import numpy as np
import pytest

import lancer
from conftest import data, run_cli

PRINTS = data("tests", "data", "gmsh_print")
CASES = sorted(path.stem for path in PRINTS.glob("*.opt"))
MIN_IOU = 0.97


def mesh_of(name):
    model = name.split("_")[0]  # wide_ortho_240x100 -> wide
    return data("tests", "data", "gmsh_view", "part.msh") if model == "part" else PRINTS / f"{model}.msh"


def gmsh_silhouette(name):
    return lancer.read_png(str(PRINTS / f"{name}.png"))[..., :3].min(axis=2) < 128  # black model on white


def iou(ours, theirs):
    return (ours & theirs).sum() / (ours | theirs).sum()


def test_the_prints_cover_wide_and_tall_models_and_images_in_both_projections():
    assert {"wide", "tall"} <= {name.split("_")[0] for name in CASES}
    for kind in ("ortho", "perspective"):
        sizes = [name.split("_")[-1] for name in CASES if f"_{kind}_" in name]
        shapes = {int(w) > int(h) for w, h in (size.split("x") for size in sizes)}
        assert shapes == {True, False}, f"{kind}: prints wider and taller than high are both wanted"
    for name in CASES:
        theirs = gmsh_silhouette(name)
        assert theirs.shape[:2] != (120, 160), f"{name}: printed at the window's size"


@pytest.mark.parametrize("name", CASES)
def test_cli_gmsh_view_frames_the_model_as_gmshs_print(tmp_path, name):
    theirs = gmsh_silhouette(name)
    height, width = theirs.shape
    out = tmp_path / "cli.png"
    run_cli("render", mesh_of(name), "--gmsh-view", PRINTS / f"{name}.opt", "-o", out, "--width", width,
            "--height", height, "--quiet")
    image = lancer.read_png(str(out))
    ours = np.any(image[..., :3] != image[0, 0, :3], axis=2)
    assert theirs.sum() > 500, f"{name}: gmsh's print shows almost nothing"
    assert iou(ours, theirs) >= MIN_IOU, f"{name}: silhouette IoU {iou(ours, theirs):.4f}"


@pytest.mark.parametrize("name", CASES)
def test_python_camera_frames_the_model_as_gmshs_print(name):
    theirs = gmsh_silhouette(name)
    scene = lancer.Scene.quick_look(lancer.read_msh(str(mesh_of(name))))
    scene.camera = lancer.Camera.from_gmsh_file(str(PRINTS / f"{name}.opt"))
    image = lancer.render(scene, width=theirs.shape[1], height=theirs.shape[0], transparent_background=True)
    ours = np.asarray(image)[..., 3] > 127
    assert iou(ours, theirs) >= MIN_IOU, f"{name}: silhouette IoU {iou(ours, theirs):.4f}"
