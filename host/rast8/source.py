"""Byte sources for the rast8 tools.

open_source(spec) -> object with .read(n) -> bytes (b'' at end of input)
and .close(); .write(data) where the source can talk back (serial).

spec:  -                stdin
       usb:...          rast8.usb.open_usb(spec)   (USB bridge)
       socket://h:p, loop://, rfc2217://h:p, spy://...   pyserial URL
       /dev/tty*, /dev/pts/N, any character device        serial port
       anything else    a file
"""
import os
import stat
import sys
import time

DEFAULT_BAUD = 115200


class FileSource:
    kind = "file"

    def __init__(self, f, name):
        self.f = f
        self.name = name

    def read(self, n=4096):
        return self.f.read1(n) if hasattr(self.f, "read1") else self.f.read(n)

    def write(self, data):
        return 0            # a file cannot take requests

    def close(self):
        if self.f is not sys.stdin.buffer:
            self.f.close()


class SerialSource:
    """A pyserial port or URL.  read() waits for data; it returns b'' when
    the other end goes away (pty closed, socket closed) or, with
    idle=SECONDS, after that long without a byte."""
    kind = "serial"

    def __init__(self, ser, name, idle=None, hello=True):
        self.ser = ser
        self.name = name
        self.idle = idle
        if hello:
            # A REQUEST right after opening: asks for a full frame, and
            # tells rast8-emu --pty/--tcp that we are ready (pyserial
            # flushes input while it opens a port, see docs/protocol.md).
            from .protocol import request_packet
            self.write(request_packet())

    def read(self, n=4096):
        import serial
        t0 = time.monotonic()
        while True:
            try:
                waiting = self.ser.in_waiting
            except (serial.SerialException, OSError):
                waiting = 0
            try:
                data = self.ser.read(max(1, min(n, waiting)))
            except (serial.SerialException, OSError):
                return b""      # device gone: end of input
            if data:
                return data
            if self.idle is not None and time.monotonic() - t0 >= self.idle:
                return b""
            if getattr(self.ser, "_closed_by_peer", False):
                return b""

    def write(self, data):
        try:
            return self.ser.write(data)
        except Exception:
            return 0

    def close(self):
        try:
            self.ser.close()
        except Exception:
            pass


def _is_url(spec):
    return "://" in spec


def open_source(spec, baud=DEFAULT_BAUD, idle=None):
    """Open SOURCE (see the module doc)."""
    if spec.startswith("usb:"):
        from rast8 import usb
        return usb.open_usb(spec, idle=idle)
    if spec == "-":
        return FileSource(sys.stdin.buffer, "stdin")
    import serial
    if _is_url(spec):
        ser = serial.serial_for_url(spec, baudrate=baud, timeout=0.05)
        return SerialSource(ser, spec, idle, hello=not spec.startswith("loop://"))
    try:
        st = os.stat(spec)
    except OSError as e:
        raise FileNotFoundError("cannot open %s: %s" % (spec, e.strerror)) from None
    if stat.S_ISCHR(st.st_mode):
        ser = serial.Serial(spec, baudrate=baud, timeout=0.05)
        return SerialSource(ser, spec, idle)
    return FileSource(open(spec, "rb"), spec)
