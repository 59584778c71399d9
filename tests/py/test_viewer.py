"""rast8 view, headless under Xvfb: a screenshot of the live window's
frame area equals the decoded frame scaled up."""
import shutil
import subprocess
import sys

import pytest
from PIL import Image, ImageChops

from rast8.protocol import StreamDecoder


@pytest.mark.skipif(not shutil.which("xvfb-run"), reason="needs Xvfb (scripts/setup.sh installs it)")
@pytest.mark.parametrize("fmt", ["page1", "idx8"])
def test_view_screenshot_matches_frame(emu_stream, tmp_path, fmt):
    stream, frames = emu_stream("--frames", "6", "--format", fmt, name=fmt)
    src = tmp_path / "s.bin"
    src.write_bytes(stream)
    shot = tmp_path / "shot.png"
    r = subprocess.run(["xvfb-run", "-a", "-s", "-screen 0 800x600x24",
                        sys.executable, "-m", "rast8.cli", "view", str(src),
                        "--scale", "3", "--screenshot", str(shot)],
                       capture_output=True, text=True, timeout=60)
    assert r.returncode == 0, r.stderr
    last = StreamDecoder().feed(stream)[-1]
    assert last.pixels == frames[-1].pixels
    want = last.to_image(3).convert("RGB")
    got = Image.open(shot).convert("RGB")
    assert got.size == want.size
    assert ImageChops.difference(got, want).getbbox() is None


@pytest.mark.skipif(not shutil.which("xvfb-run"), reason="needs Xvfb")
def test_view_live_over_pty_serial(emu, tmp_path):
    """The window on a live, paced serial line (emulator pty + pyserial)."""
    from rast8.protocol import read_dump
    dump = tmp_path / "ref.r8fb"
    p = subprocess.Popen([emu, "--pty", "--frames", "8", "--baud", "115200", "--dump", str(dump),
                          "--linger", "10"], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    path = p.stdout.readline().strip()
    shot = tmp_path / "live.png"
    r = subprocess.run(["xvfb-run", "-a", "-s", "-screen 0 800x600x24",
                        sys.executable, "-m", "rast8.cli", "view", path, "--frames", "8",
                        "--scale", "2", "--screenshot", str(shot)],
                       capture_output=True, text=True, timeout=60)
    assert r.returncode == 0, r.stderr
    assert p.wait(timeout=20) == 0
    last = read_dump(str(dump))[-1]
    want = last.to_image(2).convert("RGB")
    assert ImageChops.difference(Image.open(shot).convert("RGB"), want).getbbox() is None
    assert "errors 0" in r.stdout
