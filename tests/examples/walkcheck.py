"""walkcheck.py - what the keyed walks' checks share (fly_check.py,
maze_check.py; examples/common/walk_host.c): the PASS/FAIL lines and
counts, the key script, `rast8 stats`, a host run, the live pty path and
a target firmware's stream against the host's."""
import json
import os
import subprocess
import sys
import time

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
sys.path.insert(0, os.path.join(ROOT, "tests", "targets"))
import identity  # noqa: E402  (make, run_target, is_skip)

RAST8 = os.path.join(ROOT, ".venv", "bin", "rast8")
EXT = identity.EXT
KEY = {"UP": 0x01, "DOWN": 0x02, "LEFT": 0x04, "RIGHT": 0x08, "A": 0x10, "B": 0x20,
       "X": 0x100, "Y": 0x200}

count = {"passed": 0, "failed": 0, "skipped": 0}


def check(ok, msg):
    print("%s %s" % ("PASS" if ok else "FAIL", msg))
    count["passed" if ok else "failed"] += 1
    return ok


def skip(msg):
    print("SKIP %s" % msg)
    count["skipped"] += 1


def summary():
    """The closing lines; the exit status."""
    print("%d targets skipped (reasons above)" % count["skipped"])
    print("%d passed, %d failed" % (count["passed"], count["failed"]))
    return 1 if count["failed"] else 0


def script(path):
    masks = []
    for line in open(path):
        s = line.split("#", 1)[0].strip()
        if s:
            masks.append(int(s, 0))
    return masks


def stats(data):
    r = subprocess.run([RAST8, "stats", "--json", "-"], input=data, stdout=subprocess.PIPE,
                       stderr=subprocess.PIPE, timeout=120)
    try:
        return json.loads(r.stdout.decode())
    except ValueError:
        return {"error": r.stderr.decode()[-200:]}


def host_run(host, frames, keys, log=None, extra=()):
    args = [host, "-q", "--frames", str(frames), "--out", "-"] + list(extra)
    if keys:
        args += ["--keys", keys]
    if log:
        args += ["--log", log]
    r = subprocess.run(args, stdout=subprocess.PIPE, stderr=subprocess.PIPE, timeout=120)
    return r.returncode, r.stdout, r.stderr.decode("latin-1").strip()


def host_keyed(host, name, keys, frames, fields, extra=()):
    """The host build over the key script `keys` with --log: it ran, its
    stream decodes to `frames` good frames, and frame N was steered by
    script line N-1 (the log's key column).  Returns (the stream or None,
    the log's rows as dicts of `fields`, the script's masks)."""
    import tempfile
    masks = script(keys)
    with tempfile.TemporaryDirectory() as td:
        log = os.path.join(td, "log")
        rc, ref, err = host_run(host, frames, keys, log, extra)
        rows = []
        if os.path.exists(log):
            for line in open(log):
                f = line.split()
                rows.append({k: int(v, 16 if k == "keys" else 10) for k, v in zip(fields, f)})
    if not check(rc == 0 and ref, "host: %s --keys %s --frames %d: exit %d, %d bytes %s"
                 % (name, os.path.relpath(keys, ROOT), frames, rc, len(ref), err)):
        return None, rows, masks
    st = stats(ref)
    check(st.get("frames") == frames and not st.get("bad_packets") and not st.get("incomplete"),
          "host: the stream decodes (rast8 stats): %s frames, %s bad packets, %s incomplete"
          % (st.get("frames"), st.get("bad_packets"), st.get("incomplete")))
    want = [0] + masks[:frames - 1]
    want += [want[-1]] * (frames - len(want))
    got = [r["keys"] for r in rows]
    check(got == want, "host: frame N steered by script line N-1 (frame 0 by none): %s"
          % ("yes" if got == want else "log %s, script %s" % (got, want)))
    return ref, rows, masks


def pty_check(host, name, keys, label):
    """The live path: `name` --pty, a reader on the pty sends INPUT
    packets as `rast8 view` does; the frames stand still until the key
    mask `keys` (`label`) is held, then change."""
    try:
        import serial
        sys.path.insert(0, os.path.join(ROOT, "host"))
        from rast8.protocol import StreamDecoder, input_packet
    except ImportError as e:
        return check(False, "pty: %s (run scripts/setup.sh)" % e)
    p = subprocess.Popen([host, "--pty", "--frames", "0", "--baud", "20000", "-q"],
                         stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    before, after, sent, why = [], [], False, ""
    try:
        dev = p.stdout.readline().decode().strip()
        port = serial.Serial(dev, timeout=0.05)
        port.write(input_packet(0))            # the reader is there (opens the gate)
        dec, t0 = StreamDecoder(), time.time()
        while time.time() - t0 < 30 and len(after) < 6:
            try:
                data = port.read(4096)
            except serial.SerialException as e:
                why = str(e)
                break
            for f in dec.feed(data):
                (after if sent else before).append(f.pixels)
            if not sent and len(before) >= 4:
                port.write(input_packet(keys))
                sent = True
        port.close()
    except (OSError, serial.SerialException) as e:
        why = str(e)
    finally:
        p.terminate()
        p.wait(timeout=10)
    still = len(before) >= 4 and len(set(before)) == 1
    moved = len(after) >= 6 and len(set(after[2:])) > 1 and after[-1] != before[0]
    return check(still and moved, "pty (%s): %d frames stand still with no key, then %s "
                 "held over INPUT packets: %d frames, %d different%s"
                 % ("live, 20000 baud", len(before), label, len(after), len(set(after)),
                    "; " + why if why else ""))


def target_check(t, fw, name, ref, frames, ram_fn):
    """Firmware fw (relative to ROOT) of target t in its simulator: its
    stream equals the host's ref.  True if it ran and was identical; a
    firmware that does not fit is a SKIP line with the reason."""
    path = os.path.join(ROOT, fw)
    if not os.path.exists(path):
        check(False, "%s: %s not built (make output above)" % (name, fw))
        return False
    why = identity.is_skip(path)
    if why:
        ram = os.path.join(os.path.dirname(path), "ram.txt")
        if os.path.exists(ram) and open(ram).read().strip().isdigit():
            why += " (its arena alone, %s, is %s B)" % (ram_fn, open(ram).read().strip())
        skip("%s: %s" % (name, why))
        return False
    size = {}
    if os.path.exists(path + ".size"):
        size = dict(kv.split("=") for kv in open(path + ".size").read().split())
    data, rc, d = identity.run_target(t, path, timeout=600)
    extra = "flash %s B, static RAM %s B (arena %s B)" % (
        size.get("flash", "?"), size.get("ram_static", "?"),
        open(os.path.join(os.path.dirname(path), "ram.txt")).read().strip())
    if t.startswith("avr") and "stack_peak" in d:
        extra += ", stack %d B" % d["stack_peak"]
    at = next((i for i in range(min(len(data), len(ref))) if data[i] != ref[i]),
              min(len(data), len(ref)))
    return check(rc == 0 and data == ref, "%s: %d frames, %d bytes %s the host's (%s)%s"
                 % (name, frames, len(data), "identical to" if data == ref else
                    "DIFFER at byte %d from" % at, extra, "" if rc == 0 else "; exit %d" % rc))
