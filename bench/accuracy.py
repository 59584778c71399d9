"""bench/accuracy.py - add accuracy to the benchmark records (issue 6).

Reads build/bench/results.json (written by `make bench`, bench/bench.py),
and adds to every record, computed from build/r8probe frames against the
floating-point reference (host/rast8/reference.py) over a fixed set of
frames (rast8.metrics.FRAMES), in the record's own format and size:

    pixel_diff_pct          % of pixels whose value differs
    coverage_diff_pct       % background on one side, a face on the other
    shade_diff_pct          % same face, different value
    depth_order_errors      pixels showing a surface that is really hidden
                            there (total over the frames)
    vertex_error_subpx_max  largest C-vs-float projection error, subpixels
    psnr_db                 PSNR (peak 16 levels, or 1 for 1 bpp; 100 = equal)
    pixels_wrong, pixels_lit_c, pixels_lit_ref, pixels_total   (1 bpp)
    accuracy_frames, accuracy_format, accuracy_shading

The same bytes come out of every target (DEVELOPERS.md), so a record's
accuracy depends on scene, method, shading, cull, format and size only;
those are computed once and shared.  Writes the file back in place.

    python bench/accuracy.py [RESULTS_JSON]
"""
from __future__ import annotations

import json
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
sys.path.insert(0, os.path.join(ROOT, "host"))

from rast8 import metrics as M  # noqa: E402

FORMATS = {0: "page1", 1: "row1", 2: "idx8"}
SHADINGS = {0: "flat", 1: "lambert", 2: "gouraud"}


def _records(doc):
    if isinstance(doc, list):
        return doc
    if isinstance(doc, dict):
        for k in ("records", "results"):
            if isinstance(doc.get(k), list):
                return doc[k]
    raise ValueError("results.json: expected a list of records or {'records': [...]}")


def config_of(rec):
    fmt = rec.get("format", "page1")
    fmt = FORMATS.get(fmt, fmt) if isinstance(fmt, int) else str(fmt).lower()
    sh = rec.get("shading", "lambert")
    sh = SHADINGS.get(sh, sh) if isinstance(sh, int) else str(sh).lower()
    return (str(rec["scene"]), str(rec["method"]), sh, str(rec.get("cull", "normal")), fmt,
            int(rec.get("width", 128)), int(rec.get("height", 64)))


def accuracy_for(cfg, cache):
    if cfg not in cache:
        scene, method, sh, cull, fmt, w, h = cfg
        cache[cfg] = M.measure(scene, method, sh, fmt, w, h, cull=cull, band=8)
    return cache[cfg]


def annotate(path):
    with open(path) as f:
        doc = json.load(f)
    recs = _records(doc)
    cache = {}
    done = 0
    for rec in recs:
        if "scene" not in rec or "method" not in rec or rec.get("method") == "auto":
            continue
        try:
            acc = accuracy_for(config_of(rec), cache)
        except Exception as e:          # an unknown scene/method: say so, keep going
            rec["accuracy_error"] = str(e)[:200]
            continue
        rec.update(acc)
        done += 1
    tmp = path + ".tmp"
    with open(tmp, "w") as f:
        json.dump(doc, f, indent=1)
        f.write("\n")
    os.replace(tmp, path)
    print(f"accuracy: {done} of {len(recs)} records, {len(cache)} configurations -> {path}")
    return doc


def main(argv):
    path = argv[1] if len(argv) > 1 else os.path.join(ROOT, "build", "bench", "results.json")
    if not os.path.exists(path):
        print(f"accuracy: {path} not found (run make bench first)", file=sys.stderr)
        return 1
    if not os.path.exists(M.PROBE):
        print(f"accuracy: {M.PROBE} missing (make build/r8probe)", file=sys.stderr)
        return 1
    annotate(path)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
