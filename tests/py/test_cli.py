"""The rast8 command: decode / stats on files and stdin, JSON output,
clear errors for bad sources."""
import json
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
