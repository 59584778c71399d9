"""bench/chart.py - speed against accuracy (issue 6): `make chart`.

For each scene, every visibility method (cull, painter's, z-buffer 8/16
bits, 4x4 block naive/masked, S-buffer) and shading (flat, Lambert,
Gouraud) at its cost per frame against its error, Pareto front marked;
plus cost per frame against face count (24 to 2,000 triangles) per
method.  Writes build/chart/speed-accuracy.png and speed-accuracy.md
(`make docs` copies them to docs/).

Cost: ATmega1284P render cycles per frame from build/bench/results.json
(make bench measures every method x shading of these scenes) where every
variant of a scene has one; otherwise x86-64
instructions per frame inside r8_render_frame + r8_render_band, counted
by callgrind on build/r8probe (labelled as such: the same C code, a
different CPU; use them to compare methods, not targets).
Error: % of pixels whose shade level differs from the floating-point
reference (IDX8, 128x64, frames rast8.metrics.FRAMES), with depth-order
errors and PSNR in the table.

    python bench/chart.py [--quick] [--out-dir build/chart]
"""
from __future__ import annotations

import argparse
import json
import math
import os
import re
import subprocess
import sys
import tempfile
from concurrent.futures import ThreadPoolExecutor

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
sys.path.insert(0, os.path.join(ROOT, "host"))

from rast8 import metrics as M  # noqa: E402
from rast8 import scene as S  # noqa: E402

PROBE = os.path.join(ROOT, "build", "r8probe")
RESULTS = os.path.join(ROOT, "build", "bench", "results.json")
METHODS = ["cull", "painter", "zbuf8", "zbuf16", "block", "blockmask", "sbuf", "bsp"]
BSP_SCENES = ("cross", "wall")        # the scenes whose meshes carry BSP trees
SWEEP_METHODS = [m for m in METHODS if m != "bsp"]   # the sweep's tori have no tree
SHADINGS = ["flat", "lambert", "gouraud"]
SCENES = ["cube", "torus", "teapot", "cross", "wall"]
COST_FRAMES = 8          # frames 0..7 per callgrind run
SWEEP = [(24, 1, 4, 3), (50, 1, 5, 5), (100, 1, 10, 5), (200, 1, 10, 10),
         (500, 2, 25, 5), (1000, 4, 25, 5), (2000, 4, 50, 5)]   # (tris, objects, seg, sides); at most R8_DEMO_MAXOBJ = 4 objects


def callgrind_instr(args):
    """x86-64 instructions per frame inside the renderer (callgrind)."""
    with tempfile.TemporaryDirectory() as td:
        out = os.path.join(td, "cg.out")
        cmd = ["valgrind", "--tool=callgrind", f"--callgrind-out-file={out}",
               "--toggle-collect=r8_render_frame", "--toggle-collect=r8_render_band",
               PROBE, "--count", str(COST_FRAMES), "--stats"] + args
        r = subprocess.run(cmd, capture_output=True, text=True, check=True)
        with open(out) as f:
            m = re.search(r"^summary:\s+(\d+)", f.read(), re.M)
        dropped = re.search(r"dropped=(\d+)", r.stdout)
        return int(m.group(1)) / COST_FRAMES, int(dropped.group(1)) if dropped else 0


def avr_cycles():
    """{(scene, method, shading): cycles_per_frame} from make bench, AVR only."""
    if not os.path.exists(RESULTS):
        return {}
    with open(RESULTS) as f:
        doc = json.load(f)
    recs = doc if isinstance(doc, list) else doc.get("records", doc.get("results", []))
    out = {}
    for r in recs:
        cyc = r.get("cycles_render_per_frame") or r.get("cycles_per_frame")
        if r.get("target") != "avr1284" or not cyc or r.get("skipped"):
            continue
        out[(r.get("scene"), r.get("method"), str(r.get("shading", "lambert")))] = cyc
    return out


def pareto(points):
    """Indices of points (cost, err) not dominated by another."""
    front = []
    for i, (c, e) in enumerate(points):
        if not any((c2 <= c and e2 <= e) and (c2 < c or e2 < e) for j, (c2, e2) in enumerate(points) if j != i):
            front.append(i)
    return sorted(front, key=lambda i: points[i][0])


def sweep_scene(tris, nobj, seg, sides):
    """nobj triangulated tori of 2*seg*sides triangles each, in a grid."""
    cols = math.ceil(math.sqrt(nobj))
    rows = math.ceil(nobj / cols)
    k = 1.0 / max(cols, rows)
    t = S.torus(R=round(40 * k) or 4, r=round(16 * k) or 2, seg=seg, sides=sides)
    tri = S.Mesh("t", verts=t.verts)
    for colour, (a, b, e, d) in t.faces:
        tri.faces += [(colour, [a, b, e]), (colour, [a, e, d])]
    sc = S.Scene(f"tri{tris}")
    sc.meshes["t"] = tri
    step = 110 * k
    for i in range(nobj):
        cx, cy = i % cols - (cols - 1) / 2, i // cols - (rows - 1) / 2
        sc.objects.append(S.Obj("t", (round(cx * step), round(cy * step * 0.5), 170), (40, 7 * i % 256, 0),
                                (2, 3, 1)))
    return sc


def run(quick, out_dir):
    scenes = SCENES[:2] if quick else SCENES
    shadings = ["lambert"] if quick else SHADINGS
    avr = avr_cycles()
    variants = [(s, m, sh) for s in scenes for m in METHODS for sh in shadings
                if m != "bsp" or s in BSP_SCENES]
    acc, cost = {}, {}

    def one(v):
        s, m, sh = v
        a = M.measure(s, m, sh, "idx8", 128, 64)
        c = callgrind_instr(["--scene", s, "--method", m, "--shading", sh, "--format", "page1"])
        return v, a, c

    with ThreadPoolExecutor(max_workers=2) as ex:
        for v, a, c in ex.map(one, variants):
            acc[v], cost[v] = a, c
            print(f"  {v[0]:8s} {v[1]:9s} {v[2]:8s} instr/frame {c[0]:>12,.0f}  diff {a['pixel_diff_pct']:.3f}%"
                  f"  depth-order {a['depth_order_errors']}", flush=True)

    sweep = {}
    with tempfile.TemporaryDirectory() as td:
        jobs = []
        for tris, nobj, seg, sides in SWEEP:
            blob = os.path.join(td, f"tri{tris}.bin")
            with open(blob, "wb") as f:
                f.write(S.to_blob(sweep_scene(tris, nobj, seg, sides)))
            for m in SWEEP_METHODS:
                jobs.append((tris, m, blob))

        def sw(j):
            tris, m, blob = j
            return j, callgrind_instr(["--blob", blob, "--method", m, "--shading", "lambert",
                                       "--format", "page1"])

        with ThreadPoolExecutor(max_workers=2) as ex:
            for (tris, m, _), c in ex.map(sw, jobs):
                sweep[(tris, m)] = c
                print(f"  sweep {tris:5d} {m:9s} instr/frame {c[0]:>12,.0f} dropped {c[1]}", flush=True)

    # which unit per scene: AVR cycles only if every variant has one
    units = {}
    for s in scenes:
        have = all(v in avr for v in variants if v[0] == s)
        units[s] = ("ATmega1284P render cycles/frame (make bench)" if have
                    else "x86-64 instructions/frame (callgrind, host)")

    def cost_of(v):
        return avr[v] if units[v[0]].startswith("ATmega") else cost[v][0]

    # Each shading is measured against the reference with the same
    # shading, so errors compare within a shading: one front per shading.
    fronts = {}
    for s in scenes:
        for sh in shadings:
            vs = [v for v in variants if v[0] == s and v[2] == sh]
            pts = [(cost_of(v), acc[v]["error_pct"]) for v in vs]
            fronts[(s, sh)] = [vs[i] for i in pareto(pts)]

    write_png(out_dir, scenes, shadings, variants, acc, cost_of, fronts, units, sweep)
    write_md(out_dir, scenes, variants, acc, cost, cost_of, fronts, units, sweep, avr, quick)
    with open(os.path.join(ROOT, "build", "chart.json"), "w") as f:
        json.dump({"variants": [dict(scene=v[0], method=v[1], shading=v[2], cost=cost_of(v),
                                     unit=units[v[0]], host_instructions_per_frame=cost[v][0], **acc[v])
                                for v in variants],
                   "pareto": {f"{s}/{sh}": [v[1] for v in f] for (s, sh), f in fronts.items()},
                   "sweep": [dict(triangles=t, method=m, host_instructions_per_frame=c[0], dropped=c[1])
                             for (t, m), c in sorted(sweep.items())]}, f, indent=1)


COLOURS = {"cull": "#1f77b4", "painter": "#ff7f0e", "zbuf8": "#2ca02c", "zbuf16": "#d62728",
           "block": "#9467bd", "blockmask": "#8c564b", "sbuf": "#e377c2", "bsp": "#17becf"}
MARKERS = {"flat": "s", "lambert": "o", "gouraud": "^"}
LINES = {"flat": ":", "lambert": "--", "gouraud": "-."}


def write_png(out_dir, scenes, shadings, variants, acc, cost_of, fronts, units, sweep):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.lines import Line2D
    n = len(scenes) + 1
    cols = 3
    rows = math.ceil(n / cols)
    fig, axes = plt.subplots(rows, cols, figsize=(6 * cols, 4.6 * rows))
    axes = axes.flatten()
    for ax, s in zip(axes, scenes):
        for v in variants:
            if v[0] != s:
                continue
            ax.scatter(cost_of(v), acc[v]["error_pct"], c=COLOURS[v[1]], marker=MARKERS[v[2]], s=36,
                       edgecolors="k" if v in fronts[(s, v[2])] else "none", linewidths=1.2, zorder=3)
        for sh in shadings:
            fx = [cost_of(v) for v in fronts[(s, sh)]]
            fy = [acc[v]["error_pct"] for v in fronts[(s, sh)]]
            ax.step(fx, fy, where="post", color="k", lw=0.8, ls=LINES[sh], zorder=2)
        ax.set_title(f"{s}: cost vs error (128x64)")
        ax.set_xlabel(units[s])
        ax.set_ylabel("pixels wrong vs float reference (%)")
        ax.grid(alpha=0.3)
    ax = axes[len(scenes)]
    tris = sorted({t for t, _ in sweep})
    for m in SWEEP_METHODS:
        ax.plot(tris, [sweep[(t, m)][0] for t in tris], marker="o", ms=3, color=COLOURS[m], label=m)
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_title("cost vs triangle count (tori, Lambert, page1 128x64)")
    ax.set_xlabel("triangles in the scene")
    ax.set_ylabel("x86-64 instructions/frame (callgrind, host)")
    ax.grid(alpha=0.3, which="both")
    ax.legend(fontsize=7)
    for a in axes[n:]:
        a.axis("off")
    handles = [Line2D([], [], color=COLOURS[m], marker="o", ls="", label=m) for m in METHODS]
    handles += [Line2D([], [], color="grey", marker=MARKERS[s], ls="", label=s) for s in shadings]
    handles += [Line2D([], [], color="k", ls=LINES[s], label=f"Pareto front, {s}") for s in shadings]
    fig.legend(handles=handles, loc="lower center", ncol=len(handles), fontsize=8)
    fig.tight_layout(rect=(0, 0.04, 1, 1))
    fig.savefig(os.path.join(out_dir, "speed-accuracy.png"), dpi=90)


def write_md(out_dir, scenes, variants, acc, cost, cost_of, fronts, units, sweep, avr, quick):
    L = ["# Speed against accuracy", "",
         "Generated by `make chart` (bench/chart.py); do not edit.  Picture: "
         "[speed-accuracy.png](speed-accuracy.png).  Definitions: [accuracy.md](accuracy.md).", "",
         "- **Error** (chart axis): % of pixels whose shade level (IDX8, 128x64) differs from the "
         "floating-point reference (host/rast8/reference.py) or that show a hidden surface (a wrong "
         "face of the same shade counts too), over frames " + ", ".join(map(str, M.FRAMES)) + "; "
         "pixel diff = value differs only; "
         "coverage = background on one side only; depth order = pixels showing a surface that is "
         "really hidden there (total over the frames); PSNR with peak 16 levels (100 = identical).",
         "- **Cost**: " + ("AVR cycles per frame from `make bench` where every variant of a scene has one, else "
                           if avr else "no AVR figures were available (`build/bench/results.json` missing or "
                           "without AVR records), so ") +
         "x86-64 instructions per frame inside `r8_render_frame` + `r8_render_band`, counted by callgrind "
         f"on build/r8probe over {COST_FRAMES} frames (page1, 128x64, band 8).  Host instructions rank "
         "the methods; they are not AVR cycles.",
         "- Each shading is compared with the reference rendered with the same shading, so errors "
         "compare within a shading: the Pareto front (Pareto column, outlined points) is drawn per shading.",
         "- Subpixel bits are not a setting: `R8_SUB` is fixed at 4 in include/r8fixed.h (12.4 in "
         "r8_svert's 16 bits, guard band sized for it), so the precision settings charted are z bits "
         "(zbuf8/zbuf16), block variants (block = the seed's one compare per 4x4 block, blockmask = with "
         "a coverage mask) and shading.", ""]
    if quick:
        L += ["(quick run: cube and torus, Lambert only)", ""]
    for s in scenes:
        L += [f"## {s}", "", f"Cost unit: {units[s]}.", "",
              "| method | shading | cost/frame | error % | pixel diff % | coverage % | shade % | depth-order px | "
              "max vertex err (subpx) | PSNR dB | Pareto |",
              "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|:-:|"]
        for v in sorted((v for v in variants if v[0] == s), key=cost_of):
            a = acc[v]
            L.append(f"| {v[1]} | {v[2]} | {cost_of(v):,.0f} | {a['error_pct']:.3f} | {a['pixel_diff_pct']:.3f} | "
                     f"{a['coverage_diff_pct']:.3f} | {a['shade_diff_pct']:.3f} | {a['depth_order_errors']} | "
                     f"{a['vertex_error_subpx_max']:.2f} | {a['psnr_db']:.1f} | {'**yes**' if v in fronts[(s, v[2])] else ''} |")
        L.append("")
        for sh in sorted({v[2] for v in variants}, key=SHADINGS.index):
            L.append(f"- Pareto front, {sh} (cheapest first): " +
                     "; ".join(f"{v[1]} ({cost_of(v):,.0f}, {acc[v]['error_pct']:.3f}%)"
                               for v in fronts[(s, sh)]))
        L.append("")
    tris = sorted({t for t, _ in sweep})
    L += ["## Cost against triangle count", "",
          "Triangulated tori (several objects above 255 vertices), Lambert, page1 128x64; "
          "x86-64 instructions per frame (callgrind).  `dropped` = spans or faces the fixed pools could "
          "not hold (S-buffer nodes, clip vertices).", "",
          "| triangles | " + " | ".join(SWEEP_METHODS) + " |", "|---:|" + "---:|" * len(SWEEP_METHODS)]
    for t in tris:
        L.append(f"| {t} | " + " | ".join(
            f"{sweep[(t, m)][0]:,.0f}" + (f" (dropped {sweep[(t, m)][1]})" if sweep[(t, m)][1] else "")
            for m in SWEEP_METHODS) + " |")
    L.append("")
    with open(os.path.join(out_dir, "speed-accuracy.md"), "w") as f:
        f.write("\n".join(L))


# ---- texture mapping (issue 13): affine, subdivided, bilinear on the crate

TEXTURE_MODES = [("affine", 0, "nearest"), ("subdiv 16", 16, "nearest"),
                 ("subdiv 8", 8, "nearest"), ("subdiv 4", 4, "nearest"),
                 ("subdiv 2", 2, "nearest"), ("bilinear", 0, "bilinear"),
                 ("subdiv 8 + bilinear", 8, "bilinear")]


def texture_errors(out_dir, frames=M.FRAMES, scene="crate"):
    """Error of each texture mode against the float reference sampling
    at pixel centres (exact perspective, the same filter), IDX8 128x64:
    mean |level difference| over the pixels either draws, the share of
    those that differ at all and by more than 2 of 16 levels; cost in
    x86-64 instructions per frame (callgrind on r8probe).  Writes
    texture.json and texture.md into out_dir; returns the rows."""
    import numpy as np
    from rast8 import reference as R
    sc = S.builtin(scene)
    rows = []
    for name, persp, filt in TEXTURE_MODES:
        args = ["--scene", scene, "--shading", "texture", "--persp", str(persp),
                "--texfilter", filt, "--format", "idx8"]
        absum = n = diff = big = 0
        worst = 0.0
        with tempfile.TemporaryDirectory() as td:
            for fr in frames:
                raw = os.path.join(td, "f.raw")
                subprocess.run([PROBE] + args + ["--frame", str(fr), "--raw", raw], check=True,
                               capture_output=True)
                with open(raw, "rb") as f:
                    c = R.unpack(f.read(), "idx8", 128, 64)
                ref = R.render(sc, fr, 128, 64, "texture", filt)
                drawn = (c > 0) | (ref.fid >= 0)
                d = np.abs(c - ref.level)[drawn]
                absum += int(d.sum())
                n += int(drawn.sum())
                diff += int((d > 0).sum())
                big += int((d > 2).sum())
                worst = max(worst, float(d.mean()) if d.size else 0.0)
        instr, _ = callgrind_instr(args)
        rows.append(dict(mode=name, persp=persp, texfilter=filt, mean_abs_level_err=round(absum / n, 4),
                         worst_frame_mean_err=round(worst, 4), pixels_differ_pct=round(100.0 * diff / n, 3),
                         pixels_off_by_3plus_pct=round(100.0 * big / n, 3), x86_instr_per_frame=int(instr),
                         frames=list(frames), pixels=n))
        print(f"texture: {name}: mean |err| {absum / n:.3f} levels, {100.0 * diff / n:.2f} % px differ, "
              f"{100.0 * big / n:.2f} % off by > 2, {instr / 1e6:.2f} M instr/frame", flush=True)
    with open(os.path.join(out_dir, "texture.json"), "w") as f:
        json.dump({"scene": scene, "rows": rows}, f, indent=1)
    L = [f"# Texture mapping: speed against accuracy ({scene}, 128x64 IDX8)", "",
         "Generated by `python bench/chart.py --texture` (docs/pipeline.md, Texture mapping).  Error "
         "against the float reference sampling at pixel centres with exact perspective and the same "
         f"filter, over frames {', '.join(map(str, frames))}; cost in x86-64 instructions per frame "
         "inside the renderer (callgrind on build/r8probe).", "",
         "| mode | persp N | filter | mean abs error (levels of 16) | worst frame | px differing | px off by > 2 | x86 instr/frame |",
         "|---|---:|---|---:|---:|---:|---:|---:|"]
    for r in rows:
        L.append(f"| {r['mode']} | {r['persp']} | {r['texfilter']} | {r['mean_abs_level_err']:.3f} | "
                 f"{r['worst_frame_mean_err']:.3f} | {r['pixels_differ_pct']:.2f} % | "
                 f"{r['pixels_off_by_3plus_pct']:.2f} % | {r['x86_instr_per_frame']:,} |")
    with open(os.path.join(out_dir, "texture.md"), "w") as f:
        f.write("\n".join(L) + "\n")
    return rows


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--quick", action="store_true", help="cube and torus, Lambert only")
    ap.add_argument("--texture", action="store_true",
                    help="only the texture-mapping piece (texture.json, texture.md)")
    ap.add_argument("--out-dir", default=os.path.join(ROOT, "build", "chart"))
    a = ap.parse_args()
    for tool in (PROBE,):
        if not os.path.exists(tool):
            print(f"chart: {tool} missing (make build/r8probe)", file=sys.stderr)
            return 1
    os.makedirs(a.out_dir, exist_ok=True)
    if a.texture:
        texture_errors(a.out_dir)
        print(f"chart: wrote {a.out_dir}/texture.json and texture.md")
        return 0
    run(a.quick, a.out_dir)
    texture_errors(a.out_dir)
    print(f"chart: wrote {a.out_dir}/speed-accuracy.png and speed-accuracy.md")
    return 0


if __name__ == "__main__":
    sys.exit(main())
