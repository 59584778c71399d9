"""`make demo`: the emulator streams a demo scene (make demo: the teapot,
Gouraud-shaded in 8-bit grey) through a pty, the viewer reads it over
pyserial and writes PNGs (1:1 and x4) and a GIF, then one summary line.  `--compare` measures bytes per frame and compression with
each codec, with and without dirty bands.

    python -m rast8.demo --emu build/rast8-emu --frames 64 --out build/demo
    python -m rast8.demo --emu build/rast8-emu --frames 64 --compare [--json]
    python -m rast8.demo --emu build/rast8-emu --frames 64 --codecs [--json] [-- --format idx8]
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile

from .capture import Capture
from .protocol import StreamDecoder, read_dump, fb_bytes
from .source import open_source


def run_demo(emu, frames, out, extra, baud=None):
    os.makedirs(out, exist_ok=True)
    ref_path = os.path.join(out, "reference.r8fb")
    cmd = [emu, "--pty", "--frames", str(frames), "--dump", ref_path, "--linger", "20"] + extra
    if baud:
        cmd += ["--baud", str(baud)]
    p = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    path = p.stdout.readline().strip()
    if not path.startswith("/dev/"):
        p.wait()
        print("demo: the emulator did not start: %s" % p.stderr.read().strip(), file=sys.stderr)
        return 1
    # the emulator waits for this open before it streams (pty caveats)
    src = open_source(path, idle=10)
    cap = Capture(src, frames, progress=sys.stderr.isatty())
    images, decoded = [], []

    def on_frame(fr):
        decoded.append(fr)
        fr.to_image().save(os.path.join(out, "frame_%05d.png" % fr.number))
        big = fr.to_image(4)
        big.save(os.path.join(out, "frame_%05d_x4.png" % fr.number))
        images.append(big.convert("P"))

    try:
        cap.run(on_frame)
    finally:
        src.close()         # the emulator lingers until we close
    try:
        p.wait(timeout=30)
    except subprocess.TimeoutExpired:
        p.kill()
    emu_err = p.stderr.read().strip()
    if images:
        images[0].save(os.path.join(out, "demo.gif"), save_all=True,
                       append_images=images[1:], duration=50, loop=0)
    st = cap.stats()
    ref = {f.number: f.pixels for f in read_dump(ref_path)} if os.path.exists(ref_path) else {}
    mismatch = sum(1 for f in decoded if ref.get(f.number) != f.pixels)
    ok = st["frames"] == frames and mismatch == 0 and p.returncode == 0
    print("demo: %d frames, %s bytes/frame (compression %s:1), errors %d, "
          "%d frames differ from the emulator's framebuffer -> %s/demo.gif%s" % (
              st["frames"], st["bytes_per_frame"], st["compression_ratio"], st["errors"],
              mismatch, out, "" if ok else "  [FAILED: emulator: %s]" % (emu_err or p.returncode)))
    return 0 if ok else 1


CONFIGS = [
    ("raw, every band", ["--codec", "raw", "--no-dirty"]),
    ("rle, every band", ["--codec", "rle", "--no-dirty"]),
    ("lz77, every band", ["--codec", "lz77", "--no-dirty"]),
    ("huff, every band", ["--codec", "huff", "--no-dirty"]),
    ("lzw, every band", ["--codec", "lzw", "--no-dirty"]),
    ("best, every band", ["--codec", "best", "--no-dirty"]),
    ("rle + dirty bands", ["--codec", "rle"]),
    ("lz77 + dirty bands", ["--codec", "lz77"]),
    ("best + dirty bands", ["--codec", "best"]),
]
CODECS = ["raw", "rle", "lz77", "huff", "lzw", "best"]


def builtin_scenes(emu):
    """The emulator's built-in scene names (from its --help)."""
    h = subprocess.run([emu, "--help"], capture_output=True, text=True).stdout
    for line in h.splitlines():
        if line.strip().startswith("--scene") and "):" in line:
            return line.split("):", 1)[1].split()
    return ["cube"]


def codec_table(emu, frames, extra, as_json=False):
    """Bytes per frame, every band sent (--no-dirty), for every codec on
    every built-in scene (make stats)."""
    rows = []
    scenes = builtin_scenes(emu)
    with tempfile.TemporaryDirectory() as td:
        path = os.path.join(td, "s.bin")
        for i, scene in enumerate(scenes):
            row = {"scene": scene}
            for c in CODECS:
                if sys.stderr.isatty():
                    print("\rstats: %s %s (%d/%d)   " % (scene, c, i + 1, len(scenes)),
                          end="", file=sys.stderr)
                subprocess.run([emu, "-q", "--frames", str(frames), "--out", path, "--scene", scene,
                                "--codec", c, "--no-dirty"] + extra, check=True)
                data = open(path, "rb").read()
                dec = StreamDecoder()
                got = dec.feed(data)
                if dec.bad_packets + dec.dropped + dec.incomplete or len(got) != frames:
                    print("stats: %s %s: the stream did not decode cleanly" % (scene, c),
                          file=sys.stderr)
                    return 1
                row[c] = round(len(data) / len(got), 1)
            rows.append(row)
    if sys.stderr.isatty():
        print("\r" + " " * 40 + "\r", end="", file=sys.stderr)
    if as_json:
        print(json.dumps(rows, indent=1))
        return 0
    print("bytes/frame, every band sent, %d frames, %s" % (frames, " ".join(extra) or "128x64 page1"))
    print("%-10s" % "scene" + "".join("%9s" % c for c in CODECS))
    for r in rows:
        print("%-10s" % r["scene"] + "".join("%9.1f" % r[c] for c in CODECS))
    return 0


def compare(emu, frames, extra, as_json=False):
    rows = []
    with tempfile.TemporaryDirectory() as td:
        for name, args in CONFIGS:
            path = os.path.join(td, "s.bin")
            subprocess.run([emu, "-q", "--frames", str(frames), "--out", path] + extra + args,
                           check=True)
            data = open(path, "rb").read()
            dec = StreamDecoder()
            got = dec.feed(data)
            raw = sum(len(f.pixels) for f in got)
            rows.append({"config": name, "args": " ".join(args), "frames": len(got),
                         "bytes": len(data),
                         "bytes_per_frame": round(len(data) / max(1, len(got)), 1),
                         "raw_bytes_per_frame": round(raw / max(1, len(got)), 1),
                         "compression_ratio": round(raw / len(data), 2) if data else None,
                         "errors": dec.bad_packets + dec.dropped + dec.incomplete})
    if as_json:
        print(json.dumps(rows, indent=1))
    else:
        print("%d frames, %s (full frame every 32 with dirty bands)" % (frames, " ".join(extra) or "default demo config"))
        print("%-20s %8s %10s %9s %6s" % ("config", "bytes", "B/frame", "ratio", "errors"))
        for r in rows:
            print("%-20s %8d %10.1f %8.2f:1 %6d" % (r["config"], r["bytes"], r["bytes_per_frame"],
                                                   r["compression_ratio"], r["errors"]))
    return 0


def main(argv=None):
    ap = argparse.ArgumentParser(prog="python -m rast8.demo", description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--emu", default="build/rast8-emu")
    ap.add_argument("--frames", type=int, default=64)
    ap.add_argument("--out", default="build/demo")
    ap.add_argument("--baud", type=int, default=None, help="pace the emulator (default unpaced)")
    ap.add_argument("--compare", action="store_true", help="codec / dirty-band table")
    ap.add_argument("--codecs", action="store_true",
                    help="bytes/frame of every codec on every built-in scene")
    ap.add_argument("--json", action="store_true")
    ap.add_argument("emu_args", nargs="*", help="more rast8-emu options (after --)")
    a = ap.parse_args(argv)
    if a.codecs:
        return codec_table(a.emu, a.frames, a.emu_args, a.json)
    if a.compare:
        return compare(a.emu, a.frames, a.emu_args, a.json)
    return run_demo(a.emu, a.frames, a.out, a.emu_args, a.baud)


if __name__ == "__main__":
    sys.exit(main())
