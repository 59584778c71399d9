#!/usr/bin/env python3
"""kern6502.py - what each 6502 assembly kernel and link step buys: the
cube / cull firmware (128x64 PAGE1, bands of 8, Lambert) rebuilt with
one piece left out at a time, cycles per frame (sim65, 4-frame run minus
2-frame run, over 2) and image size (.prg.size flash).

    python3 bench/kern6502.py [--json FILE]

Rebuilds build/x/6502 for every variant (about half a minute each) and
once more with the defaults at the end.  Prints a markdown table; every
variant's stream must equal the host's (else it says so).  Not part of
`make test`: it measures, it does not assert.
"""
import argparse
import json
import os
import re
import shutil
import subprocess
import sys

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), ".."))
FW = "build/x/6502/fw/fw-0-0-%d.prg"
ALL_DEFS = ["R8_ASM_MUL16", "R8_ASM_TRAP", "R8_ASM_WIRE", "R8_ASM_TXBAND", "R8_ASM_SCANX", "R8_ASM_FILL", "R8_ASM_XFORM", "R8_ASM_PROJECT", "R8_ASM_EDGE"]
ALL_ASM = sorted(f for f in os.listdir(os.path.join(ROOT, "ports", "6502")) if f.endswith(".s"))
VARIANTS = [
    ("all kernels, gc65 (the build)", {}),
    ("without r8k_trap (R8_ASM_TRAP)", {"defs": ["R8_ASM_TRAP"], "asm": ["trap_6502.s"]}),
    ("without r8_tx_band (R8_ASM_TXBAND)", {"defs": ["R8_ASM_TXBAND"], "asm": ["txband_6502.s", "txoffs_6502.s"]}),
    ("without the wire kernels (R8_ASM_WIRE, R8_ASM_TXBAND)",
     {"defs": ["R8_ASM_WIRE", "R8_ASM_TXBAND"], "asm": ["wire_6502.s", "wirec_6502.s", "txband_6502.s", "txoffs_6502.s"]}),
    ("without r8_scanx_fill (R8_ASM_SCANX)", {"defs": ["R8_ASM_SCANX"], "asm": ["scanx_6502.s"]}),
    ("without r8k_fill (R8_ASM_FILL)", {"defs": ["R8_ASM_FILL"], "asm": ["fill_6502.s"]}),
    ("without r8k_xform (R8_ASM_XFORM)", {"defs": ["R8_ASM_XFORM"], "asm": ["xform_6502.s"]}),
    ("without r8k_project (R8_ASM_PROJECT)", {"defs": ["R8_ASM_PROJECT"], "asm": ["proj_6502.s"]}),
    ("without r8k_edge (R8_ASM_EDGE)", {"defs": ["R8_ASM_EDGE"], "asm": ["edge_6502.s"]}),
    ("without r8_mul16 (R8_ASM_MUL16)", {"defs": ["R8_ASM_MUL16"]}),
    ("without the runtime multiplies (rtmul_6502.s)", {"asm": ["rtmul_6502.s"]}),
    ("without gc65 (whole objects linked)", {"gc": False}),
    ("none of it (the C, cc65's runtime, whole objects)",
     {"defs": ALL_DEFS, "asm": ALL_ASM, "gc": False}),
]


def build_and_measure(var):
    defs = " ".join("-D" + d for d in ALL_DEFS if d not in var.get("defs", []))
    asm = " ".join("ports/6502/" + a for a in ALL_ASM if a not in var.get("asm", []))
    env = {k: v for k, v in os.environ.items() if k not in ("MAKEFLAGS", "MFLAGS", "MAKELEVEL")}
    env["C65_GC"] = "1" if var.get("gc", True) else "0"
    shutil.rmtree(os.path.join(ROOT, "build", "x", "6502"), ignore_errors=True)
    cmd = ["make", "-s", "-j2", FW % 2, FW % 4, "build/emu/fw-host",
           "C65_ASMDEF=" + defs, "C65_ASM=" + asm]
    r = subprocess.run(cmd, cwd=ROOT, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT)
    if r.returncode:
        return {"error": r.stdout.decode("latin-1")[-400:]}
    cyc, out = {}, {}
    for f in (2, 4):
        p = os.path.join(ROOT, FW % f)
        if open(p, "rb").read(5) == b"SKIP:":
            return {"error": open(p).read().strip()}
        s = subprocess.run(["sim65", "-c", p], stdout=subprocess.PIPE, timeout=900)
        m = re.search(rb"(\d+) cycles\n$", s.stdout)
        cyc[f] = int(m.group(1))
        out[f] = s.stdout[:m.start()]
    host = subprocess.run([os.path.join(ROOT, "build", "emu", "fw-host"), "0", "0", "4"],
                          stdout=subprocess.PIPE).stdout
    size = dict(kv.split("=") for kv in open(os.path.join(ROOT, FW % 4) + ".size").read().split())
    return {"cycles_per_frame": (cyc[4] - cyc[2]) // 2, "flash_bytes": int(size["flash"]),
            "ram_static_bytes": int(size["ram_static"]), "identical": out[4] == host}


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--json")
    a = ap.parse_args()
    res = []
    try:
        for name, var in VARIANTS:
            sys.stderr.write("kern6502: %s\n" % name)
            r = build_and_measure(var)
            r["variant"] = name
            res.append(r)
    finally:
        build_and_measure({})   # leave the default build behind
    base = res[0].get("cycles_per_frame")
    print("| 6502 cube / cull | cycles/frame | vs the build | flash | RAM static | same |")
    print("|---|---:|---:|---:|---:|---|")
    for r in res:
        if "error" in r:
            print("| %s | - | - | - | - | %s |" % (r["variant"], r["error"].splitlines()[-1][:80]))
            continue
        d = r["cycles_per_frame"] - base if base else 0
        print("| %s | {:,} | {:+,} | {:,} | {:,} | %s |".format(
            r["cycles_per_frame"], d, r["flash_bytes"], r["ram_static_bytes"]) %
              (r["variant"], "yes" if r["identical"] else "**NO**"))
    if a.json:
        with open(a.json, "w") as f:
            json.dump(res, f, indent=1)
    return 0 if all(r.get("identical") for r in res if "error" not in r) else 1


if __name__ == "__main__":
    sys.exit(main())
