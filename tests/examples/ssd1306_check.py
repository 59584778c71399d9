#!/usr/bin/env python3
"""ssd1306_check.py [--frames F] [--step S] - the SSD1306 example in simavr
with simavr's own SSD1306 part (emu/ssd1306sim.c, libsimavrparts).

The ATmega328P firmware (build/x/avr328/oled/oled-F.elf, frames 0, S,
2S, ...) drives the display over SPI; after every frame the runner reads
the part's display RAM.  Checks:
  * every frame's display RAM equals the host build of the same example
    (build/examples/ssd1306) and `r8dump --scene cube --frame n`, byte
    for byte; frames are not blank and the cube moves;
  * the panel was set up: display on, not inverted, page addressing;
  * the firmware fits the 328P: flash <= 32 KB, static RAM + stack peak
    <= 2048 bytes; its arena is exactly oled_cube_ram() on AVR (one byte
    less and it draws nothing, exit 2);
  * the Arduino sketch (examples/ssd1306/ssd1306.ino from the
    `make arduino` zip, built against tests/arduino/core like
    tests/arduino/check.py does) draws the same frames in the part, and
    its OLED_RAM is exact too.
Ends with "N passed, N failed".
"""
import argparse
import os
import re
import subprocess
import sys
import tempfile
import zipfile

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
sys.path.insert(0, os.path.join(ROOT, "tests", "targets"))
sys.path.insert(0, os.path.join(ROOT, "tests", "arduino"))
import identity  # noqa: E402  (make)

SIM = os.path.join(ROOT, "build", "emu", "ssd1306sim")
HOST = os.path.join(ROOT, "build", "examples", "ssd1306")
R8DUMP = os.path.join(ROOT, "build", "r8dump")
X = os.path.join("build", "x", "avr328", "oled")
FRAME = 1024
RAM_MAX, FLASH_MAX = 2048, 32768

passed = failed = 0


def check(ok, msg):
    global passed, failed
    print("%s %s" % ("PASS" if ok else "FAIL", msg))
    if ok:
        passed += 1
    else:
        failed += 1
    return ok


def simulate(elf, tmp, name, limit=None):
    """Runs elf with the SSD1306 part: (frames bytes, end RAM, log, exit)."""
    out, end, log = (os.path.join(tmp, name + x) for x in (".frames", ".end", ".log"))
    cmd = [SIM, "-o", out, "-E", end, "-m", log]
    if limit:
        cmd += ["-l", str(limit)]
    r = subprocess.run(cmd + ["atmega328p", elf], stdout=subprocess.PIPE,
                       stderr=subprocess.STDOUT, timeout=600)
    read = lambda p: open(p, "rb").read() if os.path.exists(p) else b""
    return read(out), read(end), read(log).decode("latin-1"), r.returncode


def r8dump(n):
    with tempfile.NamedTemporaryFile() as f:
        subprocess.run([R8DUMP, "--scene", "cube", "--frame", str(n), "--raw", f.name],
                       stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=True)
        return open(f.name, "rb").read()


def field(log, key):
    m = re.search(r"\b%s=(\w+)" % key, log)
    return m.group(1) if m else None


def lit(frame):
    return sum(bin(b).count("1") for b in frame)


def sketch_checks(zpath, frames, step, tmp):
    """The Arduino sketch built against the stub core, run in the part."""
    import check as ard
    with zipfile.ZipFile(zpath) as z:
        z.extractall(tmp)
    lib = os.path.join(tmp, "rast8")
    sk = os.path.join(lib, "examples", "ssd1306")
    if not check(os.path.isfile(os.path.join(sk, "ssd1306.ino")),
                 "sketch: examples/ssd1306/ssd1306.ino in %s" % os.path.relpath(zpath, ROOT)):
        return
    libarch = ard.build_library(lib, os.path.join(tmp, "lib"))
    core = ard.build_core(ard.STUB, None, os.path.join(tmp, "core"), True)
    if not check(libarch and core, "sketch: the library and the stub core build for the 328P"):
        return
    m = re.search(r"#define OLED_RAM (\d+)", open(os.path.join(sk, "ssd1306.ino")).read())
    if not check(m is not None, "sketch: ssd1306.ino has #define OLED_RAM N"):
        return
    ram = int(m.group(1))
    n = 3    # frames the sketch draws, then loop() idles until the cycle limit
    for arena, want in ((ram, r8dump(n - 1)), (ram - 1, bytes(FRAME))):
        elf = ard.build_sketch(sk, "ssd1306", lib, [ard.STUB], core, libarch,
                               os.path.join(tmp, "sk%d" % arena),
                               ["-DOLED_FRAMES=%d" % n, "-DOLED_RAM=%d" % arena], True)
        if not check(elf is not None, "sketch: builds with OLED_RAM=%d" % arena):
            continue
        _, end, log, rc = simulate(elf, tmp, "sk%d" % arena, limit=30000000)
        what = ("draws frame %d of the cube (r8dump's)" % (n - 1) if arena == ram else
                "one byte under oled_cube_ram(): draws nothing")
        check(end == want and field(log, "on") == "1",
              "sketch with OLED_RAM=%d %s: display RAM %s, display on=%s"
              % (arena, what, "as expected" if end == want else "differs (%d lit pixels)" % lit(end),
                 field(log, "on")))
        if arena == ram:
            st, pk = int(field(log, "static") or 0), int(field(log, "stack_peak") or 0)
            check(st + pk <= RAM_MAX, "sketch: static RAM %d + stack peak %d = %d of %d bytes"
                  % (st, pk, st + pk, RAM_MAX))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--frames", type=int, default=16)
    ap.add_argument("--step", type=int, default=5)
    ap.add_argument("--zip", default=None, help="the make arduino zip (default build/arduino/rast8-*.zip)")
    a = ap.parse_args()
    os.chdir(ROOT)
    fw, small = os.path.join(X, "oled-%d.elf" % a.frames), os.path.join(X, "oled-small.elf")
    identity.make(["build/emu/ssd1306sim", "build/examples/ssd1306", "build/r8dump", fw, small])
    for p in (SIM, HOST, R8DUMP, fw, small):
        if not os.path.exists(p):
            check(False, "%s not built (make output above)" % os.path.relpath(p, ROOT))
            print("%d passed, %d failed" % (passed, failed))
            return 1
    if identity.is_skip(fw):
        check(False, "the firmware does not fit the ATmega328P: %s" % identity.is_skip(fw))
        print("%d passed, %d failed" % (passed, failed))
        return 1
    with tempfile.TemporaryDirectory() as tmp:
        got, end, log, rc = simulate(fw, tmp, "fw")
        host = subprocess.run([HOST, str(a.frames), str(a.step)], stdout=subprocess.PIPE,
                              timeout=120).stdout
        nums = [i * a.step for i in range(a.frames)]
        ref = b"".join(r8dump(n) for n in nums)
        check(rc == 0 and field(log, "frames") == str(a.frames) and len(got) == a.frames * FRAME,
              "firmware: %s frames in simavr's SSD1306, exit %d" % (field(log, "frames"), rc))
        same_host = same_dump = 0
        for i, n in enumerate(nums):
            g = got[i * FRAME:(i + 1) * FRAME]
            same_host += g == host[i * FRAME:(i + 1) * FRAME]
            same_dump += g == ref[i * FRAME:(i + 1) * FRAME]
        check(same_host == a.frames and len(host) == len(got),
              "display RAM = host build (build/examples/ssd1306 %d %d): %d of %d frames identical"
              % (a.frames, a.step, same_host, a.frames))
        check(same_dump == a.frames, "display RAM = r8dump --scene cube --frame n (n = %s): "
              "%d of %d frames identical" % (",".join(map(str, nums)), same_dump, a.frames))
        frames = [got[i * FRAME:(i + 1) * FRAME] for i in range(a.frames)]
        check(all(lit(f) > 500 for f in frames) and len(set(frames)) == a.frames,
              "frames are drawn (lit pixels %d..%d) and all differ (the cube turns)"
              % (min(map(lit, frames) or [0]), max(map(lit, frames) or [0])))
        check(field(log, "on") == "1" and field(log, "inverted") == "0" and field(log, "mode") == "page",
              "panel set up: display on=%s inverted=%s mode=%s contrast=%s"
              % (field(log, "on"), field(log, "inverted"), field(log, "mode"), field(log, "contrast")))
        size = dict(kv.split("=") for kv in open(fw + ".size").read().split())
        st, pk = int(field(log, "static") or 0), int(field(log, "stack_peak") or 0)
        arena = open(os.path.join(X, "ram.txt")).read().strip()
        comp = [int(c) for c in re.findall(r"compute=(\d+)", log)]
        check(int(size["flash"]) <= FLASH_MAX and st + pk <= RAM_MAX,
              "ATmega328P: flash %s B, static RAM %d B (arena %s B) + stack peak %d B = %d of %d B; "
              "%d..%d cycles a frame rendering (simavr's SPI model adds 1608 a byte)"
              % (size["flash"], st, arena, pk, st + pk, RAM_MAX, min(comp or [0]), max(comp or [0])))
        _, end, log2, rc2 = simulate(small, tmp, "small")
        check(rc2 == 2 and field(log2, "frames") == "0" and end == bytes(FRAME),
              "arena one byte under oled_cube_ram() (%d B): exit %d, %s frames, display RAM %s"
              % (int(arena) - 1, rc2, field(log2, "frames"), "blank" if end == bytes(FRAME) else "written"))
        zpath = a.zip
        if not zpath:
            d = os.path.join(ROOT, "build", "arduino")
            zips = sorted(f for f in os.listdir(d) if f.endswith(".zip")) if os.path.isdir(d) else []
            zpath = os.path.join(d, zips[-1]) if zips else None
        if check(zpath is not None and os.path.exists(zpath), "the make arduino zip is there"):
            sketch_checks(zpath, a.frames, a.step, tmp)
    print("%d passed, %d failed" % (passed, failed))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
