"""build/rast8-emu: options, RAM budget, outputs (stdout, file, pty, TCP),
end to end emulator -> pty -> pyserial -> decoder -> PNG equal to the
emulator's framebuffer dump, full-frame requests, and 8N1 pacing."""
import json
import os
import subprocess
import sys
import time

import pytest
from PIL import Image

from rast8.protocol import StreamDecoder, read_dump, request_packet
from rast8.source import open_source

RAST8 = [sys.executable, "-m", "rast8.cli"]


def run(*args, **kw):
    return subprocess.run(list(args), capture_output=True, **kw)


def test_help_lists_scenes_methods_and_exits_0(emu):
    r = run(emu, "--help", text=True)
    assert r.returncode == 0
    for word in ("--out", "--pty", "--tcp", "--baud", "--ram", "--scene", "--method",
                 "--band", "--frames", "--width", "--height", "--format", "--codec",
                 "--dump", "cube", "auto", "cull"):
        assert word in r.stdout


@pytest.mark.parametrize("args,msg", [
    (["--scene", "nope"], "unknown scene"),
    (["--method", "nope"], "unknown method"),
    (["--codec", "zip"], "unknown codec"),
    (["--format", "rgb"], "unknown format"),
    (["--frames", "abc"], "bad number"),
    (["--band", "3"], "invalid configuration"),
    (["--width", "0"], "bad number"),
    (["--bogus"], "see --help"),
    (["extra"], "unexpected argument"),
    (["--pty", "--out", "x"], "choose one"),
])
def test_bad_options_fail_with_a_message(emu, args, msg):
    r = run(emu, *args, text=True)
    assert r.returncode == 2
    assert msg in r.stderr
    assert r.stdout == ""


def test_ram_budget(emu, tmp_path):
    r = run(emu, "--print-ram", text=True)
    need = int(r.stdout.split()[0])
    assert need > 0
    r = run(emu, "--ram", str(need - 1), "--out", str(tmp_path / "x"), text=True)
    assert r.returncode == 3
    assert "needs %d bytes" % need in r.stderr
    r = run(emu, "--ram", str(need), "--frames", "2", "--out", str(tmp_path / "x"), text=True)
    assert r.returncode == 0, r.stderr


def test_stdout_equals_file_and_method_auto(emu, tmp_path):
    f = tmp_path / "s.bin"
    a = run(emu, "-q", "--frames", "4", "--out", "-")
    b = run(emu, "-q", "--frames", "4", "--out", str(f))
    assert a.returncode == b.returncode == 0
    assert a.stdout == f.read_bytes() and len(a.stdout) > 0
    # auto: the analyser chooses (tests/py/test_analyser.py checks what)
    c = run(emu, "-q", "--frames", "2", "--method", "auto")
    assert c.returncode == 0, c.stderr
    assert StreamDecoder().feed(c.stdout)


def page1_pixel(fb, w, x, y):
    return (fb[(y // 8) * w + x] >> (y % 8)) & 1


def start_pty(emu, *args):
    p = subprocess.Popen([emu, "--pty"] + list(args), stdout=subprocess.PIPE,
                         stderr=subprocess.PIPE, text=True)
    path = p.stdout.readline().strip()
    assert path.startswith("/dev/"), p.stderr.read()
    return p, path


def test_end_to_end_pty_pyserial_png_equals_framebuffer(emu, tmp_path):
    dump = tmp_path / "ref.r8fb"
    p, path = start_pty(emu, "--frames", "16", "--dump", str(dump), "--linger", "10")
    out = tmp_path / "png"
    r = run(*RAST8, "decode", path, "-o", str(out), "--frames", "16", "--idle", "10",
            "--json", text=True)
    assert r.returncode == 0, r.stderr
    assert p.wait(timeout=20) == 0, p.stderr.read()
    st = json.loads(r.stdout)
    assert st["frames"] == 16 and st["errors"] == 0
    ref = read_dump(str(dump))
    assert len(ref) == 16
    for fr in ref:
        img = Image.open(out / ("frame_%05d.png" % fr.number)).convert("L")
        assert img.size == (fr.width, fr.height)
        px = img.load()
        for y in range(fr.height):
            for x in range(fr.width):
                assert (px[x, y] != 0) == bool(page1_pixel(fr.pixels, fr.width, x, y)), (fr.number, x, y)
    gif = Image.open(out / "anim.gif")
    assert gif.n_frames == 16


def test_tcp_socket_url(emu):
    p = subprocess.Popen([emu, "--tcp", "0", "--frames", "8", "--linger", "5"],
                         stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    port = int(p.stdout.readline())
    r = run(*RAST8, "stats", "socket://127.0.0.1:%d" % port, "--json", "--idle", "10", text=True)
    assert p.wait(timeout=20) == 0
    st = json.loads(r.stdout)
    assert st["frames"] == 8 and st["errors"] == 0


def test_full_frame_on_request_over_pty(emu):
    """With no periodic full frames, a REQUEST from the viewer makes the
    firmware send one."""
    p, path = start_pty(emu, "--frames", "30", "--full-period", "0", "--baud", "40000",
                        "--linger", "10")
    src = open_source(path, idle=10)
    dec = StreamDecoder()
    got = []
    sent = False
    while len(got) < 30:
        data = src.read(4096)
        if not data:
            break
        got += dec.feed(data)
        if len(got) >= 5 and not sent:
            src.write(request_packet())
            sent = got[-1].number
    src.close()
    p.wait(timeout=20)
    fulls = [f.number for f in got if f.full]
    assert fulls[0] == 0
    assert [n for n in fulls if n > sent], (sent, fulls)   # the requested one
    assert dec.bad_packets == dec.dropped == dec.incomplete == 0


def test_pacing_matches_8n1(emu, tmp_path):
    """Correctness of --baud: the run takes bytes * 10 / baud (within 5%)."""
    f = tmp_path / "paced.bin"
    baud = 38400
    t0 = time.monotonic()
    r = run(emu, "-q", "--frames", "10", "--baud", str(baud), "--out", str(f))
    dt = time.monotonic() - t0
    assert r.returncode == 0
    ideal = f.stat().st_size * 10 / baud
    assert ideal > 0.5
    assert abs(dt - ideal) <= 0.05 * ideal, (dt, ideal)
