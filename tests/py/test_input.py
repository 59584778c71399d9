"""The INPUT packet (issue 11): the viewer's key pad encodes key state in
Python, the device's r8_tx_rx parses it in C, and rast8-emu delivers it
to the firmware (app_keys) from a key script, an --rx file and a live pty."""
import subprocess
import time

import pytest

from rast8.protocol import input_packet, request_packet, parse_to_device, KEY_BITS, PKT_INPUT
from rast8 import codec as C
from rast8.viewer import KeyPad, KEYMAP


def test_input_packet_bytes():
    p = input_packet(0x0015)
    assert p[0] == 0 and p[-1] == 0 and 0 not in p[1:-1]
    body = C.cobs_decode(p[1:-1])
    assert body[:3] == bytes([PKT_INPUT, 0x00, 0x15])
    assert C.crc16(body[:3]) == int.from_bytes(body[3:], "big")
    with pytest.raises(ValueError):
        input_packet(0x10000)


def test_key_bits_match_the_c_header():
    import os
    from conftest import ROOT
    h = open(os.path.join(ROOT, "include", "r8wire.h")).read()
    for name, bit in KEY_BITS.items():
        assert "#define R8_KEY_%s 0x%04Xu" % (name.upper(), bit) in h


class Clock:
    t = 0.0

    def __call__(self):
        return self.t


def test_keypad_sends_on_change_and_periodically():
    sent = []
    clock = Clock()
    pad = KeyPad(sent.append, period=0.5, clock=clock)
    pad.tick()
    assert sent == []                        # nothing before a key is used
    assert pad.press("Left") and pad.mask == KEY_BITS["left"]
    assert not pad.press("Left")             # auto-repeat: no change, no packet
    assert pad.press("z") and pad.mask == KEY_BITS["left"] | KEY_BITS["a"]
    assert not pad.press("F5")               # unmapped keys are ignored
    assert pad.release("Left") and pad.mask == KEY_BITS["a"]
    assert [parse_to_device(p)[0] for p in sent] == [
        ("input", 0x0004), ("input", 0x0014), ("input", 0x0010)]
    clock.t = 0.4
    pad.tick()
    assert len(sent) == 3
    clock.t = 0.6
    pad.tick()
    assert parse_to_device(sent[-1]) == [("input", 0x0010)] and len(sent) == 4
    assert set(KEYMAP.values()) <= set(KEY_BITS)


def _key_log(path):
    return {int(a): int(b, 16) for a, b in (l.split() for l in open(path))}


def test_emulator_key_script(emu, tmp_path):
    script = tmp_path / "keys.txt"
    script.write_text("# one line per frame\n0x0001\n0x0003\n16\n0\n0x8000\n")
    log = tmp_path / "log.txt"
    r = subprocess.run([emu, "-q", "--frames", "7", "--out", str(tmp_path / "s.bin"),
                        "--keys", str(script), "--key-log", str(log)], capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    # line N is sent after frame N: the firmware sees it from frame N+1
    assert _key_log(log) == {0: 0, 1: 1, 2: 3, 3: 0x10, 4: 0, 5: 0x8000, 6: 0x8000}


def test_emulator_bad_key_script_is_an_error(emu, tmp_path):
    script = tmp_path / "keys.txt"
    script.write_text("0x1\nleft\n")
    r = subprocess.run([emu, "-q", "--frames", "5", "--out", str(tmp_path / "s.bin"),
                        "--keys", str(script)], capture_output=True, text=True)
    assert r.returncode == 2 and "bad key mask 'left'" in r.stderr


def test_emulator_rx_file_python_packets(emu, tmp_path):
    """Python-encoded packets (and an unknown kind, which the device must
    ignore) read from a file by the emulator's firmware."""
    unknown = b"\x00" + C.cobs_encode(b"\x1e\x01" + C.crc16(b"\x1e\x01").to_bytes(2, "big")) + b"\x00"
    rx = tmp_path / "rx.bin"
    rx.write_bytes(input_packet(0x0102) + unknown + request_packet())
    log = tmp_path / "log.txt"
    r = subprocess.run([emu, "-q", "--frames", "3", "--out", str(tmp_path / "s.bin"),
                        "--rx", str(rx), "--key-log", str(log)], capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    assert _key_log(log) == {0: 0, 1: 0x0102, 2: 0x0102}


def test_keys_over_a_live_pty(emu, tmp_path):
    """The viewer's path: pyserial on the emulator's pty, KeyPad writes."""
    from rast8.source import open_source
    log = tmp_path / "log.txt"
    p = subprocess.Popen([emu, "--pty", "--frames", "40", "--baud", "115200", "--linger", "5",
                          "--key-log", str(log), "-q"], stdout=subprocess.PIPE, text=True)
    try:
        path = p.stdout.readline().strip()
        src = open_source(path, idle=3)          # sends the REQUEST that opens the gate
        pad = KeyPad(src.write)
        got = b""
        while len(got) < 2000:
            got += src.read(4096)
        pad.press("Right")
        pad.press("x")
        while True:
            d = src.read(4096)
            if not d:
                break
        src.close()
        assert p.wait(timeout=30) == 0
    finally:
        if p.poll() is None:
            p.kill()
    keys = _key_log(log)
    want = KEY_BITS["right"] | KEY_BITS["b"]
    assert keys[0] == 0 and keys[39] == want
    first = min(f for f, k in keys.items() if k == want)
    assert all(keys[f] == want for f in range(first, 40))
