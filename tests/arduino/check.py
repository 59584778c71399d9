#!/usr/bin/env python3
"""check.py ZIP - checks the Arduino library zip that `make arduino` writes.

Layout (Arduino library specification 1.5, rev. 2.2):
  * one top folder holding library.properties, LICENSE and src/;
  * library.properties: every required field, valid name, version,
    category and architectures; `includes` headers exist in src/;
  * src/ holds the library: every src/*.c, src/*.h and include/*.h of
    this checkout, byte for byte;
  * every examples/NAME/ holds NAME.ino (sketch specification).
Sketches: each one is compiled and linked for an ATmega328P (Uno) with
avr-gcc against tests/arduino/core (a minimal core: Arduino.h and a
polled Serial), and against a real Arduino AVR core as well when one is
installed (ARDUINO_CORE=DIR, or the Debian arduino-core-avr path); the
library is linked as an archive, as dot_a_linkage asks.  The image must
fit the Uno (32256 bytes of flash under the bootloader, 2048 of RAM).
Sketches with a RUNS entry below are also run in libsimavr
(build/emu/avrsim): their Serial bytes must equal build/rast8-emu's
stream for the same configuration, byte for byte, and static RAM + stack
peak must stay within the 2048 bytes.  With the stub core the sketch is
also built with its arena one byte smaller than its #define NAME_RAM:
it must then stream nothing (app_run refuses), so the arena is exactly
app_ram() on AVR.

Prints one line per failure and ends with "N passed, N failed".
Exit 0 when all passed, 1 on a failed check, 2 on bad usage.
"""
import os
import re
import shutil
import subprocess
import sys
import tempfile
import zipfile

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
STUB = os.path.join(ROOT, "tests", "arduino", "core")
AVRSIM = os.path.join(ROOT, "build", "emu", "avrsim")
EMU = os.path.join(ROOT, "build", "rast8-emu")
REAL_CORES = ["/usr/share/arduino/hardware/arduino/avr"]

MCU = "atmega328p"
FLASH_MAX = 32256       # Uno: 32 KB minus the 512-byte Optiboot bootloader
RAM_MAX = 2048
REQUIRED = ["name", "version", "author", "maintainer", "sentence", "paragraph",
            "category", "url", "architectures"]
CATEGORIES = ["Display", "Communication", "Signal Input/Output", "Sensors",
              "Device Control", "Timing", "Data Storage", "Data Processing", "Other"]
# sketch -> (compile-time defines for the run, the same stream from
# build/rast8-emu: its options, the sketch's arena macro)
RUNS = {"spin": (["-DSPIN_FRAMES=4"],
                 ["--scene", "cube", "--method", "cull", "--frames", "4", "--width", "128"],
                 "SPIN_RAM")}
CYCLES = 60000000

DEFS = ["-mmcu=" + MCU, "-DF_CPU=16000000L", "-DARDUINO=10819", "-DARDUINO_AVR_UNO",
        "-DARDUINO_ARCH_AVR"]
CFLAGS = DEFS + ["-Os", "-std=gnu11", "-ffunction-sections", "-fdata-sections"]
CXXFLAGS = DEFS + ["-Os", "-std=gnu++11", "-fno-exceptions", "-fno-threadsafe-statics",
                   "-ffunction-sections", "-fdata-sections"]

passed = 0
failed = 0


def check(ok, what):
    global passed, failed
    if ok:
        passed += 1
    else:
        failed += 1
        print("FAIL: " + what)
    return ok


def parse_properties(text):
    props = {}
    for line in text.splitlines():
        line = line.strip()
        if not line or line.startswith("#"):
            continue
        if "=" not in line:
            return None, "not key=value: %r" % line
        k, v = line.split("=", 1)
        props[k.strip()] = v.strip()
    return props, None


def properties_problems(props, src_names):
    """Spec violations of a parsed library.properties, as strings."""
    bad = []
    for k in REQUIRED:
        if not props.get(k):
            bad.append("missing or empty field %s" % k)
    name = props.get("name", "")
    if name and not (re.match(r"^[A-Za-z0-9][A-Za-z0-9 _.\-]*$", name) and re.search("[A-Za-z]", name)):
        bad.append("invalid name %r" % name)
    ver = props.get("version", "")
    if ver and not re.match(r"^\d+\.\d+(\.\d+)?(-[0-9A-Za-z.\-]+)?(\+[0-9A-Za-z.\-]+)?$", ver):
        bad.append("version %r is not semver" % ver)
    if props.get("category") and props["category"] not in CATEGORIES:
        bad.append("unknown category %r" % props["category"])
    arch = props.get("architectures", "")
    if arch and not all(re.match(r"^(\*|[a-z0-9_]+)$", a.strip()) for a in arch.split(",")):
        bad.append("bad architectures %r" % arch)
    if props.get("dot_a_linkage", "true") not in ("true", "false"):
        bad.append("dot_a_linkage must be true or false")
    for h in filter(None, (x.strip() for x in props.get("includes", "").split(","))):
        if h not in src_names:
            bad.append("includes names %s, not in src/" % h)
    return bad


def check_layout(z):
    names = [n for n in z.namelist() if not n.endswith("/")]
    tops = sorted(set(n.split("/")[0] for n in z.namelist()))
    if not check(len(tops) == 1, "the zip must hold one top folder, has %s" % tops):
        return None
    top = tops[0]
    check(re.match(r"^[A-Za-z0-9][A-Za-z0-9_.\-]{0,62}$", top) is not None,
          "library folder name %r is not valid" % top)
    files = {n[len(top) + 1:]: n for n in names}
    for f in ("library.properties", "LICENSE"):
        check(f in files, "%s/%s missing" % (top, f))
    src_names = {f[4:] for f in files if f.startswith("src/") and "/" not in f[4:]}
    props, err = (None, "missing")
    if "library.properties" in files:
        props, err = parse_properties(z.read(files["library.properties"]).decode("utf-8"))
    if check(props is not None, "library.properties: %s" % err):
        bad = properties_problems(props, src_names)
        check(not bad, "library.properties: " + "; ".join(bad))
        check(props.get("name") == top, "library.properties name %r != folder %r" % (props.get("name"), top))
    # src/: the library, byte for byte
    want = {}
    for d, exts in (("src", (".c", ".h")), ("include", (".h",))):
        for f in sorted(os.listdir(os.path.join(ROOT, d))):
            if f.endswith(exts):
                want[f] = os.path.join(ROOT, d, f)
    missing = [f for f in want if f not in src_names]
    def expected(f):
        data = open(want[f], "rb").read()
        if f == "r8config.h":   # make arduino turns the Arduino preset on
            data = data.replace(b"#define R8CONFIG_H\n", b"#define R8CONFIG_H\n#define R8_ARDUINO_PRESET\n", 1)
        return data
    differ = [f for f in want if f in src_names and z.read(files["src/" + f]) != expected(f)]
    check(src_names and not missing and not differ,
          "src/: missing %s, different %s" % (missing or "-", differ or "-"))
    check(not [f for f in files if f.endswith((".c", ".cpp", ".h")) and
               not f.startswith(("src/", "examples/"))],
          "sources outside src/ and examples/")
    # examples/NAME/NAME.ino
    sketches = sorted(set(f.split("/")[1] for f in files if f.startswith("examples/")))
    check(sketches, "no examples/ sketches")
    for s in sketches:
        check(re.match(r"^[A-Za-z0-9_][A-Za-z0-9_.\-]{0,62}$", s) is not None,
              "examples/%s: invalid sketch folder name" % s)
        check("examples/%s/%s.ino" % (s, s) in files, "examples/%s/ has no %s.ino" % (s, s))
    return top, sketches


def run(cmd, cwd=None):
    r = subprocess.run(cmd, cwd=cwd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT)
    return r.returncode, r.stdout.decode("latin-1")


def compile_all(jobs, what):
    """jobs: [(cmd, cwd)]; returns True or prints the first failure."""
    for cmd, cwd in jobs:
        rc, out = run(cmd, cwd)
        if rc:
            print("FAIL: %s: %s\n%s" % (what, " ".join(cmd), out.strip()[-2000:]))
            return False
    return True


def build_core(core, variant, out, strict):
    """Compiles a core's .c/.cpp (and variant) into out/core.a."""
    os.makedirs(out, exist_ok=True)
    inc = ["-I" + core] + (["-I" + variant] if variant else [])
    warn = ["-Wall", "-Wextra", "-Werror"] if strict else ["-w"]
    if not strict:
        # Debian's arduino-core-avr 1.8.7 uses DECIMAL_DIG in WString.cpp,
        # which avr-gcc 5.4's <float.h> defines for C99 but not for C++11
        warn.append("-DDECIMAL_DIG=__DECIMAL_DIG__")
    jobs, objs = [], []
    for f in sorted(os.listdir(core)):
        src = os.path.join(core, f)
        o = os.path.join(out, f + ".o")
        if f.endswith(".c"):
            jobs.append((["avr-gcc"] + CFLAGS + warn + inc + ["-c", src, "-o", o], None))
        elif f.endswith(".cpp"):
            jobs.append((["avr-g++"] + CXXFLAGS + warn + inc + ["-c", src, "-o", o], None))
        elif f.endswith(".S"):
            jobs.append((["avr-gcc", "-x", "assembler-with-cpp"] + DEFS + inc + ["-c", src, "-o", o], None))
        else:
            continue
        objs.append(o)
    if not compile_all(jobs, "core " + core):
        return None
    lib = os.path.join(out, "core.a")
    rc, txt = run(["avr-ar", "rcs", lib] + objs)
    return lib if rc == 0 else None


def build_library(lib_dir, out):
    os.makedirs(out, exist_ok=True)
    src = os.path.join(lib_dir, "src")
    jobs, objs = [], []
    for f in sorted(os.listdir(src)):
        if f.endswith(".c"):
            o = os.path.join(out, f + ".o")
            jobs.append((["avr-gcc"] + CFLAGS + ["-Wall", "-Wextra", "-Werror", "-I" + src,
                                                  "-c", os.path.join(src, f), "-o", o], None))
            objs.append(o)
    if not compile_all(jobs, "library"):
        return None
    a = os.path.join(out, "librast8.a")
    rc, txt = run(["avr-ar", "rcs", a] + objs)
    return a if rc == 0 else None


def build_sketch(sk_dir, name, lib_dir, core_inc, core_a, libarch, out, defines, strict):
    """The Arduino build of one sketch: the .ino files joined after
    #include <Arduino.h>, the folder's .c/.cpp, then the library archive
    and the core.  Returns the ELF path or None."""
    os.makedirs(out, exist_ok=True)
    inos = [name + ".ino"] + sorted(f for f in os.listdir(sk_dir)
                                    if f.endswith(".ino") and f != name + ".ino")
    cpp = os.path.join(out, name + ".ino.cpp")
    with open(cpp, "w") as f:
        f.write("#include <Arduino.h>\n")
        for i in inos:
            f.write('#line 1 "%s"\n' % i)
            f.write(open(os.path.join(sk_dir, i)).read())
            f.write("\n")
    inc = ["-I" + d for d in core_inc] + ["-I" + os.path.join(lib_dir, "src"), "-I" + sk_dir]
    warn = ["-Wall", "-Wextra", "-Werror"] if strict else ["-Wall"]
    jobs = [(["avr-g++"] + CXXFLAGS + warn + inc + defines + ["-c", cpp, "-o", cpp + ".o"], None)]
    objs = [cpp + ".o"]
    for f in sorted(os.listdir(sk_dir)):
        o = os.path.join(out, f + ".o")
        if f.endswith(".c"):
            jobs.append((["avr-gcc"] + CFLAGS + warn + inc + defines +
                         ["-c", os.path.join(sk_dir, f), "-o", o], None))
        elif f.endswith(".cpp"):
            jobs.append((["avr-g++"] + CXXFLAGS + warn + inc + defines +
                         ["-c", os.path.join(sk_dir, f), "-o", o], None))
        else:
            continue
        objs.append(o)
    if not compile_all(jobs, "sketch " + name):
        return None
    elf = os.path.join(out, name + ".elf")
    if not compile_all([(["avr-gcc", "-mmcu=" + MCU, "-Os", "-Wl,--gc-sections", "-o", elf] + objs +
                         [libarch, core_a, "-lm"], None)], "link " + name):
        return None
    return elf


def sizes(elf):
    rc, out = run(["avr-size", "-A", elf])
    sec = {}
    for line in out.splitlines():
        m = re.match(r"^\.(\w+)\s+(\d+)", line)
        if m:
            sec[m.group(1)] = int(m.group(2))
    return sec.get("text", 0) + sec.get("data", 0), sec.get("data", 0) + sec.get("bss", 0)


def simulate(elf, name, tmp):
    """Runs the sketch in libsimavr; returns (uart bytes, info text)."""
    out = os.path.join(tmp, name + ".uart")
    info = os.path.join(tmp, name + ".info")
    subprocess.run([AVRSIM, "-q", "-l", str(CYCLES), "-m", info, "-o", out, MCU, elf],
                   stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    data = open(out, "rb").read() if os.path.exists(out) else b""
    text = open(info).read() if os.path.exists(info) else ""
    return data, text


def check_core(label, lib_dir, sketches, core_inc, core_a, libarch, tmp, strict):
    for s in sketches:
        sk = os.path.join(lib_dir, "examples", s)
        if not os.path.isfile(os.path.join(sk, s + ".ino")):
            continue   # reported by the layout check
        elf = build_sketch(sk, s, lib_dir, core_inc, core_a, libarch,
                           os.path.join(tmp, label, s), [], strict)
        if not check(elf is not None, "%s: examples/%s does not compile and link for the %s" % (label, s, MCU)):
            continue
        flash, ram = sizes(elf)
        print("  %s %s: flash=%d ram_static=%d" % (label, s, flash, ram))
        check(flash <= FLASH_MAX and ram < RAM_MAX,
              "%s %s: flash %d (max %d) / static RAM %d (max %d) do not fit an Uno"
              % (label, s, flash, FLASH_MAX, ram, RAM_MAX))
        if s not in RUNS:
            continue
        defs, host_args, ram_macro = RUNS[s]
        elf = build_sketch(sk, s, lib_dir, core_inc, core_a, libarch,
                           os.path.join(tmp, label, s + "-run"), defs, strict)
        if not check(elf is not None, "%s: %s %s does not build" % (label, s, " ".join(defs))):
            continue
        got, info = simulate(elf, s + "-" + label, tmp)
        want = subprocess.run([EMU, "-q", "--out", "-"] + host_args, stdout=subprocess.PIPE).stdout
        check(got == want and len(want) > 0,
              "%s %s: %d Serial bytes in simavr, rast8-emu %s: %d; %s"
              % (label, s, len(got), " ".join(host_args), len(want),
                 "equal" if got == want else "differ at byte %d" % next(
                     (i for i, (a, b) in enumerate(zip(got, want)) if a != b), min(len(got), len(want)))))
        m = re.search(r"RAM static=(\d+) stack_peak=(\d+)", info)
        if check(m is not None, "%s %s: no RAM line from avrsim:\n%s" % (label, s, info.strip())):
            st, pk = int(m.group(1)), int(m.group(2))
            print("  %s %s run: %d bytes streamed, RAM static %d + stack peak %d = %d of %d"
                  % (label, s, len(got), st, pk, st + pk, RAM_MAX))
            check(st + pk <= RAM_MAX, "%s %s: static %d + stack %d > %d bytes" % (label, s, st, pk, RAM_MAX))
        if not strict:
            continue
        m = re.search(r"#define %s (\d+)" % ram_macro, open(os.path.join(sk, s + ".ino")).read())
        if check(m is not None, "%s: no #define %s N in %s.ino" % (s, ram_macro, s)):
            small = int(m.group(1)) - 1
            elf = build_sketch(sk, s, lib_dir, core_inc, core_a, libarch, os.path.join(tmp, label, s + "-small"),
                               defs + ["-D%s=%d" % (ram_macro, small)], strict)
            got, info = simulate(elf, s + "-small", tmp) if elf else (None, "")
            check(got == b"", "%s %s: with %s=%d (one byte under app_ram) it should stream nothing, "
                  "streamed %s bytes" % (label, s, ram_macro, small, "?" if got is None else len(got)))


def real_core():
    """(core dir, variant dir) of an installed Arduino AVR core, or None."""
    bases = [os.environ["ARDUINO_CORE"]] if os.environ.get("ARDUINO_CORE") else REAL_CORES
    for b in bases:
        core = os.path.join(b, "cores", "arduino")
        var = os.path.join(b, "variants", "standard")
        if os.path.isfile(os.path.join(core, "Arduino.h")):
            return core, var if os.path.isdir(var) else None
    return None


def main(argv):
    if len(argv) != 2 or argv[1] in ("-h", "--help"):
        print(__doc__.strip())
        return 0 if len(argv) == 2 else 2
    path = argv[1]
    try:
        z = zipfile.ZipFile(path)
    except (OSError, zipfile.BadZipFile) as e:
        print("check.py: %s: %s" % (path, e))
        return 2
    for tool in ("avr-gcc", "avr-g++", "avr-ar", "avr-size"):
        if shutil.which(tool) is None:
            print("check.py: %s not found (apt-get install gcc-avr avr-libc)" % tool)
            return 2
    for f in (AVRSIM, EMU):
        if not os.access(f, os.X_OK):
            print("check.py: %s missing (make %s)" % (f, os.path.relpath(f, ROOT)))
            return 2
    with z:
        got = check_layout(z)
        tmp = tempfile.mkdtemp(prefix="r8ard.")
        try:
            if got:
                top, sketches = got
                z.extractall(tmp)
                lib_dir = os.path.join(tmp, top)
                libarch = build_library(lib_dir, os.path.join(tmp, "lib"))
                if check(libarch is not None, "the library does not compile for the %s" % MCU):
                    core_a = build_core(STUB, None, os.path.join(tmp, "stub"), True)
                    if check(core_a is not None, "tests/arduino/core does not compile"):
                        check_core("stub-core", lib_dir, sketches, [STUB], core_a, libarch, tmp, True)
                    rc = real_core()
                    if rc:
                        core, var = rc
                        print("  real core: %s" % core)
                        core_a = build_core(core, var, os.path.join(tmp, "real"), False)
                        if check(core_a is not None, "the real core %s does not compile" % core):
                            check_core("real-core", lib_dir, sketches, [core] + ([var] if var else []),
                                       core_a, libarch, tmp, False)
                    else:
                        print("  no real Arduino AVR core installed (ARDUINO_CORE=DIR): stub only")
        finally:
            shutil.rmtree(tmp, ignore_errors=True)
    print("%d passed, %d failed" % (passed, failed))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
