"""ports/z80/gcz80.py: the Z80 link's dead-code removal (ports/xbuild.sh).

A tiny sdcc program with a library of two modules is linked with and
without it: the unused function, the unused library function and the
library module nothing needs are left out; a function reached only
through a const table, one reached only through an initialised pointer
and a static local's initialiser are kept; both programs print the same
bytes in ucsim's sz80.
"""
import os
import re
import shutil
import subprocess
import sys

import pytest

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
sys.path.insert(0, os.path.join(ROOT, "ports", "z80"))
import gcz80  # noqa: E402

pytestmark = pytest.mark.skipif(not (shutil.which("sdcc") and shutil.which("sdasz80") and shutil.which("sz80")),
                                reason="sdcc / sdasz80 / sz80 not installed")

MAIN = r"""
#include "plat.h"
extern int lib_used(int x);
static int helper(int x) { return x * 3; }
int never_called(int x) { return helper(x) + 7; }
static int only_in_table(int x) { return x + 1; }
int only_in_data(int x) { return x - 1; }
typedef int (*fn)(int);
static const fn table[2] = { only_in_table, only_in_table };
fn ptr = only_in_data;
int unused_init = 1234;
static int count(void) { static int n = 5; return n++; }
int main(void)
{
    int v;
    plat_init();
    v = table[1](40) + ptr(2) + lib_used(1) + helper(1) + count() + count();
    plat_putc((r8_u8)v);
    plat_putc((r8_u8)(v >> 8));
    plat_exit(0);
    return 0;
}
"""
LIB = "int lib_used(int x) { return x + 100; }\nint lib_unused(int x) { return x * 7; }\n"
LIB2 = "int other_module(int x) { return x + 2; }\n"
EXPECT = 41 + 1 + 101 + 3 + 5 + 6


def sdcc(tmp, name, text=None, src=None):
    if text is not None:
        src = tmp / (name + ".c")
        src.write_text(text)
    subprocess.run(["sdcc", "-mz80", "--std-c89", "-I" + os.path.join(ROOT, "include"),
                    "-I" + os.path.join(ROOT, "ports"), "-c", "-o", str(tmp / (name + ".rel")), str(src)],
                   check=True, capture_output=True)
    return str(tmp / (name + ".asm"))


def link_run(tmp, name, rels):
    out = str(tmp / (name + ".ihx"))
    r = subprocess.run([sys.executable, os.path.join(ROOT, "ports", "z80", "z80link.py"), out] + rels,
                       capture_output=True, text=True)
    assert r.returncode == 0, r.stdout
    got = tmp / (name + ".out")
    r = subprocess.run([sys.executable, os.path.join(ROOT, "emu", "sz80run.py"), "-G", "-o", str(got), out],
                       capture_output=True, text=True, timeout=120)
    assert r.returncode == 0, r.stderr
    return got.read_bytes(), open(out[:-4] + ".map").read()


@pytest.fixture(scope="module")
def built(tmp_path_factory):
    tmp = tmp_path_factory.mktemp("gcz80")
    progs = [sdcc(tmp, "main", MAIN), sdcc(tmp, "plat_z80", src=os.path.join(ROOT, "ports", "z80", "plat_z80.c"))]
    members = [sdcc(tmp, "lib", LIB), sdcc(tmp, "lib2", LIB2)]
    subprocess.run(["sdar", "-rc", str(tmp / "lib.lib"), str(tmp / "lib.rel"), str(tmp / "lib2.rel")], check=True)
    whole = link_run(tmp, "whole", [str(tmp / "main.rel"), str(tmp / "plat_z80.rel"), str(tmp / "lib.lib")])
    r = subprocess.run([sys.executable, os.path.join(ROOT, "ports", "z80", "gcz80.py"), str(tmp / "gc")]
                       + progs + ["--"] + members, capture_output=True, text=True, check=True)
    files = r.stdout.split()
    rels = []
    for f in files:
        subprocess.run(["sdasz80", "-plosgffw", f[:-4] + ".rel", f], check=True, capture_output=True)
        rels.append(f[:-4] + ".rel")
    return tmp, files, whole, link_run(tmp, "gc", rels)


def test_same_output_and_expected_value(built):
    _, _, (whole_out, _), (gc_out, _) = built
    assert whole_out == gc_out
    assert gc_out == bytes([EXPECT & 0xFF, EXPECT >> 8])


def test_unreachable_left_out(built):
    tmp, files, (_, whole_map), (_, gc_map) = built
    for sym in ("_never_called", "_lib_unused", "_unused_init"):
        assert re.search(r"\b%s\b" % sym, whole_map)
        assert not re.search(r"\b%s\b" % sym, gc_map), sym
    assert "_other_module" not in gc_map  # a member nothing needs, as sdld leaves it
    assert [os.path.basename(f) for f in files] == ["main.asm", "plat_z80.asm", "lib.asm"]
    text = (tmp / "gc" / "main.asm").read_text()
    assert "__xinit__unused_init" not in text
    assert "\t.globl _never_called" not in text


def test_pointer_table_and_data_references_kept(built):
    tmp, _, _, (_, gc_map) = built
    text = (tmp / "gc" / "main.asm").read_text()
    for label in ("_only_in_table:", "_only_in_data::", "_table:", "_ptr::", "__xinit__ptr:", "_lib_used"):
        assert label in text + gc_map, label
    assert re.search(r"_count_n_\w+:", text)  # the static local and its _GSINIT store


def test_fall_through_keeps_next_block(tmp_path):
    src = tmp_path / "ft.asm"
    src.write_text(";--\n; File Created by SDCC : test\n;--\n\t.module ft\n\t.globl _a\n\t.globl _main\n"
                   "\t.area _CODE\n_main::\n\tcall\t_a\n\tret\n_a::\n\tld\ta, #1\n\tor\ta, a\n\tjr\tNZ, 00101$\n"
                   "_b:\n\tinc\ta\n00101$:\n\tret\n_c:\n\tret\n")
    m = gcz80.Module(str(src))
    gcz80.reach([m], [])
    assert [n for n in ("_main", "_a", "_b", "_c") if m.blocks[n].live] == ["_main", "_a", "_b"]


def test_unpaired_initialisers_keep_module_whole(tmp_path, capsys):
    src = tmp_path / "up.asm"
    src.write_text("; File Created by SDCC : test\n\t.area _INITIALIZED\n_x::\n\t.ds 2\n"
                   "\t.area _INITIALIZER\n__xinit__y:\n\t.dw 1\n\t.area _CODE\n_main::\n\tret\n")
    m = gcz80.Module(str(src))
    assert m.blocks == {} and m.text() == src.read_text().splitlines()
    assert "do not pair" in capsys.readouterr().err
