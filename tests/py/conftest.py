"""Shared fixtures for the wire/protocol/emulator tests (issue 3)."""
import os
import subprocess

import pytest

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
EMU = os.path.join(ROOT, "build", "rast8-emu")
CODEC = os.path.join(ROOT, "build", "rast8-codec")
VECTORS = os.path.join(ROOT, "tests", "vectors")


def _need(path):
    if not os.path.exists(path):
        subprocess.run(["make", "-C", ROOT, "-s", os.path.relpath(path, ROOT)], check=True)


@pytest.fixture(scope="session")
def emu():
    _need(EMU)
    return EMU


@pytest.fixture(scope="session")
def codec_tool():
    _need(CODEC)
    return CODEC


def run_emu(tmp_path, *args, name="s"):
    """Run rast8-emu --out FILE --dump FILE; returns (stream, frames)."""
    from rast8.protocol import read_dump
    _need(EMU)
    out = tmp_path / (name + ".bin")
    dump = tmp_path / (name + ".r8fb")
    r = subprocess.run([EMU, "-q", "--out", str(out), "--dump", str(dump)] + list(args),
                       capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    return out.read_bytes(), read_dump(str(dump))


@pytest.fixture
def emu_stream(tmp_path):
    def make(*args, name="s"):
        return run_emu(tmp_path, *args, name=name)
    return make
