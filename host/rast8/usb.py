"""USB source: read a rast8 stream from a vendor-class bulk IN endpoint.

Some boards send the frame stream on a USB bulk IN endpoint instead of a
CDC serial port, so there is no tty for pyserial.  ``open_usb(spec)`` reads
such a device through pyusb and libusb-1.0 and returns a file-like object:

    src = open_usb("usb:feed:beef")        # VID:PID in hex, EP 0x81
    data = src.read(4096)                  # b'' at the end of the stream
    src.close()

Spec: ``usb:VID:PID[:EP][,key=value...]``, VID, PID and EP in hex (EP is
the bulk IN endpoint address, default 81).  Options:

    timeout=SEC   fail with UsbTimeout when no data arrives for SEC seconds
                  (default 5; 0 waits forever)
    idle=SEC      end the stream cleanly (read returns b'') once the device
                  has sent data and then nothing for SEC seconds (captures)
    bus=N,addr=N  pick one of several devices with the same VID:PID
    interface=N   claim interface N (default: the one owning EP)

The stream is opaque here: bytes are passed on unchanged.  Errors are
``UsbError`` subclasses (an ``OSError``) whose message says what to do and
whose ``exit_code`` matches rast8-usbcat's exit codes.  Bytes received
before an error are returned first; the error is raised by the next read.

libusb comes from the system (libusb-1.0-0) or, where there is none, from
the ``libusb-package`` wheel.  RAST8_USB_BACKEND=system|package forces one.
See docs/usb.md.
"""

import ctypes
import os
import time

DEFAULT_EP = 0x81
DEFAULT_TIMEOUT = 5.0
URB_SIZE = 4096        # bytes per bulk IN request (as rast8-usbcat)
SLICE = 0.5            # longest single libusb wait, so Ctrl-C is seen

# libusb error codes
_SUCCESS = 0
_ERR_IO = -1
_ERR_ACCESS = -3
_ERR_NO_DEVICE = -4
_ERR_NOT_FOUND = -5
_ERR_BUSY = -6
_ERR_TIMEOUT = -7
_ERR_OVERFLOW = -8
_ERR_PIPE = -9
_ERR_INTERRUPTED = -10

UDEV_RULE = ('SUBSYSTEM=="usb", ATTR{{idVendor}}=="{vid:04x}", '
             'ATTR{{idProduct}}=="{pid:04x}", MODE="0660", TAG+="uaccess"')


class UsbError(OSError):
    """A USB source failed; str() says what happened and what to do."""
    exit_code = 1

    def __init__(self, message):
        super().__init__(message)
        self.message = message

    def __str__(self):
        return self.message


class UsbSpecError(UsbError, ValueError):
    """The usb: spec is malformed."""
    exit_code = 2


class UsbNoDevice(UsbError):
    """No device with that VID:PID (or no such endpoint)."""
    exit_code = 3


class UsbPermissionDenied(UsbError):
    """The device node is not accessible (udev rule missing)."""
    exit_code = 4


class UsbBusy(UsbError):
    """The interface is claimed by another program or driver."""
    exit_code = 5


class UsbUnplugged(UsbError):
    """The device went away mid-stream."""
    exit_code = 6


class UsbStall(UsbError):
    """The device halted (stalled) the endpoint."""
    exit_code = 7


class UsbTimeout(UsbError):
    """No data arrived in time."""
    exit_code = 8


class UsbBackendMissing(UsbError):
    """pyusb or libusb is not installed."""
    exit_code = 1


# ---------------------------------------------------------------- spec

def parse_spec(spec):
    """Parse ``usb:VID:PID[:EP][,key=value...]`` into a dict."""
    if not isinstance(spec, str) or not spec.startswith("usb:"):
        raise UsbSpecError(f"bad USB source {spec!r}: expected usb:VID:PID[:EP], "
                           "e.g. usb:feed:beef or usb:feed:beef:81")
    body, _, opts = spec[4:].partition(",")
    parts = body.split(":")
    hint = ("expected usb:VID:PID[:EP][,timeout=S][,idle=S][,bus=N][,addr=N]"
            "[,interface=N] with VID, PID and EP in hex, e.g. usb:feed:beef")
    if len(parts) not in (2, 3):
        raise UsbSpecError(f"bad USB source {spec!r}: {hint}")

    def hexnum(text, what, top):
        try:
            v = int(text, 16)
        except ValueError:
            raise UsbSpecError(f"bad {what} {text!r} in {spec!r}: {hint}") from None
        if not 0 <= v <= top:
            raise UsbSpecError(f"{what} {text!r} out of range in {spec!r}: {hint}")
        return v

    out = {"vid": hexnum(parts[0], "VID", 0xFFFF), "pid": hexnum(parts[1], "PID", 0xFFFF),
           "ep": DEFAULT_EP, "timeout": DEFAULT_TIMEOUT, "idle": None,
           "bus": None, "addr": None, "interface": None}
    if len(parts) == 3:
        out["ep"] = hexnum(parts[2], "endpoint", 0xFF)
        if not out["ep"] & 0x80:
            raise UsbSpecError(f"endpoint 0x{out['ep']:02x} in {spec!r} is an OUT endpoint; "
                               "give the bulk IN address (bit 7 set, e.g. 81)")
    for item in filter(None, opts.split(",")):
        key, eq, val = item.partition("=")
        key = key.strip()
        if not eq or key not in ("timeout", "idle", "bus", "addr", "interface"):
            raise UsbSpecError(f"unknown option {item!r} in {spec!r}: {hint}")
        try:
            num = float(val) if key in ("timeout", "idle") else int(val, 0)
        except ValueError:
            raise UsbSpecError(f"bad value for {key} in {spec!r}: {val!r}") from None
        if num < 0 or num != num:
            raise UsbSpecError(f"{key} must be >= 0 in {spec!r}")
        out[key] = num
    if out["idle"] == 0:
        out["idle"] = None
    return out


# ---------------------------------------------------------------- backend

def get_backend():
    """Return (pyusb backend, description): system libusb, else the wheel's."""
    try:
        import usb.backend.libusb1 as libusb1
    except ImportError:
        raise UsbBackendMissing(
            "pyusb is not installed: pip install pyusb libusb-package "
            "(or install rast8 with its test extra)") from None
    forced = os.environ.get("RAST8_USB_BACKEND", "").strip().lower()
    if forced not in ("", "system", "package"):
        raise UsbBackendMissing(f"RAST8_USB_BACKEND={forced!r}: use 'system' or 'package'")
    if forced != "package":
        be = libusb1.get_backend()
        if be is not None:
            return be, "system libusb-1.0"
        if forced == "system":
            raise UsbBackendMissing("no system libusb-1.0 found (RAST8_USB_BACKEND=system): "
                                    "apt install libusb-1.0-0")
    try:
        import libusb_package
        be = libusb_package.get_libusb1_backend()
    except ImportError:
        be = None
    if be is None:
        raise UsbBackendMissing("libusb-1.0 not found: install it (apt install libusb-1.0-0) "
                                "or the wheel (pip install libusb-package)")
    return be, "libusb-package " + getattr(libusb_package, "__version__", "")


def _bulk_in_interfaces(dev, ep=None):
    """Yield (interface descriptor, endpoint descriptor) for bulk IN endpoints."""
    import usb.util
    try:
        cfg = dev.get_active_configuration()
    except Exception:       # unconfigured or not readable: use the first one
        cfg = dev[0]
    for intf in cfg:
        for e in intf:
            if usb.util.endpoint_type(e.bmAttributes) != usb.util.ENDPOINT_TYPE_BULK:
                continue
            if not e.bEndpointAddress & 0x80:
                continue
            if ep is not None and e.bEndpointAddress != ep:
                continue
            yield intf, e


def list_devices():
    """Candidate devices: vendor-class interfaces with a bulk IN endpoint.

    Returns a list of dicts with spec, bus, addr, interface, alt, max_packet.
    """
    import usb.core
    backend, _ = get_backend()
    found = []
    for dev in usb.core.find(find_all=True, backend=backend):
        for intf, e in _bulk_in_interfaces(dev):
            if intf.bInterfaceClass != 0xFF:
                continue
            found.append({"spec": f"usb:{dev.idVendor:04x}:{dev.idProduct:04x}:"
                                  f"{e.bEndpointAddress:02x}",
                          "bus": dev.bus, "addr": dev.address,
                          "interface": intf.bInterfaceNumber, "alt": intf.bAlternateSetting,
                          "max_packet": e.wMaxPacketSize})
    return found


def _code(exc):
    """libusb error code of a pyusb USBError (or None)."""
    return getattr(exc, "backend_error_code", None)


# ---------------------------------------------------------------- source

class UsbSource:
    """File-like reader of one bulk IN endpoint; use open_usb()."""
    kind = "usb"

    def __init__(self, spec, timeout=None, idle=None):
        opts = parse_spec(spec)
        backend, self.backend_name = get_backend()     # UsbBackendMissing without pyusb
        import usb.core
        import usb.util
        self._usb_util = usb.util
        self._backend = backend
        if timeout is not None:
            opts["timeout"] = timeout
        if idle is not None:
            opts["idle"] = idle or None
        self.opts = opts
        self.vid, self.pid, self.ep = opts["vid"], opts["pid"], opts["ep"]
        self.name = f"usb:{self.vid:04x}:{self.pid:04x}:{self.ep:02x}"
        self.bytes_read = 0
        self.closed = False
        self._buf = b""
        self._error = None
        self._eof = False
        self._claimed = None
        self._detached = False
        self._dev = None
        self.warnings = []
        self._last_data = time.monotonic()

        def match(d):
            return ((opts["bus"] is None or d.bus == opts["bus"]) and
                    (opts["addr"] is None or d.address == opts["addr"]))
        try:
            devs = list(usb.core.find(find_all=True, idVendor=self.vid, idProduct=self.pid,
                                      backend=backend, custom_match=match))
        except usb.core.USBError as e:
            raise UsbError(f"cannot enumerate USB devices: {e}") from e
        where = " at the given bus/addr" if opts["bus"] is not None or opts["addr"] is not None else ""
        if not devs:
            raise UsbNoDevice(
                f"no such device: no USB device {self.vid:04x}:{self.pid:04x} is connected{where}. "
                "Plug the board in (check the cable carries data) and check VID:PID with "
                "'rast8-usbcat --list' or 'lsusb'")
        # "first found" = the lowest bus number, then the lowest address
        devs.sort(key=lambda d: (d.bus, d.address))
        dev = devs[0]
        self.bus, self.addr = dev.bus, dev.address
        if len(devs) > 1:
            self.warnings.append(f"{len(devs)} devices match {self.vid:04x}:{self.pid:04x}; using "
                                 f"bus {dev.bus} addr {dev.address} (choose with ,bus=N,addr=N)")
        self._dev = dev
        try:
            self._setup(dev, opts)
        except BaseException:
            self.close()
            raise

    def _setup(self, dev, opts):
        import usb.core
        want = opts["interface"]
        owners = [(i, e) for i, e in _bulk_in_interfaces(dev, self.ep)
                  if want is None or i.bInterfaceNumber == want]
        found = [(i, e) for i, e in owners if i.bInterfaceClass == 0xFF]
        if owners and not found:
            i = owners[0][0]
            kind = {0x0A: " (CDC data)", 0x02: " (CDC control)"}.get(i.bInterfaceClass, "")
            raise UsbNoDevice(
                f"not a vendor-class interface: endpoint 0x{self.ep:02x} of "
                f"{self.vid:04x}:{self.pid:04x} is on interface {i.bInterfaceNumber} of class "
                f"0x{i.bInterfaceClass:02x}{kind}, which rast8 does not open (it would take the "
                "interface from its kernel driver, e.g. the board's serial port). Use the "
                "vendor-class endpoint that 'rast8-usbcat --list' shows, or read the serial port")
        if not found:
            on = f"interface {want} of " if want is not None else ""
            raise UsbNoDevice(f"no such endpoint: {on}{self.vid:04x}:{self.pid:04x} has no bulk "
                              f"IN endpoint 0x{self.ep:02x}; 'rast8-usbcat --list' shows the "
                              "endpoints")
        intf, _ = found[0]
        iface = intf.bInterfaceNumber
        ident = f"{self.vid:04x}:{self.pid:04x} (bus {self.bus:03d} addr {self.addr:03d})"
        rule = UDEV_RULE.format(vid=self.vid, pid=self.pid)
        perm = (f"install the udev rule from docs/usb.md, e.g. in /etc/udev/rules.d/70-rast8.rules:"
                f"\n  {rule}\nthen run 'sudo udevadm control --reload && sudo udevadm trigger' "
                "and re-plug the device (or run as root)")
        try:
            try:
                active = dev.is_kernel_driver_active(iface)
            except NotImplementedError:
                active = False
            if active:
                try:
                    dev.detach_kernel_driver(iface)
                    self._detached = iface
                except usb.core.USBError as e:
                    if _code(e) not in (_ERR_NOT_FOUND, None):
                        self.warnings.append(f"cannot detach the kernel driver of interface "
                                             f"{iface}: {e}")
            self._usb_util.claim_interface(dev, iface)
            self._claimed = iface
            if intf.bAlternateSetting:
                dev.set_interface_altsetting(iface, intf.bAlternateSetting)
            try:
                dev.clear_halt(self.ep)        # a halt left by an earlier run
            except usb.core.USBError:
                pass
        except usb.core.USBError as e:
            code = _code(e)
            if code == _ERR_ACCESS:
                raise UsbPermissionDenied(f"permission denied opening {ident}: {perm}") from e
            if code == _ERR_BUSY:
                why = ("; " + self.warnings[-1]) if any(
                    w.startswith("cannot detach") for w in self.warnings) else ""
                raise UsbBusy(
                    f"interface busy: interface {iface} of {self.vid:04x}:{self.pid:04x} is "
                    "claimed by another program (another rast8 viewer or rast8-usbcat?) or by "
                    f"a kernel driver that could not be detached{why}. Close that program "
                    "(or run as root to detach the driver) and retry") from e
            if code == _ERR_NO_DEVICE:
                raise UsbUnplugged(f"device unplugged: {ident} disappeared before streaming "
                                   "began; re-plug it and retry") from e
            raise UsbError(f"cannot open interface {iface} of {ident}: {e}") from e
        # direct libusb_bulk_transfer keeps the bytes of a transfer that ends in
        # an error (pyusb's read() drops them); fall back to read() otherwise
        self._raw = None
        try:
            handle = dev._ctx.handle.handle
            lib = self._backend.lib
            if handle is not None and hasattr(lib, "libusb_bulk_transfer"):
                self._raw = (lib, handle, (ctypes.c_ubyte * URB_SIZE)(), ctypes.c_int())
        except AttributeError:
            self._raw = None

    # -- reading

    def _transfer(self, timeout_ms):
        """One bulk IN request: (bytes, libusb result code)."""
        if self._raw is not None:
            lib, handle, buf, got = self._raw
            got.value = 0
            r = lib.libusb_bulk_transfer(handle, self.ep,
                                         ctypes.cast(buf, ctypes.POINTER(ctypes.c_ubyte)),
                                         URB_SIZE, ctypes.byref(got), timeout_ms)
            return bytes(buf[:max(0, got.value)]), r
        import usb.core
        try:
            return bytes(self._dev.read(self.ep, URB_SIZE, timeout_ms)), _SUCCESS
        except usb.core.USBTimeoutError:
            return b"", _ERR_TIMEOUT
        except usb.core.USBError as e:
            return b"", _code(e) if _code(e) is not None else _ERR_IO

    def _error_for(self, r):
        n = self.bytes_read
        if r == _ERR_NO_DEVICE:
            return UsbUnplugged(
                f"device unplugged: {self.name} disappeared mid-stream after {n} bytes (all "
                "passed on). Check the cable and power, re-plug and run again")
        if r == _ERR_PIPE:
            return UsbStall(
                f"endpoint stalled: the device halted endpoint 0x{self.ep:02x} after {n} bytes "
                "(all passed on). The firmware reported an error; reset the board and run "
                "again (the halt is cleared on open)")
        if r == _ERR_OVERFLOW:
            return UsbError(f"USB overflow on endpoint 0x{self.ep:02x} after {n} bytes: the "
                            "device sent more than was asked for")
        if r == _ERR_IO:
            return UsbError(
                f"USB bus error on {self.name} after {n} bytes (all passed on): the transfer "
                "failed on the wire (EPROTO/EILSEQ/ETIME: bad signal, noise or power). Try "
                "another cable, a port on the computer itself rather than a hub, or a powered "
                "hub, then run again")
        return UsbError(f"USB read error on {self.name} after {n} bytes: libusb error {r}")

    def _fill(self):
        """Read until some bytes arrive, the stream ends or an error is due."""
        while not self._buf and self._error is None and not self._eof:
            idle = self.opts["idle"]
            limit = idle if (idle and self.bytes_read) else self.opts["timeout"]
            left = limit - (time.monotonic() - self._last_data) if limit else SLICE
            # always ask the device once more before giving up, so a slow
            # host (not a quiet device) never ends the stream early
            ms = max(1, min(int(left * 1000 + 0.5), int(SLICE * 1000)))
            data, r = self._transfer(ms)
            if data:
                self._buf += data
                self.bytes_read += len(data)
                self._last_data = time.monotonic()
            if r not in (_SUCCESS, _ERR_TIMEOUT, _ERR_INTERRUPTED):
                self._error = self._error_for(r)
            elif not data and limit and time.monotonic() - self._last_data >= limit:
                if idle and self.bytes_read:
                    self._eof = True
                else:
                    more = (" (after the data so far); idle=SEC ends a capture cleanly"
                            if self.bytes_read else "")
                    self._error = UsbTimeout(
                        f"timeout: no data from {self.name} for {limit:g} s{more}. Check "
                        "that the firmware is streaming, or wait longer with "
                        f"{self.name},timeout=SEC (0 = forever)")

    def read(self, n=-1):
        """Up to n bytes (n < 0: what is buffered); b'' at the end of the stream.

        Blocks until at least one byte arrives.  Bytes received before an
        error are returned first; the error is raised on the next call.
        """
        if self.closed:
            raise ValueError("read from a closed USB source")
        if n == 0:
            return b""
        if not self._buf:
            self._fill()
        if self._buf:
            if n is None or n < 0:
                n = len(self._buf)
            out, self._buf = self._buf[:n], self._buf[n:]
            return out
        if self._error is not None:
            raise self._error
        return b""

    def readable(self):
        return True

    def write(self, data):
        """The USB source is read-only: nothing is sent to the board, so a
        request for a full frame is not delivered (returns 0, as for a file);
        the board's periodic full frames resynchronise the viewer."""
        return 0

    def close(self):
        if self.closed:
            return
        self.closed = True
        dev = self._dev
        if dev is None:
            return
        try:
            if self._claimed is not None:
                self._usb_util.release_interface(dev, self._claimed)
            if self._detached is not False:
                dev.attach_kernel_driver(self._detached)
        except Exception:       # device gone: nothing to release
            pass
        try:
            self._usb_util.dispose_resources(dev)
        except Exception:
            pass

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    def __repr__(self):
        return f"<UsbSource {self.name} {self.bytes_read} bytes>"


def open_usb(spec, timeout=None, idle=None):
    """Open ``usb:VID:PID[:EP][,options]``; see the module docstring."""
    return UsbSource(spec, timeout=timeout, idle=idle)
