"""Test helper: read a usb: source to its end through rast8.usb.open_usb.

    python usbread.py SPEC OUTFILE [CHUNK]

Runs inside umockdev-run.  Writes every byte read to OUTFILE as it
arrives, and prints one JSON line: bytes read, backend, and the error (class
name, exit_code, message) if one was raised; exits with its exit_code.
Also checks that the error is raised again on a further read (sticky).
"""
import json
import sys

from rast8.usb import UsbError, open_usb


def main():
    spec, out = sys.argv[1], sys.argv[2]
    chunk = int(sys.argv[3]) if len(sys.argv) > 3 else 1000
    report = {"bytes": 0, "error": None, "backend": None, "reads": 0}
    rc = 0
    with open(out, "wb") as f:
        try:
            src = open_usb(spec)
        except UsbError as e:
            report["error"] = {"type": type(e).__name__, "code": e.exit_code, "message": str(e),
                               "at": "open"}
            print(json.dumps(report))
            return e.exit_code
        report["backend"] = src.backend_name
        report["warnings"] = src.warnings
        try:
            while True:
                data = src.read(chunk)
                report["reads"] += 1
                if len(data) > chunk:
                    raise AssertionError(f"read({chunk}) returned {len(data)} bytes")
                if not data:
                    break
                f.write(data)
                f.flush()
                report["bytes"] += len(data)
        except UsbError as e:
            report["error"] = {"type": type(e).__name__, "code": e.exit_code, "message": str(e),
                               "at": "read"}
            rc = e.exit_code
            try:
                src.read(chunk)
                report["error"]["sticky"] = False
            except UsbError as again:
                report["error"]["sticky"] = type(again) is type(e)
        finally:
            src.close()
    print(json.dumps(report))
    return rc


if __name__ == "__main__":
    sys.exit(main())
