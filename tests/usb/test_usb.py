"""USB transport tests, without hardware: umockdev emulates a vendor-class
board feed:beef whose bulk IN endpoint 0x81 delivers a real rast8 stream.

The stream comes from build/rast8-emu at test time and tests/usb/mkioctl.py
turns it into the usbdevfs ioctl script, so the fixture always matches the
current protocol.  Frames decoded through `rast8 decode usb:...` and through
`rast8-usbcat | rast8 decode -` must equal the frames decoded from the
stream file, exactly.

umockdev replays each bulk IN reply at once; it cannot make a device go
silent, refuse a claim or deny access.  build/usb/faultshim.so (LD_PRELOAD,
in front of umockdev's library) fakes those kernel answers, so that the
timeout, idle end, busy and permission cases still run libusb's real code.
"""
import json
import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

HERE = Path(__file__).resolve().parent
ROOT = HERE.parents[1]
BUILD = ROOT / "build"
USBCAT = BUILD / "rast8-usbcat"
SHIM = BUILD / "usb" / "faultshim.so"
EMU = BUILD / "rast8-emu"
RAST8 = Path(sys.executable).parent / "rast8"
FRAMES = 16
SPEC = "usb:feed:beef"

sys.path.insert(0, str(HERE))
import mkioctl  # noqa: E402

# exit codes shared by rast8-usbcat and rast8.usb
EX_USAGE, EX_NODEV, EX_ACCESS, EX_BUSY, EX_UNPLUGGED, EX_STALL, EX_TIMEOUT = 2, 3, 4, 5, 6, 7, 8


# ------------------------------------------------------------------ fixtures

@pytest.fixture(scope="session")
def work(tmp_path_factory):
    return tmp_path_factory.mktemp("usb")


@pytest.fixture(scope="session")
def stream(work):
    """A real encoded stream of several frames, from the emulator."""
    assert EMU.exists(), f"{EMU} is missing: run make"
    out = work / "stream.bin"
    r = subprocess.run([str(EMU), "--scene", "cube", "--frames", str(FRAMES), "--out", str(out)],
                       capture_output=True, text=True, timeout=120)
    assert r.returncode == 0, r.stderr
    data = out.read_bytes()
    assert len(data) > 1000, "the emulator stream is unexpectedly small"
    return out


@pytest.fixture(scope="session")
def bed(work):
    path = work / "bed.umockdev"
    r = subprocess.run([sys.executable, str(HERE / "mkioctl.py"), "device", str(path)],
                       capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    return path


def make_script(stream, work, name, fault=None, at=None, addr=None, bus=None, ep=None):
    """Run the generator; returns (ioctl path, replies, bytes delivered)."""
    path = work / f"{name}.ioctl"
    cmd = [sys.executable, str(HERE / "mkioctl.py"), "ioctl", str(stream), str(path)]
    if fault:
        cmd += ["--fault", fault, "--at", str(at)]
    if addr:
        cmd += ["--addr", str(addr)]
    if bus:
        cmd += ["--bus", str(bus)]
    if ep:
        cmd += ["--ep", ep]
    r = subprocess.run(cmd, capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    replies, delivered = map(int, r.stdout.split())
    return path, replies, delivered


@pytest.fixture(scope="session")
def clean(stream, work):
    return make_script(stream, work, "clean")


def mock(bed, ioctl, cmd, fault=None, timeout=60, stdin=None):
    """Run cmd inside umockdev-run with the fault shim in front."""
    env = dict(os.environ)
    env.pop("RAST8_USB_FAULT", None)
    env.pop("RAST8_USB_BACKEND", None)
    if fault:
        env["RAST8_USB_FAULT"] = fault
    full = ["umockdev-run", "--device", str(bed)]
    if ioctl and not isinstance(ioctl, dict):
        ioctl = {mkioctl.DEVNODE: ioctl}
    for node, script in (ioctl or {}).items():
        full += ["--ioctl", f"{node}={script}"]
    full += ["--", "sh", "-c", 'LD_PRELOAD="$0${LD_PRELOAD:+:$LD_PRELOAD}" exec "$@"',
             str(SHIM)] + [str(c) for c in cmd]
    return subprocess.run(full, env=env, capture_output=True, timeout=timeout, stdin=stdin)


def frames_in(directory):
    """Decoded frames of a `rast8 decode -o DIR` run: name -> (mode, size, pixels)."""
    from PIL import Image
    out = {}
    for p in sorted(Path(directory).glob("*.png")):
        with Image.open(p) as im:
            out[p.name] = (im.mode, im.size, im.tobytes())
    return out


def decode(source, outdir, **kw):
    r = subprocess.run([str(RAST8), "decode", str(source), "-o", str(outdir)],
                       capture_output=True, timeout=120, **kw)
    return r


@pytest.fixture(scope="session")
def reference(stream, work):
    """Frames decoded from the stream file directly."""
    d = work / "ref"
    r = decode(stream, d)
    assert r.returncode == 0, r.stderr.decode()
    frames = frames_in(d)
    assert len(frames) == FRAMES
    return frames


def prefix_frames(stream, n, work, name):
    """Frames decoded from the first n bytes of the stream, as a file."""
    part = work / f"{name}.prefix.bin"
    part.write_bytes(stream.read_bytes()[:n])
    d = work / f"{name}.prefix"
    decode(part, d)          # a cut stream may end with a warning; frames count
    return frames_in(d)


@pytest.fixture(scope="session")
def bed2(work):
    """Two identical boards feed:beef, at addresses 2 and 4."""
    path = work / "bed2.umockdev"
    r = subprocess.run([sys.executable, str(HERE / "mkioctl.py"), "device", str(path),
                        "--boards", "2"], capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    return path


def usbread(bed, ioctl, spec, out, fault=None, chunk=1000, backend=None):
    cmd = ["env"] + ([f"RAST8_USB_BACKEND={backend}"] if backend else []) + \
        [sys.executable, HERE / "usbread.py", spec, out, str(chunk)]
    r = mock(bed, ioctl, cmd, fault=fault)
    lines = r.stdout.decode().strip().splitlines()
    assert lines, r.stderr.decode()
    return r.returncode, json.loads(lines[-1])


# ------------------------------------------------------------------ spec / usage (no device)

def test_spec_parsing():
    from rast8.usb import parse_spec
    s = parse_spec("usb:FEED:beef")
    assert (s["vid"], s["pid"], s["ep"], s["idle"]) == (0xFEED, 0xBEEF, 0x81, None)
    s = parse_spec("usb:1234:5678:82,timeout=0,idle=0.5,bus=3,addr=7,interface=1")
    assert (s["ep"], s["timeout"], s["idle"], s["bus"], s["addr"], s["interface"]) == \
        (0x82, 0.0, 0.5, 3, 7, 1)


@pytest.mark.parametrize("bad, words", [
    ("usb:feed", "expected usb:VID:PID"),
    ("usb:xyz:beef", "bad VID"),
    ("usb:feed:10000", "out of range"),
    ("usb:feed:beef:01", "OUT endpoint"),
    ("usb:feed:beef,speed=3", "unknown option"),
    ("usb:feed:beef,timeout=-1", ">= 0"),
    ("serial:feed:beef", "expected usb:"),
])
def test_bad_spec_is_a_clear_error(bad, words):
    from rast8.usb import UsbSpecError, open_usb
    with pytest.raises(UsbSpecError) as ei:
        open_usb(bad)
    assert words in str(ei.value)
    assert ei.value.exit_code == EX_USAGE


def test_bad_backend_choice_is_a_clear_error(monkeypatch):
    from rast8.usb import UsbBackendMissing, open_usb
    monkeypatch.setenv("RAST8_USB_BACKEND", "winusb")
    with pytest.raises(UsbBackendMissing) as ei:
        open_usb(SPEC)
    assert "use 'system' or 'package'" in str(ei.value) and ei.value.exit_code == 1


def test_usbcat_help_and_usage_errors():
    r = subprocess.run([USBCAT, "--help"], capture_output=True, text=True)
    assert r.returncode == 0 and "usb:VID:PID[:EP]" in r.stdout and "--list" in r.stdout
    for args, words in [([], "no device given"), (["usb:feed"], "bad device"),
                        (["--bogus", SPEC], "unknown option"), (["-t", "x", SPEC], "bad --timeout"),
                        (["--pty", "-o", "f", SPEC], "exclusive"),
                        (["usb:feed:beef:01"], "OUT endpoint")]:
        r = subprocess.run([USBCAT, *args], capture_output=True, text=True)
        assert r.returncode == EX_USAGE, (args, r.stderr)
        assert words in r.stderr, (args, r.stderr)


# ------------------------------------------------------------------ listing

def test_usbcat_list_offers_vendor_bulk_in_only(bed, clean):
    r = mock(bed, clean[0], [USBCAT, "--list"])
    assert r.returncode == 0, r.stderr
    lines = r.stdout.decode().splitlines()
    assert len(lines) == 1, lines                       # not the HID mouse 046d:c077
    assert lines[0].startswith("usb:feed:beef:81 ") and "bus 001 addr 002" in lines[0]


def test_python_list_devices(bed, clean):
    code = "from rast8.usb import list_devices; print([d['spec'] for d in list_devices()])"
    r = mock(bed, clean[0], [sys.executable, "-c", code])
    assert r.returncode == 0, r.stderr
    assert r.stdout.decode().strip() == "['usb:feed:beef:81']"


# ------------------------------------------------------------------ clean streams

def test_usbcat_copies_the_stream_exactly(bed, stream, clean, work):
    ioctl, replies, delivered = clean
    assert delivered == stream.stat().st_size and replies > 5
    out = work / "cat.bin"
    # the device goes silent after its last reply; --idle ends the capture
    r = mock(bed, ioctl, [USBCAT, "--idle", "0.2", "-o", out, SPEC],
             fault=f"silent={replies}")
    assert r.returncode == 0, r.stderr
    assert out.read_bytes() == stream.read_bytes()
    assert f"{delivered} bytes" in r.stderr.decode()


def test_usbcat_bytes_limit(bed, stream, clean):
    r = mock(bed, clean[0], [USBCAT, "-n", "777", SPEC])
    assert r.returncode == 0, r.stderr
    assert r.stdout == stream.read_bytes()[:777]


def test_usbcat_pipe_to_decode_equals_file(bed, stream, clean, reference, work):
    ioctl, replies, _ = clean
    cat = mock(bed, ioctl, [USBCAT, "-q", "--idle", "0.2", SPEC], fault=f"silent={replies}")
    assert cat.returncode == 0, cat.stderr
    d = work / "via-usbcat"
    r = decode("-", d, input=cat.stdout)
    assert r.returncode == 0, r.stderr.decode()
    assert frames_in(d) == reference


def test_usb_source_decode_equals_file(bed, clean, reference, work):
    ioctl, replies, _ = clean
    d = work / "via-usb"
    r = mock(bed, ioctl, [RAST8, "decode", f"{SPEC},idle=0.2", "-o", d],
             fault=f"silent={replies}")
    assert r.returncode == 0, r.stderr.decode()
    assert frames_in(d) == reference


def test_usb_source_stats(bed, clean):
    ioctl, replies, delivered = clean
    r = mock(bed, ioctl, [RAST8, "stats", f"{SPEC},idle=0.2", "--json"],
             fault=f"silent={replies}")
    assert r.returncode == 0, r.stderr.decode()
    st = json.loads(r.stdout.decode().strip().splitlines()[-1])
    assert (st["frames"], st["bytes"], st["errors"]) == (FRAMES, delivered, 0)


def test_usb_source_frames_limit(bed, clean, reference, work):
    """--frames N stops a capture from a board that never goes quiet."""
    d = work / "via-usb-frames"
    r = mock(bed, clean[0], [RAST8, "decode", SPEC, "--frames", "5", "-o", d])
    assert r.returncode == 0, r.stderr.decode()
    got = frames_in(d)
    assert len(got) == 5 and all(reference[k] == v for k, v in got.items())


@pytest.mark.parametrize("backend", ["system", "package"])
def test_python_source_reads_the_stream_exactly(bed, stream, clean, work, backend):
    ioctl, replies, delivered = clean
    out = work / f"py-{backend}.bin"
    rc, rep = usbread(bed, ioctl, f"{SPEC}:81,idle=0.2", out, fault=f"silent={replies}",
                      chunk=333, backend=backend)
    assert rc == 0 and rep["error"] is None, rep
    assert out.read_bytes() == stream.read_bytes()
    want = "libusb-package" if backend == "package" else "system libusb"
    assert rep["backend"].startswith(want)


def _usbcat_pty(bed, ioctl, replies, *args):
    env = dict(os.environ, RAST8_USB_FAULT=f"silent={replies}")
    cmd = ["umockdev-run", "--device", str(bed), "--ioctl", f"{mkioctl.DEVNODE}={ioctl}", "--",
           "sh", "-c", 'LD_PRELOAD="$0${LD_PRELOAD:+:$LD_PRELOAD}" exec "$@"', str(SHIM),
           str(USBCAT), "--pty", *args, SPEC]
    p = subprocess.Popen(cmd, env=env, stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    path = p.stdout.readline().decode().strip()
    return p, path


def test_usbcat_pty(bed, stream, clean):
    """--pty prints a path and streams once a reader has it open: a plain
    reader (it sends nothing, so after --gate) gets exactly the stream."""
    ioctl, replies, _ = clean
    data = stream.read_bytes()
    p, path = _usbcat_pty(bed, ioctl, replies, "--idle", "0.3", "--gate", "200")
    try:
        assert path.startswith("/dev/pts/"), (path, p.stderr.read())
        fd = os.open(path, os.O_RDONLY | os.O_NOCTTY)
        got = bytearray()
        try:
            while len(got) < len(data):
                b = os.read(fd, 4096)
                if not b:
                    break
                got += b
        finally:
            os.close(fd)              # usbcat ends once its reader is gone
        assert p.wait(timeout=30) == 0, p.stderr.read()
    finally:
        if p.poll() is None:
            p.kill()
            p.wait()
    assert bytes(got) == data


def test_usbcat_pty_reader_leaving_ends_cleanly(bed, stream, clean):
    """A reader that takes 100 bytes and closes, while the board keeps
    streaming: usbcat notices and ends with exit 0."""
    ioctl, _, _ = clean
    p, path = _usbcat_pty(bed, ioctl, 10 ** 6, "--gate", "100")   # never silent
    try:
        assert path.startswith("/dev/pts/"), (path, p.stderr.read())
        fd = os.open(path, os.O_RDONLY | os.O_NOCTTY)
        got = bytearray()
        try:
            while len(got) < 100:
                got += os.read(fd, 100 - len(got))
        finally:
            os.close(fd)
        assert p.wait(timeout=30) == 0
        assert b"the reader closed the output" in p.stderr.read()
    finally:
        if p.poll() is None:
            p.kill()
            p.wait()
    assert bytes(got) == stream.read_bytes()[:100]


def test_usbcat_pty_to_rast8_decode(bed, clean, reference, work):
    """rast8 decode over pyserial on the pty: rast8 sends a request once its
    port is open, which starts the stream (no byte lost to pyserial's flush)."""
    ioctl, replies, _ = clean
    p, path = _usbcat_pty(bed, ioctl, replies, "--idle", "0.3")
    d = work / "via-pty"
    try:
        assert path.startswith("/dev/pts/"), (path, p.stderr.read())
        r = subprocess.run([str(RAST8), "decode", path, "--frames", str(FRAMES), "-o", str(d)],
                           capture_output=True, timeout=60)
        assert r.returncode == 0, r.stderr.decode()
        assert p.wait(timeout=30) == 0, p.stderr.read()
    finally:
        if p.poll() is None:
            p.kill()
            p.wait()
    assert frames_in(d) == reference


# ------------------------------------------------------------------ errors

def test_missing_device(bed, clean):
    r = mock(bed, clean[0], [USBCAT, "usb:feed:0001"])
    assert r.returncode == EX_NODEV
    assert "no such device" in r.stderr.decode() and "--list" in r.stderr.decode()
    rc, rep = usbread(bed, clean[0], "usb:feed:0001", os.devnull)
    assert rc == EX_NODEV and rep["error"]["type"] == "UsbNoDevice"
    assert "no such device" in rep["error"]["message"]


def test_missing_endpoint(bed, clean):
    r = mock(bed, clean[0], [USBCAT, "usb:feed:beef:83"])
    assert r.returncode == EX_NODEV and "no bulk IN endpoint 0x83" in r.stderr.decode()


@pytest.mark.parametrize("fault, code, words, typ", [
    ("unplug", EX_UNPLUGGED, "device unplugged", "UsbUnplugged"),
    ("stall", EX_STALL, "endpoint stalled", "UsbStall"),
])
def test_fault_mid_stream_keeps_earlier_frames(bed, stream, work, reference, fault, code, words,
                                               typ):
    data = stream.read_bytes()
    at = len(data) * 3 // 5
    ioctl, replies, delivered = make_script(stream, work, fault, fault, at)
    assert delivered == at
    kept = prefix_frames(stream, at, work, fault)
    assert 0 < len(kept) < len(reference)
    assert all(reference[k] == v for k, v in kept.items())

    # rast8-usbcat: the bytes before the fault are written out, then exit code
    out = work / f"{fault}.cat.bin"
    r = mock(bed, ioctl, [USBCAT, "-o", out, SPEC])
    assert r.returncode == code, r.stderr
    assert words in r.stderr.decode() and f"after {at} bytes" in r.stderr.decode()
    assert out.read_bytes() == data[:at]
    d = work / f"{fault}.cat"
    decode(out, d)
    assert frames_in(d) == kept

    # rast8 decode usb:...: the frames before the fault are written, and it fails
    d = work / f"{fault}.cli"
    r = mock(bed, ioctl, [RAST8, "decode", SPEC, "-o", d])
    assert r.returncode != 0 and words in r.stderr.decode()
    assert frames_in(d) == kept

    # rast8.usb: data first, then the error on the next read (and again after)
    rc, rep = usbread(bed, ioctl, SPEC, work / f"{fault}.py.bin")
    assert rc == code and rep["error"]["type"] == typ and rep["error"]["sticky"], rep
    assert words in rep["error"]["message"]
    assert (work / f"{fault}.py.bin").read_bytes() == data[:at]


def test_timeout_before_any_data(bed, clean):
    r = mock(bed, clean[0], [USBCAT, "-t", "0.3", SPEC], fault="silent=0")
    assert r.returncode == EX_TIMEOUT and r.stdout == b""
    assert "timeout: no data" in r.stderr.decode()
    rc, rep = usbread(bed, clean[0], f"{SPEC},timeout=0.3", os.devnull, fault="silent=0")
    assert rc == EX_TIMEOUT and rep["error"]["type"] == "UsbTimeout" and rep["bytes"] == 0


def test_timeout_mid_stream_keeps_data(bed, stream, clean, work):
    data = stream.read_bytes()
    k = 6
    ioctl = clean[0]
    # bytes in the first k replies, from the generator's chunking
    pos = 0
    for i in range(k):
        pos = min(len(data), pos + mkioctl.CHUNKS[i % len(mkioctl.CHUNKS)])
    expect = pos
    assert 0 < expect < len(data)
    r = mock(bed, ioctl, [USBCAT, "-t", "0.3", SPEC], fault=f"silent={k}")
    assert r.returncode == EX_TIMEOUT and r.stdout == data[:expect]
    assert "timeout" in r.stderr.decode()
    out = work / "timeout.py.bin"
    rc, rep = usbread(bed, ioctl, f"{SPEC},timeout=0.3", out, fault=f"silent={k}")
    assert rc == EX_TIMEOUT and rep["error"]["type"] == "UsbTimeout", rep
    assert out.read_bytes() == data[:expect]


def test_interface_busy(bed, clean):
    r = mock(bed, clean[0], [USBCAT, SPEC], fault="busy")
    assert r.returncode == EX_BUSY and "interface busy" in r.stderr.decode()
    rc, rep = usbread(bed, clean[0], SPEC, os.devnull, fault="busy")
    assert rc == EX_BUSY and rep["error"]["type"] == "UsbBusy"


def test_permission_denied_names_the_udev_rule(bed, clean):
    r = mock(bed, clean[0], [USBCAT, SPEC], fault="access")
    err = r.stderr.decode()
    assert r.returncode == EX_ACCESS and "permission denied" in err
    assert 'ATTR{idVendor}=="feed", ATTR{idProduct}=="beef"' in err
    rc, rep = usbread(bed, clean[0], SPEC, os.devnull, fault="access")
    assert rc == EX_ACCESS and rep["error"]["type"] == "UsbPermissionDenied"
    assert "udev" in rep["error"]["message"]


def test_device_selection_between_identical_boards(bed2, stream, clean, work):
    """The board at address 2 streams cleanly, the one at address 4 stalls early."""
    data = stream.read_bytes()
    at = len(data) // 4
    other, _, _ = make_script(stream, work, "board4", "stall", at, addr=4)
    scripts = {mkioctl.devnode(2): clean[0], mkioctl.devnode(4): other}
    r = mock(bed2, scripts, [USBCAT, "--list"])
    lines = r.stdout.decode().splitlines()
    assert len(lines) == 2 and all(l.startswith("usb:feed:beef:81 ") for l in lines), lines
    assert {"addr 002", "addr 004"} == {l.split("  ")[1].split(" ", 2)[2] for l in lines}

    r = mock(bed2, scripts, [USBCAT, "--addr", "4", SPEC])
    assert r.returncode == EX_STALL and r.stdout == data[:at], r.stderr
    r = mock(bed2, scripts, [USBCAT, "--bus", "1", "--addr", "2", "-n", str(len(data)), SPEC])
    assert r.returncode == 0 and r.stdout == data, r.stderr
    r = mock(bed2, scripts, [USBCAT, "--addr", "9", SPEC])
    assert r.returncode == EX_NODEV and "given --bus/--addr" in r.stderr.decode()
    r = mock(bed2, scripts, [USBCAT, "-n", "10", SPEC])
    assert r.returncode == 0 and "2 devices match" in r.stderr.decode()

    rc, rep = usbread(bed2, scripts, f"{SPEC},addr=4", work / "sel4.bin")
    assert rc == EX_STALL and (work / "sel4.bin").read_bytes() == data[:at]
    assert rep["warnings"] == []
    rc, rep = usbread(bed2, scripts, f"{SPEC},addr=9", os.devnull)
    assert rc == EX_NODEV and "at the given bus/addr" in rep["error"]["message"]
    rc, rep = usbread(bed2, scripts, f"{SPEC},timeout=0.3", os.devnull, fault="silent=0")
    assert rc == EX_TIMEOUT and "2 devices match" in rep["warnings"][0], rep
    rc, rep = usbread(bed2, scripts, f"{SPEC},bus=1,addr=2,idle=0.2", work / "sel2.bin",
                      fault=f"silent={clean[1]}")
    assert rc == 0 and (work / "sel2.bin").read_bytes() == data


def test_usbcat_unwritable_output(bed, clean, work):
    r = mock(bed, clean[0], [USBCAT, "-o", work / "no" / "such" / "dir", SPEC])
    assert r.returncode == 9 and "cannot write" in r.stderr.decode()


def test_kernel_driver_is_detached_and_reattached(bed, stream, clean, work):
    """A bound kernel driver holds the interface (claim: EBUSY) until detached."""
    ioctl, replies, _ = clean
    fault = f"driver,silent={replies}"
    r = mock(bed, ioctl, [USBCAT, "--idle", "0.2", SPEC], fault=fault)
    err = r.stderr.decode()
    assert r.returncode == 0 and r.stdout == stream.read_bytes(), err
    assert err.index("faultshim: detach 0") < err.index("faultshim: attach 0")

    out = work / "driver.py.bin"
    r = mock(bed, ioctl, [sys.executable, HERE / "usbread.py", f"{SPEC},idle=0.2", out],
             fault=fault)
    err = r.stderr.decode()
    assert r.returncode == 0 and out.read_bytes() == stream.read_bytes(), err
    assert err.index("faultshim: detach 0") < err.index("faultshim: attach 0")


@pytest.mark.skipif(not shutil.which("xvfb-run"), reason="needs Xvfb (scripts/setup.sh installs it)")
def test_view_usb_source_screenshot(bed, stream, clean, work):
    """rast8 view usb:..., headless: the window shows the last frame exactly."""
    from PIL import Image, ImageChops
    from rast8.protocol import StreamDecoder
    ioctl, replies, _ = clean
    shot = work / "view.png"
    env = dict(os.environ, RAST8_USB_FAULT=f"silent={replies}")
    env.pop("RAST8_USB_BACKEND", None)
    cmd = ["xvfb-run", "-a", "-s", "-screen 0 800x600x24",
           "umockdev-run", "--device", str(bed), "--ioctl", f"{mkioctl.DEVNODE}={ioctl}", "--",
           "sh", "-c", 'LD_PRELOAD="$0${LD_PRELOAD:+:$LD_PRELOAD}" exec "$@"', str(SHIM),
           str(RAST8), "view", f"{SPEC},idle=0.2", "--scale", "3", "--screenshot", str(shot)]
    r = subprocess.run(cmd, env=env, capture_output=True, text=True, timeout=60)
    assert r.returncode == 0, r.stderr
    assert f"{FRAMES} frames, errors 0" in r.stdout
    last = StreamDecoder().feed(stream.read_bytes())[-1]
    want = last.to_image(3).convert("RGB")
    got = Image.open(shot).convert("RGB")
    assert got.size == want.size and ImageChops.difference(got, want).getbbox() is None


# ------------------------------------------------------------------ issue 12 item 12

@pytest.fixture(scope="session")
def bed_composite(work):
    path = work / "bedc.umockdev"
    r = subprocess.run([sys.executable, str(HERE / "mkioctl.py"), "device", str(path),
                        "--composite"], capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    return path


def test_composite_board_uses_the_vendor_interface_only(bed_composite, stream, work):
    """feed:cafe: CDC control (if 0), CDC data with bulk IN 0x81 (if 1),
    vendor class with bulk IN 0x82 (if 2): 0x82 streams; 0x81 is refused."""
    data = stream.read_bytes()
    ioctl, replies, _ = make_script(stream, work, "comp", addr=5, ep="82")
    node = {mkioctl.devnode(5): ioctl}
    r = mock(bed_composite, node, [USBCAT, "-n", "500", "usb:feed:cafe:82"])
    assert r.returncode == 0 and r.stdout == data[:500], r.stderr
    for spec in ("usb:feed:cafe", "usb:feed:cafe:81"):
        r = mock(bed_composite, node, [USBCAT, spec])
        err = r.stderr.decode()
        assert r.returncode == EX_NODEV and "not a vendor-class interface" in err, err
        assert "interface 1 of class 0x0a (CDC data)" in err and r.stdout == b""
        rc, rep = usbread(bed_composite, node, spec, os.devnull)
        assert rc == EX_NODEV and "not a vendor-class interface" in rep["error"]["message"]
        r = mock(bed_composite, node, [RAST8, "stats", spec])
        assert r.returncode == EX_NODEV and b"Traceback" not in r.stderr
    rc, rep = usbread(bed_composite, node, "usb:feed:cafe:82,idle=0.2", work / "comp.bin",
                      fault=f"silent={replies}")
    assert rc == 0 and (work / "comp.bin").read_bytes() == data, rep
    r = mock(bed_composite, node, [USBCAT, "--list"])
    lines = r.stdout.decode().splitlines()
    assert any(l.startswith("usb:feed:cafe:82 ") and "interface 2" in l for l in lines), lines
    assert not any(l.startswith("usb:feed:cafe:81") for l in lines), lines


@pytest.mark.parametrize("fault, code, words", [
    ("unplug-data", EX_UNPLUGGED, "device unplugged"),
    ("shutdown", EX_UNPLUGGED, "device unplugged"),
    ("proto", 1, "USB bus error"),
])
def test_failing_transfer_keeps_its_bytes(bed, stream, work, fault, code, words):
    """The URB that fails (-ENODEV, -ESHUTDOWN, -EPROTO) still carries bytes:
    every one of them is passed on, and the message says what to try."""
    data = stream.read_bytes()
    at = len(data) // 3
    ioctl, _, delivered = make_script(stream, work, "f-" + fault, fault, at)
    assert delivered == at
    r = mock(bed, ioctl, [USBCAT, SPEC])
    err = r.stderr.decode()
    assert r.returncode == code and r.stdout == data[:at], err
    assert words in err and "libusb error" not in err
    if fault == "proto":
        assert "cable" in err
    out = work / f"f-{fault}.bin"
    rc, rep = usbread(bed, ioctl, SPEC, out)
    assert rc == code and out.read_bytes() == data[:at], rep
    assert words in rep["error"]["message"] and "libusb error" not in rep["error"]["message"]


def test_rast8_prints_the_usb_warnings(bed2, clean, work):
    """Two matching boards: rast8 says which one it uses (and how to choose)."""
    ioctl, replies, _ = clean
    scripts = {mkioctl.devnode(2): ioctl, mkioctl.devnode(4): ioctl}
    r = mock(bed2, scripts, [RAST8, "stats", f"{SPEC},idle=0.2", "--json"],
             fault=f"silent={replies}")
    err = r.stderr.decode()
    assert "warning: 2 devices match feed:beef; using bus 1 addr 2" in err, err
    assert "bus=N,addr=N" in err


def test_kernel_driver_detach_failure_is_printed(bed, clean, work):
    """A driver that cannot be detached: rast8 prints the warning it collects."""
    ioctl, replies, _ = clean
    r = mock(bed, ioctl, [RAST8, "stats", f"{SPEC},idle=0.2", "--json"],
             fault=f"driver,nodetach,silent={replies}")
    err = r.stderr.decode()
    assert "cannot detach the kernel driver" in err or "interface busy" in err, err


def test_two_boards_on_different_buses(work, stream, clean):
    """feed:beef on bus 1 and on bus 2: 'first' is bus 1; bus=2 picks the other."""
    bed = work / "bedbus.umockdev"
    r = subprocess.run([sys.executable, str(HERE / "mkioctl.py"), "device", str(bed),
                        "--boards", "2", "--other-bus"], capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    data = stream.read_bytes()
    at = len(data) // 5
    other, _, _ = make_script(stream, work, "bus2", "stall", at, bus=2)
    scripts = {mkioctl.devnode(2): clean[0], mkioctl.devnode(2, 2): other}
    r = mock(bed, scripts, [USBCAT, "--list"])
    lines = r.stdout.decode().splitlines()
    assert sorted(l.split("  ")[1][:7] for l in lines) == ["bus 001", "bus 002"], lines
    r = mock(bed, scripts, [USBCAT, "-n", "300", SPEC])
    assert r.returncode == 0 and r.stdout == data[:300]
    assert "2 devices match feed:beef; using bus 1 addr 2" in r.stderr.decode()
    r = mock(bed, scripts, [USBCAT, "--bus", "2", SPEC])
    assert r.returncode == EX_STALL and r.stdout == data[:at], r.stderr
    rc, rep = usbread(bed, scripts, f"{SPEC},bus=2", work / "bus2.bin")
    assert rc == EX_STALL and (work / "bus2.bin").read_bytes() == data[:at]
    rc, rep = usbread(bed, scripts, f"{SPEC},timeout=0.3", os.devnull, fault="silent=0")
    assert "using bus 1 addr 2" in rep["warnings"][0], rep
