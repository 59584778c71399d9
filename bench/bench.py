#!/usr/bin/env python3
"""bench.py - `make bench`: the firmware on every target, every built-in
scene x visibility method, measured in the simulators.

Writes build/bench/results.json (one record per target x scene x method,
and on the ATmega1284P per shading for the chart's scenes) and
build/bench/results.md (the same data as tables, with issue 10's targets);
`make docs` copies the tables to docs/bench-results.md.  Benchmarks
measure; nothing here asserts a timing.

Method (frames N..2N-1 everywhere, N = 2, so the first full frame and
the start-up are excluded the same way on every target):
  * AVR (ATmega1284P, ATmega328P; avr-gcc -Os): exact cycles between the
    firmware's FRAME_BEGIN/FRAME_END markers (GPIOR0 writes timed by
    emu/avrsim), minus the cycles spent busy-waiting on the UART (the
    link is accounted separately as fps_115200 / fps_1m).
  * 6502 (cc65 -Oirs, sim65): sim65 has no readable cycle counter, so
    differential builds: total cycles of the 2N-frame build minus the
    N-frame build, over N.  Includes the stream encoding and write calls.
  * Z80 (sdcc --opt-code-speed, ucsim sz80): ticks between the markers
    (write breakpoints).  ucsim under-counts some (HL) read-modify-write
    instructions, so these are indicative.
  * host (x86-64, gcc -O2): callgrind instructions of the host build of
    the same firmware main, 2N frames minus N frames, over N.
Clocks for the compute-bound fps: AVR 16 MHz, 6502 0.985 MHz (C64 PAL),
Z80 3.5 MHz (ZX Spectrum).  Link-bound fps at 8N1: baud / 10 / bytes.
RAM: ram_static_bytes = .data+.bss (AVR, avr-size), DATA+BSS (6502, ld65
map), the statics placed after the code (Z80, ports/z80/z80link.py), all
including the firmware's arena; stack_peak_bytes = free RAM painted with
0xA5 before main and the high-water mark read at the end (AVR: by
emu/avrsim from the simulator's memory; 6502/Z80: by the platform layer,
C stack + hardware stack on the 6502).  flash_bytes = code + constant
data (on AVR and Z80 constant data is also copied to RAM: it is counted
in both).
"""
import concurrent.futures as cf
import json
import os
import re
import subprocess
import sys
import tempfile
import time

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), ".."))
sys.path.insert(0, os.path.join(ROOT, "tests", "targets"))
import identity as idt  # noqa: E402

N = 2
FRAMES = 2 * N
CLOCK = {"avr1284": 16000000, "avr328": 16000000, "6502": 985248, "z80": 3500000}
CPU = {"avr1284": "ATmega1284P", "avr328": "ATmega328P", "6502": "6502", "z80": "Z80"}
TARGETS = ["avr328", "avr1284", "6502", "z80"]
SHADINGS = ["flat", "lambert", "gouraud", "texture"]   # R8_SHADE_* order
# every shading of these (the speed-accuracy chart's scenes), on the 1284P
SHADE_SCENES = ["cube", "torus", "teapot", "cross", "wall"]
W, H, FMT = 128, 64, "PAGE1"


def run(cmd, **kw):
    return subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, **kw)


def callgrind_ir(s, m, frames):
    with tempfile.TemporaryDirectory() as td:
        out = os.path.join(td, "cg.out")
        r = run(["valgrind", "--tool=callgrind", "--callgrind-out-file=" + out,
                 os.path.join(ROOT, "build", "emu", "fw-host"), str(s), str(m), str(frames)],
                timeout=600)
        if r.returncode:
            return None
        for line in open(out):
            if line.startswith("summary:") or line.startswith("totals:"):
                return int(line.split()[1])
    return None


def size_of(path):
    try:
        return {k: int(v) for k, v in (kv.split("=") for kv in open(path + ".size").read().split())}
    except (OSError, ValueError):
        return {}


def frames_from(info, key="compute"):
    """Per-frame cycles of frames N..2N-1 from FRAME lines."""
    vals = {}
    for m in re.finditer(r"FRAME (\d+) cycles=(\d+)(?: compute=(\d+))?", info):
        n = int(m.group(1))
        c = int(m.group(3)) if (key == "compute" and m.group(3)) else int(m.group(2))
        vals[n] = c
    sel = [vals[i] for i in range(N, 2 * N) if i in vals]
    return sel


def measure(t, s, m, need, host_streams, sh=1, wire=0, objs=1):
    rec = {"target": t, "cpu": CPU[t], "scene": idt.SCENES[s], "method": idt.mname(m),
           "shading": SHADINGS[idt.SHADING.get(idt.SCENES[s], sh) if sh == 1 else sh],
           "width": W, "height": H, "format": FMT, "clock_hz": CLOCK[t], "arena_bytes": need,
           "cycles_per_frame": None, "cycles_exact": None, "host_instructions_per_frame": None,
           "ram_static_bytes": None, "stack_peak_bytes": None, "flash_bytes": None,
           "wire_bytes_per_frame": None, "fps_115200": None, "fps_1m": None,
           "fps_compute": None, "identical_to_host": None, "skipped": None}
    path = idt.fw_path(t, s, m, FRAMES, sh, wire, objs)
    rec["wire"] = wire
    if not os.path.exists(path):
        rec["skipped"] = "not built"
        return rec
    why = idt.is_skip(path)
    if why:
        rec["skipped"] = why
        return rec
    sz = size_of(path)
    rec["ram_static_bytes"] = sz.get("ram_static")
    rec["flash_bytes"] = sz.get("flash")
    ref2, ref4 = host_streams
    if t in idt.RAM and rec["ram_static_bytes"] is not None and \
            idt.RAM[t] - rec["ram_static_bytes"] < idt.STACK_MIN:
        rec["skipped"] = "RAM: statics %d B leave %d B for the stack" % (
            rec["ram_static_bytes"], idt.RAM[t] - rec["ram_static_bytes"])
        return rec
    if t.startswith("avr") or t == "z80":
        with tempfile.TemporaryDirectory() as td:
            out, info = os.path.join(td, "o.bin"), os.path.join(td, "i.txt")
            prof = os.path.join(td, "prof.txt")
            if t.startswith("avr"):
                cmd = [os.path.join(ROOT, "build", "emu", "avrsim"), "-l", "4000000000", "-m", info,
                       "-F", str(N), "-P", prof, "-o", out, idt.MCU[t], path]
            else:
                cmd = [sys.executable, os.path.join(ROOT, "emu", "sz80run.py"), "-t", "600",
                       "-m", info, "-o", out, path]
            r = run(cmd, timeout=900)
            data = open(out, "rb").read() if os.path.exists(out) else b""
            text = open(info).read() if os.path.exists(info) else ""
            ptext = open(prof).read() if os.path.exists(prof) else ""
        if ptext and re.search(r"^\s*\d+ ", ptext, re.M):
            split_profile(rec, ptext)
        sel = frames_from(text, "compute" if t.startswith("avr") else "cycles")
        if len(sel) == N:
            rec["cycles_per_frame"] = sum(sel) // N
            rec["cycles_exact"] = t.startswith("avr")
        if t.startswith("avr"):
            w = [a - b for a, b in zip(frames_from(text, "cycles"), sel)]
            if w:
                rec["uart_wait_cycles_per_frame"] = sum(w) // len(w)
        mm = re.search(r"stack_peak=(\d+)", text)
        if mm:
            rec["stack_peak_bytes"] = int(mm.group(1))
        rec["identical_to_host"] = (r.returncode == 0 and data == ref4) if ref4 is not None else None
        if t in idt.RAM and rec["stack_peak_bytes"] is not None and rec["ram_static_bytes"]:
            tot = rec["stack_peak_bytes"] + rec["ram_static_bytes"]
            rec["ram_total_bytes"] = tot
            rec["ram_free_bytes"] = idt.RAM[t] - tot
        if t == "avr328" and rec["stack_peak_bytes"] is not None and rec["ram_static_bytes"]:
            if tot >= 2048:
                rec["skipped"] = "RAM: statics %d + stack %d >= 2048 B" % (rec["ram_static_bytes"],
                                                                          rec["stack_peak_bytes"])
    else:  # 6502: differential builds
        p2 = idt.fw_path(t, s, m, N, 1, 1) if wire else idt.fw_path(t, s, m, N)
        res = {}
        for frames, p in ((N, p2), (FRAMES, path)):
            if not os.path.exists(p) or idt.is_skip(p):
                break
            with tempfile.TemporaryDirectory() as td:
                out, info = os.path.join(td, "o.bin"), os.path.join(td, "i.txt")
                r = run([sys.executable, os.path.join(ROOT, "emu", "sim65run.py"), "-t", "900",
                         "-m", info, "-o", out, p], timeout=1000)
                data = open(out, "rb").read() if os.path.exists(out) else b""
                text = open(info).read() if os.path.exists(info) else ""
            mm = re.search(r"cycles=(\d+)", text)
            res[frames] = (int(mm.group(1)) if mm else None, data, r.returncode, text)
        if N in res and FRAMES in res and res[N][0] and res[FRAMES][0]:
            rec["cycles_per_frame"] = (res[FRAMES][0] - res[N][0]) // N
            rec["cycles_exact"] = True
        if FRAMES in res:
            mm = re.search(r"stack_peak=(\d+)", res[FRAMES][3])
            if mm:
                rec["stack_peak_bytes"] = int(mm.group(1))
            rec["identical_to_host"] = (res[FRAMES][2] == 0 and res[FRAMES][1] == ref4 and
                                        (N not in res or res[N][1] == ref2))
            # where the cycles go: emu/prof65 (sim65's CPU, the same totals)
            with tempfile.TemporaryDirectory() as td:
                prof = os.path.join(td, "prof.txt")
                run([os.path.join(ROOT, "build", "emu", "prof65"), "-q", "-o", os.devnull,
                     "-m", os.devnull, "-F", str(N), "-P", prof, path], timeout=600)
                ptext = open(prof).read() if os.path.exists(prof) else ""
            if ptext:
                split_profile(rec, prof65_rows(ptext))
    wire = (len(ref4) - len(ref2)) / float(N) if ref4 is not None and ref2 is not None else 0
    rec["wire_bytes_per_frame"] = round(wire, 1) if wire else None
    if wire > 0:
        rec["fps_115200"] = round(11520.0 / wire, 2)
        rec["fps_1m"] = round(100000.0 / wire, 2)
    if rec["cycles_per_frame"]:
        rec["fps_compute"] = round(CLOCK[t] / float(rec["cycles_per_frame"]), 3)
    return rec


# The 6502 port's assembly and link step, measured by bench/kern6502.py
# (the cube / cull firmware rebuilt without each piece; it rebuilds
# build/x/6502, so it is not run from here).
SECTION_6502 = [
    "## The 6502 port: what each piece buys (cube / cull)",
    "",
    "`python3 bench/kern6502.py` (measured on branch j-m6502, issue 10): sim65 cycles per "
    "frame (4-frame run minus 2-frame run, over 2) and image size of the cube / cull firmware "
    "with one piece left out.  Every variant's stream equals the host's.",
    "",
    "| 6502 cube / cull | cycles/frame | vs the build | flash | RAM static |",
    "|---|---:|---:|---:|---:|",
    "| all kernels, gc65 (the build) | 377,990 | +0 | 44,369 | 4,601 |",
    "| without r8k_trap (R8_ASM_TRAP, trap_6502.s) | 700,784 | +322,794 | 44,936 | 4,599 |",
    "| without r8_tx_band (R8_ASM_TXBAND, txband_6502.s) | 434,924 | +56,934 | 43,111 | 4,591 |",
    "| without the wire kernels (R8_ASM_WIRE + R8_ASM_TXBAND, wire_6502.s, txband_6502.s) | 721,501 | +343,511 | 43,043 | 4,094 |",
    "| without r8_scanx_fill (R8_ASM_SCANX, scanx_6502.s) | 392,703 | +14,713 | 43,735 | 4,591 |",
    "| without r8k_fill (R8_ASM_FILL, fill_6502.s) | 380,742 | +2,752 | 44,368 | 4,601 |",
    "| without r8k_xform (R8_ASM_XFORM, xform_6502.s) | 400,943 | +22,953 | 44,666 | 4,609 |",
    "| without r8k_project (R8_ASM_PROJECT, proj_6502.s) | 410,790 | +32,800 | 44,171 | 4,613 |",
    "| without r8k_edge (R8_ASM_EDGE, edge_6502.s) | 391,216 | +13,226 | 44,686 | 4,632 |",
    "| without r8_mul16 (R8_ASM_MUL16, mul16_6502.s) | 392,972 | +14,982 | 44,591 | 4,605 |",
    "| without cc65's runtime multiplies replaced (rtmul_6502.s) | 397,291 | +19,301 | 44,080 | 4,601 |",
    "| without gc65 (whole objects linked) | 378,120 | +130 | 53,958 | 4,825 |",
    "| none of it (the C, cc65's runtime, whole objects) | 1,372,456 | +994,466 | 49,763 | 2,268 |",
    "",
    "* The multiplies (ports/6502/mul_6502.s) are quarter squares: four 512-entry tables "
    "(2 KB) and the CRC table (512 B) are built in RAM before main (R8PAGE in "
    "ports/6502/rast8.cfg: RAM static above includes them, the image does not).",
    "* ports/6502/gc65.py drops every function and data item nothing reaches from `main` "
    "(cc65 links whole object files), on every 6502 program.",
    "* emu/prof65 runs the same .prg as sim65 (same cycle totals, tests/targets/prof65_check.py) "
    "and gives cycles per function (`-P`), per instruction (`-H`, with ld65's debug file; "
    "`emu/prof65_lines.py` sums them per C line) and coverage (`-C`).",
    "",
]

WIRE_FN = re.compile(r"crc|rle|cobs|tx_|put_raw|^out$|plat_|codec|lz77|raw_copy")


def prof65_rows(ptext):
    """6502: emu/prof65 -P as avrsim's "cycles pct name" rows: each C
    function with the runtime helpers (and assembly labels) it calls, so
    the rows add up to the frames' cycles."""
    rows = []
    for line in ptext.splitlines():
        f = line.split()
        if line.startswith("#") or len(f) != 7 or not f[6].startswith("_"):
            continue
        rows.append((int(f[2]), f[6][1:]))
    rows.sort(key=lambda r: -r[0])
    return "\n".join("%d - %s" % r for r in rows)


def split_profile(rec, ptext):
    """AVR: per-function cycles of frames N..2N-1 (emu/avrsim -P): render
    vs wire (CRC, RLE, COBS, packet assembly, UART writes), and the top 8."""
    render = wire = 0
    top = []
    for line in ptext.splitlines():
        f = line.split()
        if len(f) != 3 or line.startswith("#"):
            continue
        cyc, name = int(f[0]), f[2]
        if WIRE_FN.search(name):
            wire += cyc
        else:
            render += cyc
        if len(top) < 8:
            top.append([name, cyc // N])
    rec["cycles_render_per_frame"] = render // N
    rec["cycles_wire_per_frame"] = wire // N
    rec["profile_top"] = top


def fmt(v, nd=0):
    if v is None:
        return "-"
    if isinstance(v, bool):
        return "yes" if v else "**NO**"
    if isinstance(v, float):
        return ("%%.%df" % nd) % v
    if isinstance(v, int) and v >= 10000:
        return "{:,}".format(v)
    return str(v)


def write_md(recs, host, elapsed):
    L = []
    L.append("# Benchmark results (generated by `make bench`, bench/bench.py)")
    L.append("")
    L.append("Do not edit: `make bench` writes build/bench/results.md from "
             "`build/bench/results.json` and `make docs` copies it here (docs/benchmarks.md "
             "explains the figures).  %s; commit %s; "
             "run took %.0f s." % (time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime()),
                                  git_rev(), elapsed))
    L.append("")
    L.append("128x64 PAGE1 (1 bpp, SSD1306 layout), 8-row bands, Lambert shading, RLE + COBS + "
             "CRC-16 wire protocol, `app_defaults()` otherwise.  Frames %d..%d of a %d-frame run "
             "(frame 0 is the full frame; later frames send changed bands only)." % (N, 2 * N - 1, 2 * N))
    L.append("")
    L.append("**How it is measured** (details in bench/bench.py):")
    L.append("")
    L.append("* **cycles/frame** - AVR: exact, between the firmware's FRAME_BEGIN/FRAME_END GPIOR0 "
             "markers in libsimavr (emu/avrsim), minus the UART busy-wait; 6502: exact totals of "
             "sim65 runs with %d and %d frames, subtracted (differential builds); Z80: ucsim sz80 "
             "ticks between markers, indicative (ucsim under-counts some `(HL)` read-modify-write "
             "instructions)." % (N, 2 * N))
    L.append("* **host Ir/frame** - callgrind instructions of the host build of the same firmware "
             "main (x86-64, gcc -O2), %d-frame run minus %d-frame run, over %d." % (2 * N, N, N))
    L.append("* **compute fps** at AVR 16 MHz, 6502 0.985 MHz (C64 PAL), Z80 3.5 MHz (ZX Spectrum). "
             "**link fps** = baud / 10 / wire bytes per frame (8N1).")
    L.append("* **RAM static** = .data + .bss including the firmware's arena (`app_ram()` bytes: "
             "renderer work memory + one band + encoder scratch); **stack** = measured high-water "
             "mark (free RAM painted with 0xA5); **flash** = code + constant data (tables and "
             "meshes are R8_FLASH: program memory on AVR, read with `pgm_read_*`).")
    L.append("* **same** = the target's UART stream is byte-identical to the host build's.")
    L.append("")
    lam = [r for r in recs if r["shading"] == "lambert"]
    L.extend(targets_md(lam))
    L.extend(shadings_md(recs))
    ray = [r for r in recs if r["method"] == "ray"]
    if ray:
        L += ["## Ray caster (the maze, docs/visibility.md)", "", scene_md(ray)]
    L.append("## Headline")
    L.append("")
    L.append("| target | scene | method | cycles/frame | of which render / wire | ms | compute fps | RAM static+stack | flash | same |")
    L.append("|---|---|---|---:|---:|---:|---:|---:|---:|---|")
    for r in lam:
        if r["scene"] in ("cube", "torus") and r["target"] in ("avr1284", "avr328", "6502", "z80"):
            if r["cycles_per_frame"] is None and r["target"] != "avr328":
                continue
            ms = (1000.0 * r["cycles_per_frame"] / r["clock_hz"]) if r["cycles_per_frame"] else None
            ram = None
            if r["ram_static_bytes"] is not None and r["stack_peak_bytes"] is not None:
                ram = "%d+%d" % (r["ram_static_bytes"], r["stack_peak_bytes"])
                if r.get("ram_free_bytes") is not None and r["target"] == "avr328" and not r["skipped"]:
                    ram += " (%d free)" % r["ram_free_bytes"]
            split = "-"
            if r.get("cycles_render_per_frame") is not None and r["cycles_per_frame"]:
                split = "%s / %s" % (fmt(r["cycles_render_per_frame"]), fmt(r["cycles_wire_per_frame"]))
            L.append("| %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |" % (
                r["cpu"], r["scene"], r["method"], fmt(r["cycles_per_frame"]), split, fmt(ms, 1),
                fmt(r["fps_compute"], 2), ram or "-", fmt(r["flash_bytes"]),
                fmt(r["identical_to_host"]) if not r["skipped"] else "skip: " + r["skipped"][:60]))
    L.append("")
    L.append("*render / wire*: AVR cycles per function (emu/avrsim -P), split into the renderer "
             "and the wire encoder (CRC-16, RLE, COBS, packets, UART writes).")
    L.append("")
    prof = [r for r in lam if r["target"] == "avr1284" and r.get("profile_top")
            and r["scene"] in ("cube", "torus") and r["method"] in ("cull", "zbuf16", "block")]
    if prof:
        L.append("## Where the AVR cycles go (ATmega1284P, cycles per frame, top functions)")
        L.append("")
        for r in prof:
            L.append("* **%s / %s** (%s cycles): %s" % (r["scene"], r["method"], fmt(r["cycles_per_frame"]),
                     ", ".join("`%s` %s" % (n, fmt(c)) for n, c in r["profile_top"])))
        L.append("")
    prof = [r for r in recs if r["target"] == "6502" and r.get("profile_top")
            and r["scene"] in ("cube", "torus") and r["method"] in ("cull", "painter", "zbuf16")]
    if prof:
        L.append("## Where the 6502 cycles go (emu/prof65, cycles per frame, top C functions "
                 "with the runtime helpers they call)")
        L.append("")
        for r in prof:
            L.append("* **%s / %s** (%s cycles): %s" % (r["scene"], r["method"], fmt(r["cycles_per_frame"]),
                     ", ".join("`%s` %s" % (n, fmt(c)) for n, c in r["profile_top"])))
        L.append("")
        L.extend(SECTION_6502)
    mic = micro()
    if mic:
        with open(os.path.join(ROOT, "build", "bench", "micro.json"), "w") as f:
            json.dump(mic, f, indent=1)
        L.append("## Inner loops (bench/fw_micro.c; build/bench/micro.json)")
        L.append("")
        L.append("| piece | what | unit | ATmega1284P cycles/unit | Z80 T-states/unit (indicative) |")
        L.append("|---|---|---|---:|---:|")
        for name, _, what, unit in MICRO:
            a = [x for x in mic if x["piece"] == name and x["target"] == "avr1284"]
            z = [x for x in mic if x["piece"] == name and x["target"] == "z80"]
            L.append("| %s | %s | %s | %s | %s |" % (name, what, unit,
                     a[0]["cycles_per_unit"] if a else "-", z[0]["cycles_per_unit"] if z else "-"))
        L.append("")
    L.extend(codec_section())
    L.extend(ram_budget_328())
    L.extend([
        "## Running the firmware yourself",
        "",
        "```",
        "make fw                                   # every firmware image the tests use",
        "build/emu/avrsim atmega1284p build/x/avr1284/fw/fw-1-3-4.elf | .venv/bin/rast8 stats -",
        "build/emu/avrsim -P prof.txt -F 2 -o out.bin atmega1284p FW.elf   # cycles per function",
        "build/emu/avrsim -p atmega1284p FW.elf    # UART on a pty (name on stderr; start with a line on stdin)",
        "python3 emu/sim65run.py -o out.bin build/x/6502/fw/fw-0-0-4.prg",
        "python3 emu/sz80run.py -o out.bin -m marks.txt build/x/z80/fw/fw-0-0-4.ihx",
        "make xident-avr328                        # the 2 KB ATmega328P identity run",
        "```",
        "",
        "fw-S-M-F: scene S, method M (numbers as in r8render.h), F frames.  Every stream "
        "decodes with `rast8 decode` / `rast8 stats` (the identity tests pipe one per target "
        "through `rast8 stats`).",
        ""])
    for t in TARGETS:
        rs = [r for r in lam if r["target"] == t]
        L.append("## %s (%s)" % (CPU[t], t))
        L.append("")
        L.append("| scene | method | cycles/frame | host Ir/frame | compute fps | wire B/frame | "
                 "fps 115200 | fps 1M | arena | RAM static | stack | flash | same | note |")
        L.append("|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|---|")
        for r in rs:
            L.append("| %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |" % (
                r["scene"], r["method"], fmt(r["cycles_per_frame"]),
                fmt(r["host_instructions_per_frame"]), fmt(r["fps_compute"], 2),
                fmt(r["wire_bytes_per_frame"], 1), fmt(r["fps_115200"], 1), fmt(r["fps_1m"], 1),
                fmt(r["arena_bytes"]), fmt(r["ram_static_bytes"]), fmt(r["stack_peak_bytes"]),
                fmt(r["flash_bytes"]), fmt(r["identical_to_host"]),
                (r["skipped"] or "").replace("|", "/")[:110]))
        L.append("")
    with open(os.path.join(ROOT, "build", "bench", "results.md"), "w") as f:
        f.write("\n".join(L) + "\n")


# issue 10's figures: (label, target, scene, method, field, must, aim)
TARGETS10 = [
    ("AVR cube, cull: render", "avr1284", "cube", "cull", "cycles_render_per_frame", 40000, 25000),
    ("AVR cube: wire encoding", "avr1284", "cube", "cull", "cycles_wire_per_frame", 30000, 15000),
    ("AVR torus, cull: render", "avr1284", "torus", "cull", "cycles_render_per_frame", 500000, 300000),
    ("AVR torus, zbuf16: render", "avr1284", "torus", "zbuf16", "cycles_render_per_frame", 800000, 400000),
    ("AVR teapot, painter's: render", "avr1284", "teapot", "painter", "cycles_render_per_frame", 600000, 400000),
    ("6502 cube, cull (with the wire)", "6502", "cube", "cull", "cycles_per_frame", 400000, 200000),
    ("Z80 cube, cull (with the wire), T-states", "z80", "cube", "cull", "cycles_per_frame", 500000, 250000),
    ("AVR flash, cube firmware (bytes)", "avr1284", "cube", "cull", "flash_bytes", 12 * 1024, 8 * 1024),
    ("6502 image, cube firmware (bytes)", "6502", "cube", "cull", "flash_bytes", 24 * 1024, None),
    ("Z80 image, cube firmware (bytes)", "z80", "cube", "cull", "flash_bytes", 24 * 1024, None),
]


def targets_md(recs):
    """Issue 10's table: each figure against its must-reach and aim."""
    by = {(r["target"], r["scene"], r["method"]): r for r in recs}
    L = ["## Issue 10 targets", "",
         "| measure | measured | must reach | aim | |", "|---|---:|---:|---:|---|"]
    for label, t, sc, m, field, must, aim in TARGETS10:
        r = by.get((t, sc, m))
        v = r.get(field) if r else None
        ok = "" if v is None else ("**met**" if v <= must else "missed")
        if v is not None and aim is not None and v <= aim:
            ok = "**aim met**"
        L.append("| %s | %s | <= %s | %s | %s |" % (label, fmt(v), fmt(must),
                                                     "<= " + fmt(aim) if aim else "-", ok))
    for sc in ("torus", "teapot"):
        ps = [r for r in recs if r["target"] == "avr328" and r["scene"] == sc
              and r["method"] != "cull" and r.get("identical_to_host") and not r["skipped"]]
        best = max(ps, key=lambda r: r.get("ram_free_bytes") or 0) if ps else None
        L.append("| ATmega328P (2 KB): %s with painter's or better | %s | runs, identical, >= 64 B free | %s | %s |"
                 % (sc, "%s, %s B free" % (best["method"], best.get("ram_free_bytes")) if best else "does not fit",
                    "also the teapot" if sc == "torus" else "-",
                    ("**met**" if best and (best.get("ram_free_bytes") or 0) >= 64 else "missed")))
    L.append("")
    return L


def shadings_md(recs):
    """Render cycles per frame of every method x shading (ATmega1284P)."""
    rs = [r for r in recs if r["target"] == "avr1284" and r["scene"] in SHADE_SCENES]
    by = {(r["scene"], r["method"], r["shading"]): r for r in rs}
    L = ["## Every shading (ATmega1284P, render cycles per frame)", "",
         "The chart's cost axis (`make chart`).  *same*: all three streams equal the host's.", "",
         "| scene | method | flat | Lambert | Gouraud | same |", "|---|---|---:|---:|---:|---|"]
    for sc in SHADE_SCENES:
        for m in idt.METHODS[:7]:
            cells, same = [], True
            for sh in SHADINGS:
                r = by.get((sc, m, sh))
                if r is None or r["skipped"]:
                    cells.append("skip" if r is not None else "-")
                    continue
                cells.append(fmt(r.get("cycles_render_per_frame")))
                same = same and bool(r.get("identical_to_host"))
            L.append("| %s | %s | %s | %s | %s | %s |" % (sc, m, cells[0], cells[1], cells[2],
                                                         "yes" if same else "**NO**"))
    L.append("")
    return L


MICRO = [("span", 10, "r8_fb_span_dither, PAGE1, 120-px rows", "pixel"),
         ("fill", 12, "r8_scan_fill of a 2405-px triangle (edges + spans)", "pixel"),
         ("edges", 14, "r8_scan_next, depth + shade attributes", "row (both edges)"),
         ("vert", 16, "r8_mat_apply + 3 r8_asr14 + r8_project", "vertex"),
         ("crc", 18, "r8_crc16_update", "byte"),
         ("rle", 20, "r8_rle_encode", "byte"),
         ("crc32", 22, "r8_crc32_update (R8_WIRE_CRC32's frame check)", "byte"),
         ("line", 24, "r8_line, 128-px lines across the PAGE1 frame", "pixel"),
         ("wu", 26, "r8_wu_line, PAGE1 dithered, 128-step lines", "step (2 px)"),
         ("circle", 28, "r8_circle, radius 30, PAGE1", "circle"),
         ("disc", 30, "r8_circle_fill, radius 30, PAGE1", "circle")]


def lines_bench(recs):
    """The wireframe cube (cfg.wire, cull) on every target, beside the
    filled cube's record: build/bench/lines.json."""
    try:
        st = (idt.host_ref(0, 0, N, 1, 1), idt.host_ref(0, 0, FRAMES, 1, 1))
    except Exception as e:  # noqa: BLE001
        print("bench: host wireframe: %s" % e)
        st = (b"", b"")
    out = []
    for t in TARGETS:
        r = measure(t, 0, 0, None, st, 1, 1)
        filled = [x for x in recs if x["target"] == t and x["scene"] == "cube" and
                  x["method"] == "cull" and x["shading"] == "lambert"]
        if filled:
            r["filled_cycles_per_frame"] = filled[0]["cycles_per_frame"]
            r["filled_flash_bytes"] = filled[0]["flash_bytes"]
        out.append(r)
    os.makedirs(os.path.join(ROOT, "build", "bench"), exist_ok=True)
    with open(os.path.join(ROOT, "build", "bench", "lines.json"), "w") as f:
        json.dump(out, f, indent=1)
    return out


def lines_md(wire_recs):
    """Appends the wireframe table to build/bench/results.md."""
    L = ["", "## Wireframe (cfg.wire; build/bench/lines.json)", "",
         "The cube with the cull drawn as Bresenham edges of its front faces "
         "(fw-0-0-%d-1-1), against the filled cube's firmware (fw-0-0-%d)." % (FRAMES, FRAMES), "",
         "| target | wire cycles/frame | filled cycles/frame | wire flash | filled flash | wire B/frame | same |",
         "|---|---|---|---|---|---|---|"]
    for r in wire_recs:
        L.append("| %s | %s | %s | %s | %s | %s | %s |" % (
            r["target"], fmt(r["cycles_per_frame"]), fmt(r.get("filled_cycles_per_frame")),
            fmt(r["flash_bytes"]), fmt(r.get("filled_flash_bytes")),
            fmt(r["wire_bytes_per_frame"], 1), fmt(r["identical_to_host"]) if not r["skipped"]
            else "skipped: %s" % r["skipped"]))
    with open(os.path.join(ROOT, "build", "bench", "results.md"), "a") as f:
        f.write("\n".join(L) + "\n")


def micro():
    """Inner-loop costs from bench/fw_micro.c on the 1284P (exact) and the
    Z80 (indicative): cycles per pixel / row / vertex / byte."""
    res = []
    for t in ("avr1284", "z80"):
        path = os.path.join(idt.XB, t, "micro." + idt.EXT[t])
        if not os.path.exists(path) or idt.is_skip(path):
            continue
        with tempfile.TemporaryDirectory() as td:
            out, info = os.path.join(td, "o.txt"), os.path.join(td, "i.txt")
            if t.startswith("avr"):
                cmd = [os.path.join(ROOT, "build", "emu", "avrsim"), "-m", info, "-o", out,
                       idt.MCU[t], path]
            else:
                cmd = [sys.executable, os.path.join(ROOT, "emu", "sz80run.py"), "-m", info,
                       "-o", out, path]
            run(cmd, timeout=300)
            text = open(info).read() if os.path.exists(info) else ""
            units = open(out).read().split() if os.path.exists(out) else []
        delta = {}
        for m in re.finditer(r"MARK (\d+) \S+ delta=(\d+)(?: wait=(\d+))?", text):
            delta[int(m.group(1))] = int(m.group(2))
        counts = [int(u.split("=")[1]) for u in units if "=" in u]
        for k, (name, mk, what, unit) in enumerate(MICRO):
            if mk + 1 in delta and k < len(counts) and counts[k]:
                res.append({"target": t, "piece": name, "what": what, "unit": unit,
                            "cycles": delta[mk + 1], "units": counts[k],
                            "cycles_per_unit": round(delta[mk + 1] / float(counts[k]), 1)})
    return res


def codec_section():
    """The band codecs per CPU (bench/codec_bench.py; build/bench/codecs.json)."""
    import codec_bench  # bench/codec_bench.py (bench/ is on sys.path[0])
    idt.make([t[1] for t in codec_bench.TARGETS] + ["build/emu/prof65"])
    rows, bad = codec_bench.measure()
    with open(os.path.join(ROOT, "build", "bench", "codecs.json"), "w") as f:
        json.dump(rows, f, indent=1)
    for b in bad:
        print("bench: codecs: %s" % b)
    return (["## Band codecs (bench/codec_bench.py, bench/fw_codecs.c; build/bench/codecs.json)", ""]
            + codec_bench.table(rows) + [""])


def ram_budget_328():
    """Where the 2 KB of the ATmega328P go in the cube/cull firmware."""
    elf = idt.fw_path("avr328", 0, 0, FRAMES)
    if os.path.exists(elf + ".toobig"):
        elf += ".toobig"
    if not os.path.exists(elf) or idt.is_skip(elf):
        return []
    r = run(["avr-nm", "-S", "--size-sort", elf])
    syms = []
    for line in r.stdout.decode().splitlines():
        f = line.split()
        if len(f) == 4 and f[2].lower() in ("b", "d") and int(f[0], 16) >= 0x800100:
            syms.append((int(f[1], 16), f[3]))
    syms.sort(reverse=True)
    total = sum(n for n, _ in syms)
    L = ["## ATmega328P: where the 2048 bytes go (cube / cull firmware)", ""]
    rec_stack = None
    info = run([os.path.join(ROOT, "build", "emu", "avrsim"), "-q", "-o", "/dev/null", "-m", "/dev/stdout",
                "atmega1284p", idt.fw_path("avr1284", 0, 0, FRAMES)]).stdout.decode()
    m = re.search(r"stack_peak=(\d+)", info)
    if m:
        rec_stack = int(m.group(1))
    L.append("Static RAM %d B (the same program on the 1284P peaks at %s B of stack): %s."
             % (total, rec_stack, ", ".join("`%s` %d" % (nm, n) for n, nm in syms[:14])))
    L.append("`mem` is the firmware's arena (`app_ram()`: renderer work memory, one 128-byte band, "
             "encoder scratch).")
    L.append("")
    return L


def scene_md(recs):
    """One scene's records as a table (bench.py --scene)."""
    out = ["| target | method | shading | cycles/frame | fps (compute) | arena B | RAM static B "
           "| stack B | flash B | wire B/frame | same as host |",
           "|---|---|---|---:|---:|---:|---:|---:|---:|---:|---|"]
    for r in recs:
        out.append("| %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |" % (
            r["cpu"], r["method"], r["shading"], fmt(r["cycles_per_frame"]),
            r["fps_compute"] if r["fps_compute"] is not None else "-", fmt(r["arena_bytes"]),
            fmt(r["ram_static_bytes"]), fmt(r["stack_peak_bytes"]), fmt(r["flash_bytes"]),
            r["wire_bytes_per_frame"] if r["wire_bytes_per_frame"] is not None else "-",
            r["skipped"] or fmt(r["identical_to_host"])))
    for r in [r for r in recs if "texel_wrong_rate" in r][:1]:
        out.append("")
        out.append("Textured maze (tmaze) against the float ray caster sampling its textures at "
                   "each wall pixel's centre (rast8.raycast_ref --scene tmaze, 200 cameras): wrong "
                   "pixels per frame mean %.1f, max %d (%.2f %% of wall pixels); level error mean "
                   "%.4f." % (r["texel_wrong_pixels_per_frame_mean"], r["texel_wrong_pixels_per_frame_max"],
                              100 * r["texel_wrong_rate"], r["texel_level_error_mean"]))
    for r in recs[:1]:
        if "wall_height_error_max_px" in r:
            out.append("")
            out.append("Wall height per column against the float ray caster (rast8.raycast_ref, "
                       "200 cameras in the maze): max %.3f px (%.2f %%), mean %.4f px; columns "
                       "that hit another face (grazing a corner): %s." % (
                           r["wall_height_error_max_px"], 100 * r["wall_height_error_max_rel"],
                           r["wall_height_error_mean_px"], r["wall_height_columns_other_face"]))
    return "\n".join(out) + "\n"


def git_rev():
    r = run(["git", "rev-parse", "--short", "HEAD"], cwd=ROOT)
    return r.stdout.decode().strip() or "?"


def ray_figures(scene="maze"):
    """The ray caster's wall-height error per column against the float
    caster (host/rast8/raycast_ref.py over 200 cameras in the maze); the
    textured maze's also its texel error ("tex")."""
    if idt.make(["build/r8raycols"]):
        return None
    sys.path.insert(0, os.path.join(ROOT, "host"))
    from rast8 import raycast_ref  # noqa: E402
    return raycast_ref.run(os.path.join(ROOT, "build", "r8raycols"), 200, scene=scene)


PORTAL_SCENE = 9                 # rooms (scenes/demo.h R8_DEMO_ROOMS)
PORTAL_METHODS = [16, 3, 1]      # portal, zbuf16, painter's
PORTAL_TARGETS = ["avr1284", "6502", "z80"]
PORTAL_WALLS = "avr1284"         # where the walls alone (no movable objects) are timed too


def portal_main():
    """--portal (make bench-portal): issue 14's figures only.  The host
    walk (build/portal_bench: every frame of the rooms path) gives
    overdraw, polygons, vertices transformed, sectors and differences; the
    firmware of the rooms with each method on the targets gives cycles
    (frames N..2N-1: the first room, looking at its door), RAM and flash."""
    t0 = time.time()
    os.chdir(ROOT)
    r = run([os.path.join(ROOT, "build", "portal_bench")], timeout=600)
    if r.returncode:
        sys.exit("bench: build/portal_bench failed: %s" % r.stderr.decode()[-300:])
    host = [json.loads(line) for line in r.stdout.decode().splitlines() if line.strip()]
    ready = ["build/emu/avrsim", "build/emu/prof65", "build/emu/fw-host"] + sorted(
        {"build/x/%s/sizes.txt" % idt.SIZES[t] for t in PORTAL_TARGETS})
    if idt.make(ready, keep_going=False):
        sys.exit("bench: cannot build the runners / sizes")
    files = []
    for t in PORTAL_TARGETS:
        for m in PORTAL_METHODS:
            files.append(os.path.relpath(idt.fw_path(t, PORTAL_SCENE, m, FRAMES), ROOT))
            if t == "6502":
                files.append(os.path.relpath(idt.fw_path(t, PORTAL_SCENE, m, N), ROOT))
    # the portal firmware without the movable objects (the walls alone)
    files.append(os.path.relpath(idt.fw_path(PORTAL_WALLS, PORTAL_SCENE, 16, FRAMES, objs=0), ROOT))
    print("bench: building %d firmware images" % len(files))
    idt.make(files)
    jobs = []
    for t in PORTAL_TARGETS:
        sizes, _ = idt.read_sizes(t)
        for m in PORTAL_METHODS:
            st = (idt.host_ref(PORTAL_SCENE, m, N), idt.host_ref(PORTAL_SCENE, m, FRAMES))
            jobs.append((t, m, sizes.get((PORTAL_SCENE, m), 0), st, 1))
    # (no host stream of the walls alone: fw-host draws the scene as built;
    # its arena is the one with the objects: app_ram() of the walls alone
    # is less)
    jobs.append((PORTAL_WALLS, 16, idt.read_sizes(PORTAL_WALLS)[0].get((PORTAL_SCENE, 16), 0),
                 (None, None), 0))
    print("bench: running %d simulations" % len(jobs))
    with cf.ThreadPoolExecutor(2) as ex:
        recs = list(ex.map(lambda j: measure(j[0], PORTAL_SCENE, j[1], j[2], j[3], objs=j[4]), jobs))
    for rec, j in zip(recs, jobs):
        if not j[4]:
            rec["method"] += " (walls alone)"
            rec["identical_to_host"] = rec["identical_to_host"] or "not compared"
    out = {"scene": "rooms", "host_walk": host, "targets": recs}
    os.makedirs(os.path.join(ROOT, "build", "bench"), exist_ok=True)
    with open(os.path.join(ROOT, "build", "bench", "portal.json"), "w") as f:
        json.dump(out, f, indent=1)
    L = ["## Portal renderer (rooms, 128x64)", "",
         "Host walk: all %d frames of the camera path (8 bpp, Lambert, band 8, clip 24)." %
         host[0]["frames"], "",
         "| method | objects | overdraw mean | max | polygons mean | max | vertices transformed (walls: of %d) |"
         " sectors visited (of %d) | faces tested | objects set up / not seen (mean) |"
         " pixels != zbuf16 (max) | work RAM, band 8 |" % (
             host[0]["vertices"], host[0].get("sectors", 0)),
         "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"]
    for h in host:
        L.append("| %s | %d | %.3f | %.3f | %.1f | %d | %.1f | %s | %s | %s | %.1f (%d) | %d |" % (
            h["method"], h.get("objects", 0), h["overdraw_mean"], h["overdraw_max"], h["polygons_mean"],
            h["polygons_max"], h["vertices_transformed_mean"],
            "%.2f" % h["sectors_visited_mean"] if "sectors_visited_mean" in h else "all",
            "%.1f" % h["faces_tested_mean"] if "faces_tested_mean" in h else "all",
            "%.2f / %.2f" % (h["objects_set_up_mean"], h["objects_unseen_mean"])
            if "objects_set_up_mean" in h else "all",
            h["pixels_differing_from_zbuf16_mean"], h["pixels_differing_from_zbuf16_max"],
            h["work_bytes_band8"]))
    L += ["", "Firmware (frames %d..%d of the walk; PAGE1, Lambert):" % (N, 2 * N - 1), "",
          "| target | method | cycles/frame | fps | arena | static RAM | stack | flash | same as host |",
          "|---|---|---:|---:|---:|---:|---:|---:|---|"]
    for rec in recs:
        L.append("| %s | %s | %s | %s | %s | %s | %s | %s | %s |" % (
            rec["target"], rec["method"], fmt(rec["cycles_per_frame"]), fmt(rec["fps_compute"], 2),
            fmt(rec["arena_bytes"]), fmt(rec["ram_static_bytes"]), fmt(rec["stack_peak_bytes"]),
            fmt(rec["flash_bytes"]), rec["skipped"] or rec["identical_to_host"]))
    with open(os.path.join(ROOT, "build", "bench", "portal.md"), "w") as f:
        f.write("\n".join(L) + "\n")
    print("\n".join(L))
    print("bench: wrote build/bench/portal.json and portal.md in %.0f s" % (time.time() - t0))


def main():
    if "--portal" in sys.argv[1:]:
        return portal_main()
    import argparse
    ap = argparse.ArgumentParser(description="make bench: every target x scene x method")
    ap.add_argument("--scene", help="this built-in scene only (e.g. maze), written to "
                    "build/bench/results-SCENE.json / .md instead of results.*")
    a = ap.parse_args()
    only = None
    if a.scene:
        if a.scene not in idt.SCENES:
            sys.exit("bench: unknown scene '%s' (%s)" % (a.scene, ", ".join(n for n in idt.SCENES if n)))
        only = idt.SCENES.index(a.scene)
    t0 = time.time()
    os.chdir(ROOT)
    ready = ["build/emu/avrsim", "build/emu/prof65", "build/emu/fw-host"] + sorted(
        {"build/x/%s/sizes.txt" % idt.SIZES[t] for t in TARGETS})
    if idt.make(ready, keep_going=False):
        sys.exit("bench: cannot build the runners / sizes")
    idt.make(["build/x/avr1284/micro.elf", "build/x/z80/micro.ihx"])
    plans = {t: idt.plan(t, FRAMES) for t in TARGETS}
    if only is not None:
        plans = {t: ([j for j in p[0] if j[0] == only], [j for j in p[1] if j[0] == only])
                 for t, p in plans.items()}
    files = []
    for t in TARGETS:
        for s, m, _ in plans[t][0]:
            files.append(os.path.relpath(idt.fw_path(t, s, m, FRAMES), ROOT))
            if t == "6502":
                files.append(os.path.relpath(idt.fw_path(t, s, m, N), ROOT))
    # the other shadings (flat, Gouraud) of the chart's scenes on the 1284P
    shade_jobs = []
    idt.make(["build/x/avr1284/sizes-sh2.txt"])
    for s in [idt.SCENES.index(n) for n in SHADE_SCENES if only is None or n == a.scene]:
        for m in range(len(idt.METHODS)):
            if (s, m) not in set(idt.combos()):
                continue
            for sh in (0, 2):
                shade_jobs.append((s, m, sh))
                files.append(os.path.relpath(idt.fw_path("avr1284", s, m, FRAMES, sh), ROOT))
    # the wireframe cube (cfg.wire, cull) on every target
    for t in TARGETS:
        files.append(os.path.relpath(idt.fw_path(t, 0, 0, FRAMES, 1, 1), ROOT))
        if t == "6502":
            files.append(os.path.relpath(idt.fw_path(t, 0, 0, N, 1, 1), ROOT))
    print("bench: building %d firmware images" % len(files))
    idt.make(files)
    # host streams and callgrind
    combos = [(s, m) for s, m in idt.combos() if only is None or s == only]
    streams = {}
    for s, m in combos:
        try:
            sh = idt.SHADING.get(idt.SCENES[s], 1)   # the crate's firmware is textured
            streams[(s, m)] = (idt.host_ref(s, m, N, sh), idt.host_ref(s, m, FRAMES, sh))
        except Exception as e:  # noqa: BLE001
            print("bench: host %d %d: %s" % (s, m, e))
            streams[(s, m)] = (b"", b"")
    print("bench: callgrind on the host build (%d runs)" % (2 * len(combos)))
    host = {}

    def cg(sm):
        s, m = sm
        a, b = callgrind_ir(s, m, N), callgrind_ir(s, m, FRAMES)
        return sm, ((b - a) // N if a is not None and b is not None else None)

    with cf.ThreadPoolExecutor(2) as ex:
        for sm, v in ex.map(cg, combos):
            host[sm] = v
    recs = []
    jobs = []
    for t in TARGETS:
        todo, skips = plans[t]
        for s, m, need in todo:
            jobs.append((t, s, m, need))
        for s, m, why in skips:
            sizes, _ = idt.read_sizes(t)
            rec = measure(t, s, m, sizes.get((s, m), 0), streams[(s, m)]) if False else None
            rec = {"target": t, "cpu": CPU[t], "scene": idt.SCENES[s], "method": idt.mname(m), "shading": "lambert",
                   "width": W, "height": H, "format": FMT, "clock_hz": CLOCK[t],
                   "arena_bytes": sizes.get((s, m), 0) or None, "cycles_per_frame": None,
                   "cycles_exact": None, "host_instructions_per_frame": None,
                   "ram_static_bytes": None, "stack_peak_bytes": None, "flash_bytes": None,
                   "wire_bytes_per_frame": None, "fps_115200": None, "fps_1m": None,
                   "fps_compute": None, "identical_to_host": None, "skipped": why}
            recs.append(rec)
    print("bench: running %d simulations" % (len(jobs) + len(shade_jobs)))
    with cf.ThreadPoolExecutor(2) as ex:
        futs = [ex.submit(measure, t, s, m, need, streams[(s, m)]) for t, s, m, need in jobs]
        for s, m, sh in shade_jobs:
            try:
                st = (idt.host_ref(s, m, N, sh), idt.host_ref(s, m, FRAMES, sh))
            except Exception as e:  # noqa: BLE001
                print("bench: host %d %d %s: %s" % (s, m, SHADINGS[sh], e))
                st = (b"", b"")
            futs.append(ex.submit(measure, "avr1284", s, m, None, st, sh))
        for f in cf.as_completed(futs):
            recs.append(f.result())
    for r in recs:
        s, m = idt.SCENES.index(r["scene"]), idt.mid(r["method"])
        if r["shading"] != "lambert":
            continue                     # host figures and streams: Lambert's
        r["host_instructions_per_frame"] = host.get((s, m))
        if r["wire_bytes_per_frame"] is None and streams[(s, m)][1]:
            wire = (len(streams[(s, m)][1]) - len(streams[(s, m)][0])) / float(N)
            r["wire_bytes_per_frame"] = round(wire, 1)
            if wire > 0:
                r["fps_115200"] = round(11520.0 / wire, 2)
                r["fps_1m"] = round(100000.0 / wire, 2)
    order = {t: i for i, t in enumerate(TARGETS)}
    recs.sort(key=lambda r: (order[r["target"]], SHADINGS.index(r["shading"]) != 1,
                             idt.SCENES.index(r["scene"]), idt.mid(r["method"]),
                             SHADINGS.index(r["shading"])))
    if any(r["method"] == "ray" for r in recs):
        fig = ray_figures()
        tfig = ray_figures("tmaze") if any(r["scene"] == "tmaze" for r in recs) else None
        for r in recs:
            if r["scene"] == "tmaze" and tfig and "tex" in tfig:
                t = tfig["tex"]
                r["texel_wrong_pixels_per_frame_mean"] = round(t["wrong_mean"], 1)
                r["texel_wrong_pixels_per_frame_max"] = t["wrong_max"]
                r["texel_wrong_rate"] = round(t["wrong_rate"], 5)
                r["texel_level_error_mean"] = round(t["level_mean"], 4)
            if r["method"] == "ray" and fig:
                r["wall_height_error_max_px"] = round(fig["max_px"], 3)
                r["wall_height_error_mean_px"] = round(fig["mean_px"], 4)
                r["wall_height_error_max_rel"] = round(fig["max_rel"], 4)
                r["wall_height_columns_other_face"] = "%d/%d" % (fig["other_face"], fig["columns"])
    os.makedirs(os.path.join(ROOT, "build", "bench"), exist_ok=True)
    if only is not None:
        base = os.path.join(ROOT, "build", "bench", "results-%s" % a.scene)
        with open(base + ".json", "w") as f:
            json.dump(recs, f, indent=1)
        with open(base + ".md", "w") as f:
            f.write(scene_md(recs))
        print("bench: wrote %s.json and .md (%d records) in %.0f s"
              % (os.path.relpath(base, ROOT), len(recs), time.time() - t0))
        print(scene_md(recs))
        return
    with open(os.path.join(ROOT, "build", "bench", "results.json"), "w") as f:
        json.dump(recs, f, indent=1)
    wire_recs = lines_bench(recs)
    write_md(recs, host, time.time() - t0)
    lines_md(wire_recs)
    print("bench: wrote build/bench/results.json (%d records) and build/bench/results.md in %.0f s"
          % (len(recs), time.time() - t0))
    for r in recs:
        if r["scene"] in ("cube", "torus") and r["cycles_per_frame"]:
            print("  %-8s %-6s %-9s %12s cyc/frame  static %s stack %s flash %s same=%s" % (
                r["target"], r["scene"], r["method"], r["cycles_per_frame"], r["ram_static_bytes"],
                r["stack_peak_bytes"], r["flash_bytes"], r["identical_to_host"]))


if __name__ == "__main__":
    main()
