"""rast8-emu --method auto: the analyser's choice per built-in scene, the
band it picks for a RAM budget, and a clear failure when nothing fits.
The choice itself is checked to render exactly like the 16-bit z-buffer
in tests/host/test_visibility.c."""
import re
import subprocess

import pytest

from rast8.protocol import StreamDecoder, read_dump

EXPECT = {"cube": "cull", "torus": "zbuf16", "teapot": "zbuf16", "terrain": "zbuf16",
          "wall": "zbuf16", "cross": "bsp", "separate": "painter",
          "crate": "cull", "maze": "ray", "tmaze": "ray",
          "rooms": "portal"}


@pytest.mark.parametrize("scene", sorted(EXPECT))
def test_auto_picks_the_cheapest_exact_method(emu, tmp_path, scene):
    out, dump = tmp_path / "s.bin", tmp_path / "s.r8fb"
    r = subprocess.run([emu, "--scene", scene, "--method", "auto", "--frames", "3",
                        "--out", str(out), "--dump", str(dump)], capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    m = re.search(r"analyser: scene (\w+) -> method (\w+) \(([^)]*)\), band (\d+) rows, "
                  r"renderer\+band (\d+) bytes", r.stderr)
    assert m, r.stderr
    assert m.group(1) == scene and m.group(2) == EXPECT[scene]
    assert int(m.group(5)) <= 16384
    # the stream decodes to the emulator's own frames
    dec = StreamDecoder()
    frames = dec.feed(out.read_bytes())
    ref = read_dump(str(dump))
    assert len(frames) == len(ref) == 3
    for f, d in zip(frames, ref):
        assert bytes(f.pixels) == bytes(d.pixels)


def test_auto_band_fits_the_ram_budget(emu, tmp_path):
    sizes = {}
    for ram in (1400, 2400, 8000):
        r = subprocess.run([emu, "--scene", "cube", "--method", "auto", "--ram", str(ram),
                            "--frames", "1", "--out", str(tmp_path / "c.bin")],
                           capture_output=True, text=True)
        assert r.returncode == 0, r.stderr
        band = int(re.search(r"band (\d+) rows", r.stderr).group(1))
        used = int(re.search(r"RAM (\d+) of (\d+) bytes", r.stderr).group(1))
        assert band % 8 == 0 and used <= ram
        sizes[ram] = band
    assert sizes[1400] <= sizes[2400] <= sizes[8000]
    assert sizes[1400] == 8 and sizes[8000] == 64


def test_auto_says_when_nothing_fits(emu, tmp_path):
    r = subprocess.run([emu, "--scene", "teapot", "--method", "auto", "--ram", "900",
                        "--frames", "1", "--out", str(tmp_path / "t.bin")],
                       capture_output=True, text=True)
    assert r.returncode == 3
    assert "nothing fits 900 bytes of RAM for scene teapot" in r.stderr
