"""Image.save to JPEG and WebP, the DPI and the provenance a saved picture records, and MP4/WebM from
lancer.animate; bad quality and DPI values are errors that write nothing."""

import shutil
import subprocess

import numpy as np
import pytest

import lancer
from conftest import data, png_chunks

BRACKET = data("tests", "data", "render", "bracket_coarse.msh")


@pytest.fixture(scope="module")
def image():
    return lancer.render(lancer.read_msh(str(BRACKET)), width=64, height=48)


def test_png_records_dpi_version_and_the_call(tmp_path, image):
    image.save(tmp_path / "a.png", dpi=300)
    chunks = dict(png_chunks(tmp_path / "a.png"))
    assert chunks["pHYs"] == (11811).to_bytes(4, "big") * 2 + b"\x01"
    texts = [data for kind, data in png_chunks(tmp_path / "a.png") if kind == "tEXt"]
    assert b"Software\x00lancer " + lancer.__version__.encode() in texts
    assert any(t.startswith(b"Comment\x00lancer.render(<lancer.") and b"width=64, height=48)" in t for t in texts)


def test_jpeg_and_webp_by_extension(tmp_path, image):
    image.save(tmp_path / "a.jpg", quality=80, dpi=150)
    jpeg = (tmp_path / "a.jpg").read_bytes()
    assert jpeg[:2] == b"\xff\xd8" and jpeg[6:11] == b"JFIF\x00"
    assert jpeg[13] == 1 and int.from_bytes(jpeg[14:16], "big") == 150
    assert b"lancer.render(" in jpeg  # the COM marker
    image.save(tmp_path / "a.webp", lossless=True)
    webp = (tmp_path / "a.webp").read_bytes()
    assert webp[:4] == b"RIFF" and webp[8:12] == b"WEBP" and b"EXIF" in webp
    assert (tmp_path / "a.webp").stat().st_size < (tmp_path / "a.jpg").stat().st_size * 4


@pytest.mark.parametrize("arguments, message", [
    ({"quality": 0}, "quality: error: quality 0 is out of range"),
    ({"quality": 101}, "quality: error: quality 101 is out of range"),
    ({"dpi": 0}, "dpi: error: 0 is not a resolution in dots per inch"),
    ({"dpi": -3.0}, "dpi: error: -3 is not a resolution in dots per inch"),
])
def test_bad_quality_or_dpi_writes_nothing(tmp_path, image, arguments, message):
    with pytest.raises(lancer.InputError, match=message):
        image.save(tmp_path / "a.jpg", **arguments)
    assert list(tmp_path.iterdir()) == []


def test_unknown_extension_lists_the_formats(tmp_path, image):
    with pytest.raises(lancer.InputError, match=r"the supported extensions are .png, .jpg, .jpeg, .webp"):
        image.save(tmp_path / "a.tif")
    assert list(tmp_path.iterdir()) == []


@pytest.mark.skipif(shutil.which("ffprobe") is None, reason="ffprobe is not installed (apt-get install ffmpeg)")
@pytest.mark.parametrize("name, codec", [("turn.mp4", "h264"), ("turn.webm", "vp9")])
def test_animate_writes_video(tmp_path, name, codec):
    scene = lancer.Scene.load(str(data("tests", "data", "render", "turntable.toml")))
    try:
        lancer.animate(scene, tmp_path / name, frames=3)
    except lancer.InputError as error:
        if "built without FFmpeg" in str(error):
            pytest.skip("this lancer was built without FFmpeg (-DLANCER_FFMPEG=OFF)")
        raise
    probe = subprocess.run(["ffprobe", "-v", "error", "-select_streams", "v:0", "-count_frames", "-show_entries",
                            "stream=codec_name,width,height,nb_read_frames:format_tags=comment", "-of",
                            "default=nw=1", str(tmp_path / name)], capture_output=True, text=True, check=True)
    assert f"codec_name={codec}" in probe.stdout and "nb_read_frames=3" in probe.stdout
    assert "width=64" in probe.stdout and "height=48" in probe.stdout
    assert "lancer.animate(" in probe.stdout
    assert [p.name for p in tmp_path.iterdir()] == [name]
