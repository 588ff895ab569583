"""The view set up in gmsh, reproduced: for each view of tests/data/gmsh_view (made by
scripts/make_gmsh_view_fixtures.sh: the options file gmsh saves and gmsh's own PNG of the view),
lancer's silhouette of the model agrees with gmsh's to within 2 pixels, through the Python camera,
the CLI's --gmsh-view and a scene file's [camera] gmsh_view."""

import numpy as np
import pytest

import lancer
from conftest import data, run_cli

VIEWS = data("tests", "data", "gmsh_view")
CASES = sorted(path.stem for path in VIEWS.glob("*.opt"))
TOLERANCE = 2  # pixels


def gmsh_silhouette(name):
    return lancer.read_png(str(VIEWS / f"{name}.png"))[..., :3].min(axis=2) < 128  # black model on white


def dilate(mask, radius):
    grown = np.zeros_like(mask)
    padded = np.pad(mask, radius)
    height, width = mask.shape
    for dy in range(2 * radius + 1):
        for dx in range(2 * radius + 1):
            grown |= padded[dy:dy + height, dx:dx + width]
    return grown


def assert_same_silhouette(ours, theirs, name):
    assert ours.shape == theirs.shape
    assert theirs.sum() > 200, f"{name}: gmsh's image shows almost nothing"
    outside_theirs = ours & ~dilate(theirs, TOLERANCE)
    outside_ours = theirs & ~dilate(ours, TOLERANCE)
    assert not outside_theirs.any() and not outside_ours.any(), (
        f"{name}: {outside_theirs.sum()} lancer pixels and {outside_ours.sum()} gmsh pixels are more than "
        f"{TOLERANCE} pixels from the other's silhouette")


def test_the_fixtures_cover_every_kind_of_view():
    assert {"euler_xyz", "trackball_x", "trackball_y", "trackball_z", "translated_scaled", "perspective"} <= set(CASES)


@pytest.mark.parametrize("name", CASES)
def test_python_camera_matches_gmsh(name):
    theirs = gmsh_silhouette(name)
    scene = lancer.Scene.quick_look(lancer.read_msh(str(VIEWS / "part.msh")))
    scene.camera = lancer.Camera.from_gmsh_file(str(VIEWS / f"{name}.opt"))
    image = lancer.render(scene, width=theirs.shape[1], height=theirs.shape[0], transparent_background=True)
    assert_same_silhouette(np.asarray(image)[..., 3] > 127, theirs, name)


@pytest.mark.parametrize("name", ["euler_xyz", "perspective"])
def test_cli_gmsh_view_matches_gmsh(tmp_path, name):
    theirs = gmsh_silhouette(name)
    out = tmp_path / "cli.png"
    run_cli("render", VIEWS / "part.msh", "--gmsh-view", VIEWS / f"{name}.opt", "-o", out, "--width",
            theirs.shape[1], "--height", theirs.shape[0], "--quiet")
    background = lancer.read_png(str(out))[0, 0, :3]
    ours = np.any(lancer.read_png(str(out))[..., :3] != background, axis=2)
    assert_same_silhouette(ours, theirs, name)


def test_scene_key_and_default_file_beside_the_mesh(tmp_path):
    import shutil

    shutil.copy(VIEWS / "part.msh", tmp_path / "part.msh")
    shutil.copy(VIEWS / "trackball_y.opt", tmp_path / "part.msh.opt")
    theirs = gmsh_silhouette("trackball_y")
    size = ["--width", theirs.shape[1], "--height", theirs.shape[0], "--quiet"]
    run_cli("render", tmp_path / "part.msh", "--gmsh-view", "-o", tmp_path / "default.png", *size)
    scene = tmp_path / "scene.toml"
    scene.write_text('[camera]\ngmsh_view = "part.msh.opt"\n[render]\nbackground = "transparent"\n'
                     '[[mesh]]\nfile = "part.msh"\n')
    run_cli("render", scene, "-o", tmp_path / "scene.png", *size)
    default = lancer.read_png(str(tmp_path / "default.png"))
    ours = np.any(default[..., :3] != default[0, 0, :3], axis=2)
    assert_same_silhouette(ours, theirs, "--gmsh-view (part.msh.opt)")
    assert_same_silhouette(lancer.read_png(str(tmp_path / "scene.png"))[..., 3] > 127, theirs, "gmsh_view key")


def test_bad_gmsh_view_files(tmp_path):
    with pytest.raises(lancer.InputError, match="cannot open this gmsh options file"):
        lancer.Camera.from_gmsh_file(str(tmp_path / "missing.opt"))
    bad = tmp_path / "bad.opt"
    bad.write_text("General.RotationX = 30;\nGeneral.RotationY = twenty;\n")
    with pytest.raises(lancer.InputError, match="General.RotationY should be a number") as caught:
        lancer.Camera.from_gmsh_file(str(bad))
    assert caught.value.line == 2
    scene = tmp_path / "scene.toml"
    scene.write_text('[camera]\ngmsh_view = "part.msh.opt"\nfov = 30\n[[mesh]]\nfile = "part.msh"\n')
    with pytest.raises(lancer.InputError, match="camera.fov and camera.gmsh_view both set the camera"):
        lancer.Scene.load(str(scene))


def test_live_gmsh_view(tmp_path):
    import gmsh

    gmsh.initialize(["lancer-test"], readConfigFiles=False)
    try:
        gmsh.option.setNumber("General.Terminal", 0)
        gmsh.open(str(VIEWS / "part.msh"))
        gmsh.merge(str(VIEWS / "translated_scaled.opt"))
        camera = lancer.Camera.from_gmsh()
        mesh = lancer.from_gmsh()
    finally:
        gmsh.finalize()
    theirs = gmsh_silhouette("translated_scaled")
    scene = lancer.Scene.quick_look(mesh)
    scene.camera = camera
    image = lancer.render(scene, width=theirs.shape[1], height=theirs.shape[0], transparent_background=True)
    assert_same_silhouette(np.asarray(image)[..., 3] > 127, theirs, "Camera.from_gmsh()")


def test_quick_look_lights_follow_a_gmsh_view(tmp_path):
    """Seen from behind (gmsh's RotationY = 160), the part is lit as well as in the default view:
    the quick look's key and fill follow the gmsh camera instead of staying at the automatic one."""
    behind = tmp_path / "behind.opt"
    behind.write_text("General.Trackball = 0;\nGeneral.RotationY = 160;\nGeneral.RotationX = 25;\n")
    mesh = lancer.read_msh(str(VIEWS / "part.msh"))

    def part_brightness(scene):
        image = np.asarray(lancer.render(scene, width=160, height=120, transparent_background=True), dtype=float)
        covered = image[..., 3] > 127
        return image[..., :3][covered].mean()

    default = part_brightness(lancer.Scene.quick_look(mesh))
    scene = lancer.Scene.quick_look(mesh)
    scene.camera = lancer.Camera.from_gmsh_file(str(behind))
    assert part_brightness(scene) > 0.8 * default
