"""lancer.render gives the CLI's bytes (the record of the call that made them aside): for a mesh's quick look, a scene file, with overrides, with
sRGB and transparency, and for animate's GIF."""

import numpy as np
import pytest

import lancer
from conftest import data, picture_bytes, run_cli

BRACKET = data("tests", "data", "render", "bracket_coarse.msh")


def rendered_bytes(tmp_path, image, name="python.png"):
    path = tmp_path / name
    image.save(path)
    return picture_bytes(path)


@pytest.mark.parametrize("extension", [".png", ".bmp", ".ppm"])
def test_mesh_quick_look_is_the_cli_image(tmp_path, extension):
    cli_path = tmp_path / f"cli{extension}"
    run_cli("render", BRACKET, "-o", cli_path, "--width", 96, "--height", 72, "--quiet")
    image = lancer.render(lancer.read_msh(str(BRACKET)), width=96, height=72)
    assert isinstance(image, lancer.Image) and isinstance(image, np.ndarray)
    assert image.shape == (72, 96, 3) and image.dtype == np.uint8
    assert rendered_bytes(tmp_path, image, f"python{extension}") == picture_bytes(cli_path)


def test_scene_file_is_the_cli_image(tmp_path):
    scene_file = data("tests", "data", "render", "bracket_ortho.toml")
    cli_path = tmp_path / "cli.png"
    run_cli("render", scene_file, "-o", cli_path, "--width", 80, "--height", 60, "--samples", 4, "--quiet")
    image = lancer.render(lancer.Scene.load(str(scene_file)), width=80, height=60, samples=4)
    assert rendered_bytes(tmp_path, image) == picture_bytes(cli_path)


def test_overrides_are_the_cli_options(tmp_path):
    cli_path = tmp_path / "cli.png"
    run_cli("render", BRACKET, "-o", cli_path, "--width", 64, "--height", 48, "--shading", "flat", "--srgb",
            "--edges", "--samples", 4, "--quiet")
    image = lancer.render(lancer.read_msh(str(BRACKET)), width=64, height=48, shading="flat", srgb=True,
                          edges=True, samples=4)
    assert image.srgb
    assert rendered_bytes(tmp_path, image) == picture_bytes(cli_path)


def test_transparent_scene_gives_rgba(tmp_path):
    scene_file = data("examples", "shadow_catcher.toml")
    cli_path = tmp_path / "cli.png"
    run_cli("render", scene_file, "-o", cli_path, "--width", 64, "--height", 48, "--quiet")
    image = lancer.render(lancer.Scene.load(str(scene_file)), width=64, height=48)
    assert image.shape == (48, 64, 4)
    assert rendered_bytes(tmp_path, image) == picture_bytes(cli_path)


def test_linear_float_is_what_the_bytes_encode():
    mesh = lancer.read_msh(str(BRACKET))
    linear = lancer.render(mesh, width=40, height=30, dtype="float32", encoding="linear")
    encoded = lancer.render(mesh, width=40, height=30, encoding="linear")
    assert linear.shape == (30, 40, 4) and linear.dtype == np.float32
    assert not encoded.srgb
    expected = np.round(255 * np.clip(linear[..., :3], 0, 1)).astype(np.uint8)
    assert np.array_equal(expected, np.asarray(encoded))
    assert np.all(linear[..., 3] == 1)


def test_uint8_is_srgb_encoded_by_default():
    mesh = lancer.read_msh(str(BRACKET))
    linear = np.clip(lancer.render(mesh, width=40, height=30, dtype="float32")[..., :3].astype(np.float64), 0, 1)
    encoded = lancer.render(mesh, width=40, height=30)
    assert encoded.srgb
    srgb = np.where(linear <= 0.0031308, 12.92 * linear, 1.055 * linear ** (1 / 2.4) - 0.055)
    assert np.max(np.abs(np.round(255 * srgb) - np.asarray(encoded, dtype=np.float64))) <= 1


def test_path_float32_is_the_radiance_the_bytes_encode():
    mesh = lancer.read_msh(str(BRACKET))
    arguments = dict(width=40, height=30, integrator="path", samples=4, noise=0.05, denoise=True)
    linear = lancer.render(mesh, dtype="float32", encoding="linear", **arguments)
    encoded = lancer.render(mesh, encoding="linear", **arguments)
    assert linear.shape == (30, 40, 4) and linear.dtype == np.float32 and np.all(np.isfinite(linear))
    expected = np.round(255 * np.clip(linear[..., :3], 0, 1)).astype(np.uint8)
    assert np.array_equal(expected, np.asarray(encoded))


def test_encoding_tonemap_and_denoise_arguments(tmp_path):
    cli_path = tmp_path / "cli.png"
    run_cli("render", BRACKET, "-o", cli_path, "--width", 48, "--height", 36, "--tonemap", "aces", "--exposure",
            1, "--denoise", "--quiet")
    image = lancer.render(lancer.read_msh(str(BRACKET)), width=48, height=36, tonemap="aces", exposure=1,
                          denoise=True)
    assert rendered_bytes(tmp_path, image) == picture_bytes(cli_path)
    with pytest.raises(ValueError, match="tonemap='agx'"):
        lancer.render(lancer.read_msh(str(BRACKET)), width=8, height=8, tonemap="agx")
    with pytest.raises(ValueError, match="encoding='gamma'"):
        lancer.render(lancer.read_msh(str(BRACKET)), width=8, height=8, encoding="gamma")
    with pytest.raises(lancer.InputError, match="exposure must be a number of stops between -20 and 20, found nan"):
        lancer.render(lancer.read_msh(str(BRACKET)), width=8, height=8, exposure=float("nan"))


def test_repr_png_is_a_png():
    image = lancer.render(lancer.read_msh(str(BRACKET)), width=32, height=24)
    assert image._repr_png_()[:8] == b"\x89PNG\r\n\x1a\n"


def test_arrays_give_the_file_image(tmp_path):
    mesh = lancer.read_msh(str(BRACKET))
    again = lancer.Mesh(mesh.points, mesh.faces, groups=mesh.groups, group_names=mesh.group_names, entities=mesh.entities,
                        name=str(BRACKET))
    assert again.faces.shape == mesh.faces.shape
    first = lancer.render(mesh, width=64, height=48)
    second = lancer.render(again, width=64, height=48)
    assert np.array_equal(first, second)


def test_animate_is_the_cli_gif(tmp_path):
    cli_path = tmp_path / "cli.gif"
    run_cli("animate", BRACKET, "-o", cli_path, "--frames", 3, "--width", 48, "--height", 36, "--quiet")
    python_path = tmp_path / "python.gif"
    lancer.animate(lancer.read_msh(str(BRACKET)), python_path, frames=3, width=48, height=36)
    assert picture_bytes(python_path) == picture_bytes(cli_path)


def test_camera_set_from_python_moves_the_view():
    scene = lancer.Scene.quick_look(lancer.read_msh(str(BRACKET)))
    before = lancer.render(scene, width=48, height=36)
    scene.camera = lancer.Camera(position=(0, 0, 20), look_at=(0, 0, 0), up=(0, 1, 0), fov=35)
    assert tuple(scene.camera.position) == (0, 0, 20) and scene.camera.fov == 35
    after = lancer.render(scene, width=48, height=36)
    assert not np.array_equal(before, after)


def test_path_integrator_and_look_are_the_cli_image(tmp_path):
    cli_path = tmp_path / "cli.png"
    run_cli("render", BRACKET, "-o", cli_path, "--width", 48, "--height", 36, "--look", "studio", "--samples", 8,
            "--noise", 0.05, "--integrator", "path", "--quiet")
    image = lancer.render(lancer.read_msh(str(BRACKET)), width=48, height=36, look="studio", samples=8,
                          noise=0.05, integrator="path")
    assert rendered_bytes(tmp_path, image) == picture_bytes(cli_path)


def test_adaptive_noise_is_the_cli_image(tmp_path):
    cli_path = tmp_path / "cli.png"
    run_cli("render", BRACKET, "-o", cli_path, "--width", 48, "--height", 36, "--look", "studio", "--samples", 16,
            "--adaptive-noise", 0.03, "--denoise", "--quiet")
    image = lancer.render(lancer.read_msh(str(BRACKET)), width=48, height=36, look="studio", samples=16,
                          adaptive_noise=0.03, denoise=True)
    assert rendered_bytes(tmp_path, image) == picture_bytes(cli_path)
    assert image.stats["samples_per_pixel"] < 16


def test_bad_integrator_and_noise_are_value_errors():
    mesh = lancer.read_msh(str(BRACKET))
    with pytest.raises(ValueError, match="integrator='photon'"):
        lancer.render(mesh, width=8, height=8, integrator="photon")
    with pytest.raises(lancer.InputError, match="noise must be greater than 0 and less than 1"):
        lancer.render(mesh, width=8, height=8, integrator="path", noise=1.0)
    for bad in (0.0, -0.1, float("nan"), 1e300):
        with pytest.raises(lancer.InputError, match="adaptive_noise must be greater than 0 and less than 1"):
            lancer.render(mesh, width=8, height=8, integrator="path", adaptive_noise=bad)
