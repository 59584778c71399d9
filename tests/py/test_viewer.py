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
