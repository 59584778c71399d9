"""The rast8 command: decode / stats on files and stdin, JSON output,
clear errors for bad sources."""
import json
import pytest
import subprocess
import sys

from PIL import Image

RAST8 = [sys.executable, "-m", "rast8.cli"]


def test_decode_stdin_writes_pngs_and_gif(emu_stream, tmp_path):
    stream, frames = emu_stream("--frames", "5")
    out = tmp_path / "o"
    r = subprocess.run(RAST8 + ["decode", "-", "-o", str(out), "--gif", str(tmp_path / "a.gif")],
                       input=stream, capture_output=True)
    assert r.returncode == 0, r.stderr
    assert b"5 frames" in r.stdout
    assert len(list(out.glob("frame_*.png"))) == 5
    assert Image.open(tmp_path / "a.gif").n_frames == 5


def test_stats_json(emu_stream, tmp_path):
    stream, frames = emu_stream("--frames", "8")
    f = tmp_path / "s.bin"
    f.write_bytes(stream)
    r = subprocess.run(RAST8 + ["stats", str(f), "--json"], capture_output=True, text=True)
    st = json.loads(r.stdout)
    assert st["frames"] == 8 and st["bytes"] == len(stream)
    assert st["bytes_per_frame"] == round(len(stream) / 8, 1)
    raw = sum(len(fr.pixels) for fr in frames)
    assert st["compression_ratio"] == round(raw / len(stream), 2)
    assert st["errors"] == 0
    r = subprocess.run(RAST8 + ["stats", str(f)], capture_output=True, text=True)
    assert "bytes/frame" in r.stdout and "incomplete frames" in r.stdout


def test_stats_counts_errors_in_a_damaged_file(emu_stream, tmp_path):
    stream, _ = emu_stream("--frames", "8", "--no-dirty")
    bad = bytearray(stream)
    bad[len(bad) // 2] ^= 0x40
    f = tmp_path / "bad.bin"
    f.write_bytes(bytes(bad))
    st = json.loads(subprocess.run(RAST8 + ["stats", str(f), "--json"],
                                   capture_output=True, text=True).stdout)
    assert st["frames"] == 7 and st["bad_packets"] >= 1 and st["errors"] >= 1


def test_missing_source_is_a_clear_error(tmp_path):
    r = subprocess.run(RAST8 + ["stats", str(tmp_path / "nope.bin")], capture_output=True, text=True)
    assert r.returncode == 2
    assert "cannot open" in r.stderr


def test_help():
    r = subprocess.run(RAST8 + ["--help"], capture_output=True, text=True)
    assert r.returncode == 0
    for cmd in ("decode", "stats", "view", "SOURCE", "socket://", "loop://"):
        assert cmd in r.stdout


# ---- issue 12 items 7-9: one clear line, never a traceback; honest exit codes

def _run(args, **kw):
    return subprocess.run(RAST8 + args, capture_output=True, text=True, **kw)


def _one_line_error(r, words):
    assert r.returncode != 0
    assert "Traceback" not in r.stderr
    lines = [l for l in r.stderr.splitlines() if l.strip()]
    assert len(lines) == 1, r.stderr
    assert words in lines[0], lines[0]


@pytest.fixture
def good_file(emu_stream, tmp_path):
    stream, _ = emu_stream("--frames", "4")
    f = tmp_path / "good.bin"
    f.write_bytes(stream)
    return f


def test_decode_output_is_an_existing_file(good_file, tmp_path):
    f = tmp_path / "afile"
    f.write_text("x")
    _one_line_error(_run(["decode", str(good_file), "-o", str(f)]), "not a directory")
    assert f.read_text() == "x"


def test_decode_output_unwritable(good_file, tmp_path):
    _one_line_error(_run(["decode", str(good_file), "-o", "/proc/nope/out"]), "cannot create")


def test_decode_gif_is_a_directory(good_file, tmp_path):
    _one_line_error(_run(["decode", str(good_file), "-o", str(tmp_path / "o"),
                          "--gif", str(tmp_path)]), "is a directory")


@pytest.mark.parametrize("scale", ["0", "-3", "x"])
def test_decode_bad_scale(good_file, tmp_path, scale):
    _one_line_error(_run(["decode", str(good_file), "-o", str(tmp_path / "o"), "--scale", scale]),
                    "--scale")


def test_stats_negative_frames(good_file):
    _one_line_error(_run(["stats", str(good_file), "--frames", "-1"]), "--frames")


def test_empty_input_prints_no_none(tmp_path):
    f = tmp_path / "empty.bin"
    f.write_bytes(b"")
    for cmd in (["stats", str(f)], ["stats", str(f), "--json"],
                ["decode", str(f), "-o", str(tmp_path / "o")]):
        r = _run(cmd)
        assert r.returncode == 1 and "None" not in r.stdout + r.stderr, (cmd, r.stdout)
        assert "no frame" in r.stderr


def test_file_source_has_no_frame_rate(good_file):
    r = _run(["stats", str(good_file)])
    assert r.returncode == 0 and "frames/s" not in r.stdout
    assert json.loads(_run(["stats", str(good_file), "--json"]).stdout)["fps"] is None


def test_errors_give_exit_1_unless_lossy(emu_stream, tmp_path):
    stream, _ = emu_stream("--frames", "8", "--no-dirty")
    bad = bytearray(stream)
    bad[len(bad) // 2] ^= 0x40
    f = tmp_path / "bad.bin"
    f.write_bytes(bytes(bad))
    for cmd in (["stats", str(f)], ["decode", str(f), "-o", str(tmp_path / "o")]):
        r = _run(cmd)
        assert r.returncode == 1 and "--lossy" in r.stderr, r.stderr
        assert _run(cmd + ["--lossy"]).returncode == 0
    # a stream cut inside a packet is an error too (the unterminated tail)
    f.write_bytes(stream[:-3])
    st = json.loads(_run(["stats", str(f), "--json"]).stdout)
    assert st["bad_packets"] == 1 and st["incomplete"] == 1
    assert _run(["stats", str(f)]).returncode == 1


def test_subcommand_help_says_what_source_is():
    for cmd in ("decode", "stats", "view"):
        r = _run([cmd, "--help"])
        assert r.returncode == 0 and "SOURCE:" in r.stdout and "socket://" in r.stdout
    out = _run(["decode", "--help"]).stdout
    import re
    # every option has a help line
    opts = re.findall(r"^  (-[-\w, ]+?)(?:\s{2,}(\S.*))?$", out, re.M)
    assert opts and all(h for o, h in opts if o.strip() not in ("-h, --help",)), opts


def test_scene_subcommand(tmp_path):
    r = _run(["scene", "list"])
    assert r.returncode == 0 and "cube" in r.stdout and "teapot" in r.stdout
    r = _run(["scene", "check", "cube"])
    assert r.returncode == 0 and "convex" in r.stdout
    r = _run(["scene", "blob", "cube", str(tmp_path / "c.bin")])
    assert r.returncode == 0 and (tmp_path / "c.bin").read_bytes()[:4] == b"R8SC"
    r = _run(["scene", "c", str(tmp_path / "s.c"), "cube"])
    assert r.returncode == 0 and "r8_demo_cube" in (tmp_path / "s.c").read_text()
    _one_line_error(_run(["scene", "check", "nosuch"]), "not a built-in scene")
