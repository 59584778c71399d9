#!/usr/bin/env python3
"""check.py - the packages users install rast8 from.

  * `make install PREFIX=<temp>` puts every include/*.h under
    PREFIX/include/rast8/, librast8.a under PREFIX/lib and rast8.pc under
    PREFIX/lib/pkgconfig; pkg-config (PKG_CONFIG_PATH=PREFIX/lib/pkgconfig)
    reports the version of library.properties; tests/package/frame.c,
    copied out of the tree and compiled as strict C89 with nothing but
    `pkg-config --cflags --libs rast8`, renders the same frames as
    build/r8dump; `make uninstall` removes every installed file.
  * library.json against the PlatformIO manifest schema (required keys,
    name, semver version, keywords, SPDX licence, frameworks/platforms,
    export and build fields), library.properties against the Arduino
    library specification, and one version in library.properties,
    library.json and host/pyproject.toml.

Prints one line per failure and ends with "N passed, N failed".
"""
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))

def _arduino_check():
    """tests/arduino/check.py: its library.properties validator."""
    import importlib.util
    spec = importlib.util.spec_from_file_location("arduino_check", os.path.join(ROOT, "tests", "arduino", "check.py"))
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


_ac = _arduino_check()
parse_properties, properties_problems = _ac.parse_properties, _ac.properties_problems

R8DUMP = os.path.join(ROOT, "build", "r8dump")
SPDX_SEEN = {"Zlib", "MIT", "Apache-2.0", "BSD-2-Clause", "BSD-3-Clause", "GPL-3.0-or-later",
             "LGPL-2.1-or-later", "MPL-2.0", "CC0-1.0", "Unlicense", "ISC"}

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


def run(cmd, **kw):
    r = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, **kw)
    return r.returncode, r.stdout


def read_version_pyproject():
    m = re.search(r'^version\s*=\s*"([^"]+)"', open(os.path.join(ROOT, "host", "pyproject.toml")).read(), re.M)
    return m.group(1) if m else None


def library_json_problems(d):
    """PlatformIO manifest schema (platformio/package/manifest/schema.py)."""
    bad = []
    for k in ("name", "version", "description"):
        if not isinstance(d.get(k), str) or not d[k]:
            bad.append("required key %s missing or not a string" % k)
    name = d.get("name", "")
    if isinstance(name, str) and (len(name) > 100 or re.search(r"[:;/,@<>]", name)):
        bad.append("name %r: no [:;/,@<>], at most 100 chars" % name)
    ver = d.get("version", "")
    if isinstance(ver, str) and not re.match(r"^\d+\.\d+(\.\d+)?([-+][0-9A-Za-z.\-+]*)?$", ver):
        bad.append("version %r is not semver" % ver)
    if isinstance(d.get("description"), str) and len(d["description"]) > 255:
        bad.append("description longer than 255 chars")
    kw = d.get("keywords", [])
    kw = kw.split(",") if isinstance(kw, str) else kw
    for k in kw:
        if not re.match(r"^[a-z\d\-+. ]{1,50}$", k.strip()):
            bad.append("keyword %r: only [a-z0-9-+. ]" % k)
    if "license" in d and d["license"] not in SPDX_SEEN:
        bad.append("license %r is not an SPDX id this check knows" % d["license"])
    for f in ("frameworks", "platforms"):
        v = d.get(f, "*")
        for x in (v.split(",") if isinstance(v, str) else v):
            if not re.match(r"^([a-z\d\-_]+|\*)$", x.strip()):
                bad.append("%s entry %r: only [a-z0-9-_*]" % (f, x))
    for a in d.get("authors", []) if isinstance(d.get("authors", []), list) else [d["authors"]]:
        if not isinstance(a, dict) or not a.get("name") or len(a["name"]) > 50:
            bad.append("author %r needs a name of 1-50 chars" % (a,))
    exp = d.get("export", {})
    for k in exp:
        if k not in ("include", "exclude") or not isinstance(exp[k], list):
            bad.append("export.%s: only include/exclude lists" % k)
    for p in exp.get("include", []):
        if not os.path.exists(os.path.join(ROOT, p)):
            bad.append("export.include %s does not exist" % p)
    b = d.get("build", {})
    for k in ("srcDir", "includeDir"):
        if k in b and not os.path.isdir(os.path.join(ROOT, b[k])):
            bad.append("build.%s %s is not a folder" % (k, b[k]))
    for h in d.get("headers", []):
        if not os.path.isfile(os.path.join(ROOT, b.get("includeDir", "include"), h)):
            bad.append("headers: %s not in %s/" % (h, b.get("includeDir", "include")))
    return bad


def check_manifests():
    props, err = parse_properties(open(os.path.join(ROOT, "library.properties"), encoding="utf-8").read())
    if check(props is not None, "library.properties: %s" % err):
        names = set(os.listdir(os.path.join(ROOT, "include"))) | set(os.listdir(os.path.join(ROOT, "src")))
        bad = properties_problems(props, names)
        check(not bad, "library.properties: " + "; ".join(bad))
    try:
        d = json.load(open(os.path.join(ROOT, "library.json"), encoding="utf-8"))
    except (OSError, ValueError) as e:
        check(False, "library.json: %s" % e)
        return None
    check(isinstance(d, dict) and not library_json_problems(d),
          "library.json: " + "; ".join(library_json_problems(d) if isinstance(d, dict) else ["not an object"]))
    versions = {"library.properties": (props or {}).get("version"), "library.json": d.get("version"),
                "host/pyproject.toml": read_version_pyproject()}
    check(len(set(versions.values())) == 1 and None not in versions.values(),
          "versions differ: %s" % versions)
    return (props or {}).get("version")


def check_install(version):
    if shutil.which("pkg-config") is None:
        check(False, "pkg-config not found (apt-get install pkg-config)")
        return
    tmp = tempfile.mkdtemp(prefix="r8inst.")
    try:
        prefix = os.path.join(tmp, "prefix")
        rc, out = run(["make", "-C", ROOT, "-s", "--no-print-directory", "install", "PREFIX=" + prefix])
        if not check(rc == 0, "make install PREFIX=%s failed:\n%s" % (prefix, out.decode(errors="replace"))):
            return
        hdrs = sorted(f for f in os.listdir(os.path.join(ROOT, "include")) if f.endswith(".h"))
        inst = os.path.join(prefix, "include", "rast8")
        check(os.path.isdir(inst) and sorted(os.listdir(inst)) == hdrs and all(
              open(os.path.join(inst, h), "rb").read() == open(os.path.join(ROOT, "include", h), "rb").read()
              for h in hdrs), "installed headers differ from include/*.h")
        lib = os.path.join(prefix, "lib", "librast8.a")
        check(os.path.isfile(lib) and open(lib, "rb").read() == open(os.path.join(ROOT, "build", "librast8.a"), "rb").read(),
              "PREFIX/lib/librast8.a missing or not build/librast8.a")
        pcdir = os.path.join(prefix, "lib", "pkgconfig")
        check(os.path.isfile(os.path.join(pcdir, "rast8.pc")), "PREFIX/lib/pkgconfig/rast8.pc missing")
        env = dict(os.environ, PKG_CONFIG_PATH=pcdir, PKG_CONFIG_LIBDIR=pcdir)
        rc, mv = run(["pkg-config", "--modversion", "rast8"], env=env)
        check(rc == 0 and mv.decode().strip() == version,
              "pkg-config --modversion rast8: %r, library.properties %r" % (mv.decode().strip(), version))
        rc, flags = run(["pkg-config", "--cflags", "--libs", "rast8"], env=env)
        if not check(rc == 0, "pkg-config --cflags --libs rast8: %s" % flags.decode().strip()):
            return
        flags = flags.decode().split()
        check(("-I" + inst) in flags and ("-L" + os.path.join(prefix, "lib")) in flags and "-lrast8" in flags,
              "pkg-config flags %s do not point at the prefix" % flags)
        # a user program, out of the tree, with nothing but the pkg-config flags
        work = os.path.join(tmp, "user")
        os.makedirs(work)
        shutil.copy(os.path.join(ROOT, "tests", "package", "frame.c"), work)
        cc = os.environ.get("CC") or "gcc"
        rc, out = run([cc, "-std=c89", "-pedantic", "-Wall", "-Wextra", "-Werror", "frame.c", "-o", "frame"] + flags,
                      cwd=work)
        if check(rc == 0, "%s -std=c89 frame.c $(pkg-config --cflags --libs rast8) failed:\n%s"
                 % (cc, out.decode(errors="replace"))):
            bad = []
            for n in (0, 7, 21):
                raw = os.path.join(tmp, "ref.raw")
                subprocess.run([R8DUMP, "--scene", "cube", "--method", "cull", "--frame", str(n), "--raw", raw],
                               stdout=subprocess.DEVNULL, check=False)
                got = subprocess.run([os.path.join(work, "frame"), str(n)], stdout=subprocess.PIPE).stdout
                ref = open(raw, "rb").read() if os.path.exists(raw) else b""
                if got != ref or len(ref) != 1024 or ref == bytes(1024):
                    bad.append("frame %d: %d bytes vs r8dump's %d" % (n, len(got), len(ref)))
            check(not bad, "installed-library program vs build/r8dump: " + "; ".join(bad))
        rc, out = run(["make", "-C", ROOT, "-s", "--no-print-directory", "uninstall", "PREFIX=" + prefix])
        left = [os.path.join(d, f) for d, _, fs in os.walk(prefix) for f in fs]
        check(rc == 0 and not left, "make uninstall left %s" % left)
    finally:
        shutil.rmtree(tmp, ignore_errors=True)


def main():
    if len(sys.argv) > 1:
        print(__doc__.strip())
        return 0 if sys.argv[1] in ("-h", "--help") else 2
    version = check_manifests()
    if version:
        check_install(version)
    print("%d passed, %d failed" % (passed, failed))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
