"""`pip install ./host` into a clean venv gives a working package: the
built-in scenes are package data (python -m rast8.scene, rast8 scene),
and the CLI decodes a stream, without this checkout on sys.path."""
import os
import subprocess
import sys

import pytest

from conftest import ROOT


@pytest.fixture(scope="module")
def clean_venv(tmp_path_factory):
    d = tmp_path_factory.mktemp("venv")
    venv = d / "v"
    subprocess.run(["python3",
                    "-m", "venv", str(venv)], check=True)
    r = subprocess.run([str(venv / "bin" / "python"), "-m", "pip", "install", "-q",
                        os.path.join(ROOT, "host")], capture_output=True, text=True, cwd=str(d))
    assert r.returncode == 0, r.stdout + r.stderr
    return venv, d


def _py(venv, cwd, *args):
    env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "VIRTUAL_ENV")}
    return subprocess.run([str(venv / "bin" / "python")] + list(args), capture_output=True,
                          text=True, cwd=str(cwd), env=env)


def test_installed_not_editable(clean_venv):
    venv, cwd = clean_venv
    r = _py(venv, cwd, "-c", "import rast8, os; print(os.path.realpath(rast8.__file__))")
    assert r.returncode == 0 and not r.stdout.startswith(os.path.realpath(ROOT)), r.stdout


def test_installed_scene_module_and_subcommand(clean_venv):
    venv, cwd = clean_venv
    r = _py(venv, cwd, "-m", "rast8.scene", "c", str(cwd / "s.c"))
    assert r.returncode == 0, r.stderr
    from rast8.scene import BUILTIN_ORDER
    assert "%d scenes" % len(BUILTIN_ORDER) in r.stdout and "cube" in (cwd / "s.c").read_text()
    r = _py(venv, cwd, "-m", "rast8", "scene", "check", "wall")
    assert r.returncode == 0 and "objects" in r.stdout, r.stderr


def test_installed_cli_decodes_a_stream(clean_venv, emu_stream):
    venv, cwd = clean_venv
    stream, frames = emu_stream("--frames", "3")
    (cwd / "s.bin").write_bytes(stream)
    r = subprocess.run([str(venv / "bin" / "rast8"), "stats", str(cwd / "s.bin"), "--json"],
                       capture_output=True, text=True, cwd=str(cwd))
    assert r.returncode == 0, r.stderr
    assert '"frames": 3' in r.stdout


def test_metadata(clean_venv):
    venv, cwd = clean_venv
    r = _py(venv, cwd, "-c", "import importlib.metadata as m; d = m.metadata('rast8'); "
                             "print(d['License']); print(len(d.get_all('Classifier')))")
    lic, n = r.stdout.split()
    assert lic == "MIT" and int(n) >= 5
