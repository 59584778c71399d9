#!/usr/bin/env python3
"""identity.py TARGET... - firmware bit identity: every built-in scene x
visibility method, on each target, streams the same UART bytes as the host.

    identity.py [--frames F] [--build-only] TARGET...     (avr328 avr1284 6502 z80)

For each scene S and method M the target firmware build/x/T/fw/fw-S-M-F.*
(examples/spin/fw_app.c with a static arena of app_ram() bytes measured on the
target) runs in its simulator and its stream is compared byte for byte
with the host build of the same main (build/emu/fw-host S M F), and with
build/rast8-emu --scene --method --frames when that exists.  A
combination is skipped only with a printed reason: app_ram() is 0 there,
it does not fit the target (flash, static RAM, 64 KB address space), or,
on the 2 KB ATmega328P, app_ram() plus the measured statics and stack
exceed 2048 bytes.  On the 328P the cube is mandatory (cull and at least
one real depth method must fit and pass), and so is the 200-face torus
with painter's or a better method (issue 10), each with >= 64 B free.  Prints one line per combination and
"N passed, N failed" (skips are listed and counted, never passed).
"""
import argparse
import concurrent.futures as cf
import os
import re
import subprocess
import sys
import tempfile

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
XB = os.path.join(ROOT, "build", "x")
EXT = {"avr328": "elf", "avr1284": "elf", "6502": "prg", "z80": "ihx"}
SIZES = {"avr328": "avr328", "avr1284": "avr1284", "6502": "6502", "z80": "z80"}
RAM = {"avr328": 2048, "avr1284": 16384}
MCU = {"avr328": "atmega328p", "avr1284": "atmega1284p"}
SCENES = ["cube", "torus", "teapot", "terrain", "wall", "cross", "separate", "crate", "maze", "rooms", "tmaze"]
# scenes drawn with another shading than Lambert (R8_SHADE_*), checked
# with their own method only (issue 13: the crate, textured, cull)
SHADING = {"crate": 3, "tmaze": 3}
OWN_METHOD = {"crate": 0}
METHODS = ["cull", "painter", "zbuf8", "zbuf16", "block", "blockmask", "sbuf", "bsp"]
BSP_SCENES = ("wall", "cross")   # BSP runs on its own scenes only (CI time)
# world renderers (outside the mesh methods): their id, name and scenes
WORLD = {16: ("portal", [9]), 17: ("ray", [8, 10])}


def mname(m):
    return METHODS[m] if m < len(METHODS) else WORLD[m][0]


def mid(name):
    """A method's id from its name (mesh methods and world renderers)."""
    if name in METHODS:
        return METHODS.index(name)
    return next(m for m, (n, _) in WORLD.items() if n == name)


def combos():
    """(scene, method): every mesh scene with every mesh method, a world
    scene (or one in OWN_METHOD) with its own method only; bsp on
    BSP_SCENES only."""
    for s, name in enumerate(SCENES):
        if name is None:
            continue
        own = [m for m, (_, ss) in WORLD.items() if s in ss]
        if name in OWN_METHOD:
            own = [OWN_METHOD[name]]
        for m in own or range(len(METHODS)):
            if m < len(METHODS) and METHODS[m] == "bsp" and name not in BSP_SCENES:
                continue
            yield s, m


AVR328_OVERHEAD = 320  # rough statics + stack besides the arena, pre-filter only
MARGIN_328 = 64        # the mandatory 328P cube must leave at least this much SRAM free
STACK_MIN = 200        # AVR: fewer free bytes than this for the stack: does not fit, not run
STACK_SUSPECT = 600    # AVR: a crash with fewer free bytes than this is a stack overflow


def make(targets, keep_going=True):
    """Build files with make -j2, serialised across steps with a lock."""
    if not targets:
        return 0
    env = {k: v for k, v in os.environ.items() if k not in ("MAKEFLAGS", "MFLAGS", "MAKELEVEL")}
    os.makedirs(XB, exist_ok=True)
    cmd = ["flock", os.path.join(XB, ".lock"), "make", "-s", "--no-print-directory", "-j2"]
    if keep_going:
        cmd.append("-k")
    r = subprocess.run(cmd + targets, cwd=ROOT, env=env, stdout=subprocess.PIPE,
                       stderr=subprocess.STDOUT)
    out = r.stdout.decode("latin-1")
    for line in out.splitlines():
        if not line.startswith("SKIP"):
            print("  make: " + line)
    return r.returncode


def read_sizes(t):
    sizes, why = {}, {}
    for line in open(os.path.join(XB, SIZES[t], "sizes.txt")):
        f = line.split(None, 3)
        if len(f) >= 3 and f[0].isdigit():
            sizes[(int(f[0]), int(f[1]))] = int(f[2])
            if len(f) > 3:
                why[(int(f[0]), int(f[1]))] = f[3].lstrip("# ").strip()
    return sizes, why


def fw_path(t, s, m, frames, sh=1, wire=0, objs=1):
    """Firmware of scene s, method m, `frames` frames; shading sh
    (R8_SHADE_*; Lambert, the demo's, unless make bench asks); wire=1 the
    wireframe build (cfg.wire; ports/fwdefs.sh); objs=0 a world's walls
    without its movable objects (make bench-portal)."""
    tail = "" if sh == 1 and not wire and objs else "-%d" % sh
    if wire or not objs:
        tail += "-%d" % wire
    if not objs:
        tail += "-0"
    return os.path.join(XB, t, "fw", "fw-%d-%d-%d%s.%s" % (s, m, frames, tail, EXT[t]))


def is_skip(path):
    with open(path, "rb") as f:
        head = f.read(200)
    return head.decode("latin-1").strip()[6:] if head.startswith(b"SKIP:") else None


def run_target(t, path, timeout=300):
    """Run one program; returns (bytes, exit code, info dict)."""
    with tempfile.TemporaryDirectory() as td:
        out, info = os.path.join(td, "out.bin"), os.path.join(td, "info.txt")
        if t.startswith("avr"):
            cmd = [os.path.join(ROOT, "build", "emu", "avrsim"), "-l", "3000000000", "-m", info,
                   "-o", out, MCU[t], path]
        elif t == "6502":
            cmd = [sys.executable, os.path.join(ROOT, "emu", "sim65run.py"), "-m", info, "-o", out, path]
        else:
            cmd = [sys.executable, os.path.join(ROOT, "emu", "sz80run.py"), "-G", "-m", info,
                   "-o", out, path]
        try:
            rc = subprocess.run(cmd, timeout=timeout, stdout=subprocess.DEVNULL,
                                stderr=subprocess.DEVNULL).returncode
        except subprocess.TimeoutExpired:
            rc = 124
        data = open(out, "rb").read() if os.path.exists(out) else b""
        text = open(info).read() if os.path.exists(info) else ""
    d = {}
    m = re.search(r"stack_peak=(\d+)", text)
    if m:
        d["stack_peak"] = int(m.group(1))
    m = re.search(r"RAM static=(\d+)", text)
    if m:
        d["static"] = int(m.group(1))
    d["info"] = text
    return data, rc, d


def host_ref(s, m, frames, sh=1, wire=0):
    cache = os.path.join(XB, "host", "ref-%d-%d-%d-%d%s.bin" % (s, m, frames, sh, "-w" if wire else ""))
    fwhost = os.path.join(ROOT, "build", "emu", "fw-host")
    if os.path.exists(cache) and os.path.getmtime(cache) >= os.path.getmtime(fwhost):
        return open(cache, "rb").read()
    os.makedirs(os.path.dirname(cache), exist_ok=True)
    r = subprocess.run([fwhost, str(s), str(m), str(frames), str(sh), str(wire)], stdout=subprocess.PIPE,
                       timeout=120)
    if r.returncode:
        raise RuntimeError("fw-host %d %d %d exit %d" % (s, m, frames, r.returncode))
    with open(cache, "wb") as f:
        f.write(r.stdout)
    return r.stdout


def emu_ref(s, m, frames, wire=0):
    emu = os.path.join(ROOT, "build", "rast8-emu")
    if not os.path.exists(emu):
        return None
    with tempfile.TemporaryDirectory() as td:
        out = os.path.join(td, "emu.bin")
        sh = ["--shading", "texture"] if SHADING.get(SCENES[s]) == 3 else []
        r = subprocess.run([emu, "--scene", SCENES[s], "--method", mname(m), "--frames",
                            str(frames), "--out", out] + sh + (["--wire"] if wire else []), stdout=subprocess.DEVNULL,
                           stderr=subprocess.PIPE, timeout=120)
        if r.returncode:
            return ("error", r.stderr.decode("latin-1").strip()[:200])
        return open(out, "rb").read()


def decoder_check(t, s, m, frames):
    """Pipe the target's stream into `rast8 stats --json -`: every frame
    decodes, no bad packets."""
    data, rc, _ = run_target(t, fw_path(t, s, m, frames))
    rast8 = os.path.join(ROOT, ".venv", "bin", "rast8")
    name = "%s %s/%s: simulator stream through rast8 stats" % (t, SCENES[s], mname(m))
    if not os.path.exists(rast8):
        return False, name + ": .venv/bin/rast8 missing"
    r = subprocess.run([rast8, "stats", "--json", "-"], input=data, stdout=subprocess.PIPE,
                       stderr=subprocess.PIPE, timeout=120)
    try:
        import json
        st = json.loads(r.stdout.decode())
    except ValueError:
        return False, name + ": no JSON (%s)" % r.stderr.decode()[-200:]
    ok = st.get("frames") == frames and not st.get("bad_packets") and not st.get("errors")
    return ok, name + ": %s frames, %s bad packets, %s errors" % (
        st.get("frames"), st.get("bad_packets"), st.get("errors"))


# wireframe builds checked (scene, method): the cube with the cull
WIRE = [(0, 0)]


def wire_check(t, s, m, frames):
    """The wireframe firmware's stream against fw-host and rast8-emu --wire."""
    path = fw_path(t, s, m, frames, 1, 1)
    name = "%s %s/%s wireframe" % (t, SCENES[s], METHODS[m])
    if not os.path.exists(path):
        return ("FAIL", "%s: not built (see the make errors above)" % name)
    reason = is_skip(path)
    if reason:
        return ("SKIP", "%s: %s" % (name, reason))
    data, rc, d = run_target(t, path)
    ref = host_ref(s, m, frames, 1, 1)
    if rc != 0:
        return ("FAIL", "%s: exit %d" % (name, rc))
    if data != ref:
        return ("FAIL", "%s: stream differs from the host (%d vs %d bytes)" % (name, len(data), len(ref)))
    plain = host_ref(s, m, frames)
    if data == plain:
        return ("FAIL", "%s: the stream equals the filled render's" % name)
    emu = emu_ref(s, m, frames, 1)
    if isinstance(emu, bytes) and emu != data:
        return ("FAIL", "%s: equals the host fw build but not rast8-emu --wire" % name)
    return ("PASS", "%s: %d bytes identical to host fw%s" % (
        name, len(data), " and rast8-emu --wire" if isinstance(emu, bytes) else ""))


def plan(t, frames):
    sizes, why = read_sizes(t)
    todo, skips = [], []
    for s, m in combos():
        need = sizes.get((s, m), 0)
        if need == 0:
            skips.append((s, m, "app_ram() = 0: %s" % why.get((s, m), "configuration rejected")))
        elif t == "avr328" and need + AVR328_OVERHEAD > RAM[t]:
            skips.append((s, m, "RAM: app_ram() %d B + ~%d B statics/stack > %d B SRAM"
                           % (need, AVR328_OVERHEAD, RAM[t])))
        else:
            todo.append((s, m, need))
    return todo, skips


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--frames", type=int, default=4)
    ap.add_argument("--build-only", action="store_true")
    ap.add_argument("--scene", help="this built-in scene only (e.g. maze)")
    ap.add_argument("targets", nargs="+")
    a = ap.parse_args()
    os.chdir(ROOT)
    ready = ["build/emu/avrsim", "build/emu/fw-host"] + sorted(
        {"build/x/%s/sizes.txt" % SIZES[t] for t in a.targets})
    if make(ready, keep_going=False):
        print("identity: could not build the runners / sizes")
        print("0 passed, 1 failed")
        return 1
    plans = {t: plan(t, a.frames) for t in a.targets}
    if a.scene:
        if a.scene not in SCENES:
            print("identity: unknown scene '%s'" % a.scene)
            return 2
        s0 = SCENES.index(a.scene)
        plans = {t: ([j for j in p[0] if j[0] == s0], [j for j in p[1] if j[0] == s0])
                 for t, p in plans.items()}
    files = [os.path.relpath(fw_path(t, s, m, a.frames), ROOT)
             for t in a.targets for (s, m, _) in plans[t][0]]
    files += [os.path.relpath(fw_path(t, s, m, a.frames, 1, 1), ROOT)
              for t in a.targets for (s, m) in WIRE if (s, m) in [j[:2] for j in plans[t][0]]]
    make(files)
    if a.build_only:
        return 0
    passed = failed = 0
    nskip = 0
    for t in a.targets:
        todo, skips = plans[t]
        results = {}

        def one(job):
            s, m, need = job
            path = fw_path(t, s, m, a.frames)
            name = "%s %s/%s" % (t, SCENES[s], mname(m))
            if not os.path.exists(path):
                return ("FAIL", "%s: not built (see the make errors above)" % name)
            reason = is_skip(path)
            if reason:
                return ("SKIP", "%s: %s" % (name, reason))
            size = {}
            if os.path.exists(path + ".size"):
                size = dict(kv.split("=") for kv in open(path + ".size").read().split())
            left = RAM[t] - int(size["ram_static"]) if t in RAM and "ram_static" in size else None
            if left is not None and left < STACK_MIN:
                return ("SKIP", "%s: RAM: statics %s B leave %d B of the %d B SRAM for the stack "
                        "(measured peaks are ~300-420 B)" % (name, size["ram_static"], left, RAM[t]))
            data, rc, d = run_target(t, path)
            ref = host_ref(s, m, a.frames, SHADING.get(SCENES[s], 1))
            if rc != 0 and left is not None and left < STACK_SUSPECT and "stack_peak" not in d:
                return ("SKIP", "%s: RAM: the run crashed (exit %d) with statics %s B leaving %d B "
                        "for the stack: stack overflow" % (name, rc, size["ram_static"], left))
            extra = "arena %d B" % need
            if "ram_static" in size:
                extra += ", static %s B" % size["ram_static"]
            if "stack_peak" in d:
                extra += ", stack %d B" % d["stack_peak"]
            if t in RAM and "stack_peak" in d and "ram_static" in size:
                total = int(size["ram_static"]) + d["stack_peak"]
                extra += ", total %d/%d B" % (total, RAM[t])
                if total >= RAM[t]:
                    return ("SKIP", "%s: RAM: statics %s + stack %d = %d B >= %d B SRAM"
                            % (name, size["ram_static"], d["stack_peak"], total, RAM[t]))
            if rc != 0:
                return ("FAIL", "%s: exit %d (%s)" % (name, rc, d["info"].strip().replace("\n", "; ")[-200:]))
            if data != ref:
                n = min(len(data), len(ref))
                at = next((i for i in range(n) if data[i] != ref[i]), n)
                return ("FAIL", "%s: stream differs from the host at byte %d (%d vs %d bytes)"
                        % (name, at, len(data), len(ref)))
            emu = emu_ref(s, m, a.frames)
            tag = "host fw"
            if isinstance(emu, tuple):
                tag += "; rast8-emu failed: %s" % emu[1]
            elif emu is not None:
                if emu != data:
                    return ("FAIL", "%s: equals the host fw build but not build/rast8-emu (%d vs %d bytes)"
                            % (name, len(data), len(emu)))
                tag += " and rast8-emu"
            res = ("PASS", "%s: %d bytes identical to %s (%s)" % (name, len(data), tag, extra))
            if t in RAM and "stack_peak" in d and "ram_static" in size:
                res += (RAM[t] - int(size["ram_static"]) - d["stack_peak"],)
            return res

        with cf.ThreadPoolExecutor(2) as ex:
            for job, res in zip(todo, ex.map(one, todo)):
                results[(job[0], job[1])] = res
        for s, m, why in skips:
            results[(s, m)] = ("SKIP", "%s %s/%s: %s" % (t, SCENES[s], mname(m), why))
        for key in sorted(results):
            st, msg = results[key][:2]
            print("%s %s" % (st, msg))
            if st == "PASS":
                passed += 1
            elif st == "FAIL":
                failed += 1
            else:
                nskip += 1
        # the wireframe (cfg.wire), its scene with its method only
        for s, m in WIRE:
            if (s, m) not in [j[:2] for j in todo]:
                continue
            st, msg = wire_check(t, s, m, a.frames)
            print("%s %s" % (st, msg))
            passed, failed = passed + (st == "PASS"), failed + (st == "FAIL")
            nskip += st == "SKIP"
        # the simulator's stream through the display-side decoder (rast8 stats)
        first = next((k for k in sorted(results) if results[k][0] == "PASS"), None)
        if first is not None:
            ok, msg = decoder_check(t, first[0], first[1], a.frames)
            print("%s %s" % ("PASS" if ok else "FAIL", msg))
            passed, failed = passed + ok, failed + (not ok)
        if t == "avr328" and not a.scene:   # (the mandatory 328P checks need every scene)
            def fits(m):
                r = results.get((0, m), ("", ""))
                return r[0] == "PASS" and len(r) > 2 and r[2] >= MARGIN_328
            def free(m):
                r = results.get((0, m), ("", ""))
                return "%d B free" % r[2] if len(r) > 2 else "-"
            cull = fits(0)
            depth = ["%s (%s)" % (mname(m), free(m)) for m in range(1, len(METHODS)) if fits(m)]
            ok = cull and depth
            print("%s mandatory: ATmega328P 128x64 1bpp cube in 2048 B SRAM with >= %d B free: "
                  "cull %s (%s), depth methods [%s]"
                  % ("PASS" if ok else "FAIL", MARGIN_328, "passes" if cull else "FAILS", free(0),
                     ", ".join(depth)))
            if ok:
                passed += 1
            else:
                failed += 1
            # issue 10: the 200-face torus with painter's (or better) on the 2 KB part
            def fits_s(s, m):
                r = results.get((s, m), ("", ""))
                return r[0] == "PASS" and len(r) > 2 and r[2] >= MARGIN_328
            tor = [mname(m) for m in range(1, len(METHODS)) if fits_s(1, m)]
            ok = bool(tor)
            r = results.get((1, 1), ("", ""))
            print("%s mandatory: ATmega328P torus (200 faces) with painter's or better, identical, "
                  ">= %d B free: [%s]%s" % ("PASS" if ok else "FAIL", MARGIN_328, ", ".join(tor),
                                            " (painter's: %d B free)" % r[2] if len(r) > 2 else ""))
            if ok:
                passed += 1
            else:
                failed += 1
    print("%d combinations skipped (reasons above)" % nskip)
    print("%d passed, %d failed" % (passed, failed))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
