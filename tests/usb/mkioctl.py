#!/usr/bin/env python3
"""Write umockdev fixtures for the USB tests from a real rast8 stream.

  mkioctl.py device OUT.umockdev [--boards 2]
      the emulated bus: a vendor-class board feed:beef (interface 0, class
      ff, bulk IN 0x81 and bulk OUT 0x01, 64-byte packets) at
      /dev/bus/usb/001/002, and a HID mouse 046d:c077 (interrupt IN 0x81)
      at /dev/bus/usb/001/003 that `--list` must not offer.  With
      --boards 2, a second identical board at /dev/bus/usb/001/004.

  mkioctl.py ioctl STREAM OUT.ioctl [--fault unplug|stall --at BYTES] [--addr N]
      a usbdevfs ioctl script in which endpoint 0x81 delivers the bytes of
      STREAM (a file written by `rast8-emu --out`), split into bulk IN
      transfers of varying length (full, short, 1 byte, zero-length) as a
      device's short packets would end them.  With --fault, the transfer
      that would pass byte offset BYTES ends there with an error status
      instead: -ENODEV (unplugged) or -EPIPE (stalled); for a stall it
      still carries the bytes up to BYTES, as a real URB does.  --addr
      picks the board (device address, default 2).  Prints the number of
      bulk IN replies and the number of stream bytes delivered.

Each reply answers one 4096-byte read (URB_SIZE of rast8.usb and
rast8-usbcat); umockdev matches replies on endpoint, flags and length.
Replies are consumed in order and the script starts over after the last
one, so tests stop the device after the last reply (fault reply, or the
fault shim's silent=N).
"""

import argparse
import sys

URB_SIZE = 4096
BUS, DEVNUM = 1, 2
DEVNODE = f"/dev/bus/usb/{BUS:03d}/{DEVNUM:03d}"
ENODEV, EPIPE = 19, 32

# chunk lengths cycle through these: full reads, packet multiples, odd
# lengths, a single byte and a zero-length packet (which carries nothing)
CHUNKS = [64, 1, 700, 0, 4096, 300, 128, 63, 1500, 2, 1000, 4096, 64, 512]


def _desc_hex(parts):
    return "".join(parts).upper()


# feed:beef: device, config (1 interface), interface 0 class ff with 2 bulk EPs
FEEDBEEF = _desc_hex([
    "12010002ff000040edfeefbe0001000000 01".replace(" ", ""),
    "09022000010100803209040000 02ff000000".replace(" ", ""),
    "0705010240 0000".replace(" ", ""),
    "0705810240 0000".replace(" ", ""),
])
# feed:cafe composite board: interface 0 CDC comm (interrupt IN 0x83),
# interface 1 CDC data (class 0a: bulk OUT 0x01, bulk IN 0x81), interface 2
# vendor class ff with the stream on bulk IN 0x82
COMPOSITE = _desc_hex([
    "12010002000000 40 edfe feca 0001 000000 01".replace(" ", ""),
    "0902400003010080 32".replace(" ", ""),
    "090400000102020100", "0705830308 0010".replace(" ", ""),
    "0904010002 0a000000".replace(" ", ""), "0705010240 0000".replace(" ", ""),
    "0705810240 0000".replace(" ", ""),
    "0904020001ff000000", "0705820240 0000".replace(" ", ""),
])
# 046d:c077 HID mouse: interface class 03, interrupt IN 0x81
MOUSE = _desc_hex([
    "120100020000000 86d0477c0000100000001".replace(" ", ""),
    "0902220001010 0a032".replace(" ", ""),
    "090400000103010200",
    "092111010001223400",
    "07058103040 00a".replace(" ", ""),
])


def _device(desc, vid, pid, devnum, cls, bus=BUS, nifaces=1):
    BUS = bus  # noqa: N806 - the device's own bus
    minor = (BUS - 1) * 128 + devnum - 1
    return "\n".join([
        f"P: /devices/pci0000:00/0000:00:14.0/usb{BUS}/{BUS}-{devnum - 1}",
        f"N: bus/usb/{BUS:03d}/{devnum:03d}={desc}",
        f"E: BUSNUM={BUS:03d}",
        f"E: DEVNAME=/dev/bus/usb/{BUS:03d}/{devnum:03d}",
        f"E: DEVNUM={devnum:03d}",
        "E: DEVTYPE=usb_device",
        "E: DRIVER=usb",
        "E: ID_BUS=usb",
        f"E: ID_VENDOR_ID={vid}",
        f"E: ID_MODEL_ID={pid}",
        "E: MAJOR=189",
        f"E: MINOR={minor}",
        f"E: PRODUCT={vid.lstrip('0')}/{pid.lstrip('0')}/100",
        "E: SUBSYSTEM=usb",
        f"E: TYPE={int(cls, 16)}/0/0",
        "A: bConfigurationValue=1",
        f"A: bDeviceClass={cls}",
        "A: bDeviceProtocol=00",
        "A: bDeviceSubClass=00",
        f"A: bMaxPacketSize0={int(desc[14:16], 16)}",
        "A: bNumConfigurations=1",
        f"A: bNumInterfaces= {nifaces}",
        "A: bcdDevice=0100",
        f"A: busnum={BUS}",
        f"H: descriptors={desc}",
        f"A: dev=189:{minor}",
        f"A: devnum={devnum}",
        f"A: devpath={devnum - 1}",
        f"A: idProduct={pid}",
        f"A: idVendor={vid}",
        "A: speed=12",
        "A: version= 2.00",
        "",
    ])


def devnode(addr=DEVNUM, bus=BUS):
    return f"/dev/bus/usb/{bus:03d}/{addr:03d}"


def device_file(boards=1, other_bus=False, composite=False):
    """boards=2: a second feed:beef at address 4 (bus 1), or with
    other_bus at address 2 of bus 2.  composite: also the feed:cafe
    composite board at address 5."""
    devs = [_device(FEEDBEEF, "feed", "beef", DEVNUM, "ff"),
            _device(MOUSE, "046d", "c077", DEVNUM + 1, "00")]
    if boards > 1:
        if other_bus:
            devs.append(_device(FEEDBEEF, "feed", "beef", DEVNUM, "ff", bus=2))
        else:
            devs.append(_device(FEEDBEEF, "feed", "beef", DEVNUM + 2, "ff"))
    if composite:
        devs.append(_device(COMPOSITE, "feed", "cafe", 5, "00", nifaces=3))
    return "\n".join(devs)


def _reply(status, data, ep=0x81):
    return (f"USBDEVFS_REAPURBNDELAY 0 3 {ep} {status} 0 {URB_SIZE} {len(data)} 0 "
            f"{data.hex().upper()}")


ESHUTDOWN, EPROTO = 108, 71
# fault -> (errno of the failing URB, whether that URB still carries data)
FAULTS = {"unplug": (ENODEV, False), "stall": (EPIPE, True),
          "unplug-data": (ENODEV, True), "shutdown": (ESHUTDOWN, True),
          "proto": (EPROTO, True)}


def ioctl_script(stream, fault=None, at=None, addr=DEVNUM, bus=BUS, ep=0x81):
    """(script text, number of bulk IN replies, bytes delivered)."""
    if fault not in (None, *FAULTS):
        raise ValueError(f"unknown fault {fault!r}")
    if fault and (at is None or not 0 <= at <= len(stream)):
        raise ValueError(f"--at must be within the stream (0..{len(stream)})")
    lines = [f"@DEV {devnode(addr, bus)} (usbdevfs)", "USBDEVFS_GET_CAPABILITIES 0 0F000000"]
    pos = k = replies = 0
    end = at if fault else len(stream)
    while pos < end:
        n = min(CHUNKS[k % len(CHUNKS)], URB_SIZE)
        k += 1
        if fault and pos + n > end:
            break
        n = min(n, end - pos)
        lines.append(_reply(0, stream[pos:pos + n], ep))
        replies += 1
        pos += n
    delivered = pos
    if fault:
        err, with_data = FAULTS[fault]
        if with_data:                                   # the failing URB carries
            lines.append(_reply(-err, stream[pos:end], ep))   # the bytes up to `at`
        else:
            if pos < end:                               # last whole transfer before
                lines.append(_reply(0, stream[pos:end], ep))  # the cable is pulled
                replies += 1
            lines.append(_reply(-err, b"", ep))
        delivered = end
        replies += 1
    return "\n".join(lines) + "\n", replies, delivered


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter,
                                 epilog=__doc__.split("\n\n", 1)[1])
    sub = ap.add_subparsers(dest="cmd", required=True)
    d = sub.add_parser("device", help="write the umockdev device description")
    d.add_argument("out")
    d.add_argument("--boards", type=int, choices=[1, 2], default=1)
    d.add_argument("--other-bus", action="store_true", help="the second board on bus 2")
    d.add_argument("--composite", action="store_true", help="add the composite board feed:cafe")
    i = sub.add_parser("ioctl", help="write the ioctl script for a stream file")
    i.add_argument("stream")
    i.add_argument("out")
    i.add_argument("--fault", choices=sorted(FAULTS))
    i.add_argument("--at", type=int, help="stream byte offset of the fault")
    i.add_argument("--addr", type=int, default=DEVNUM, help="device address of the board")
    i.add_argument("--bus", type=int, default=BUS, help="bus of the board")
    i.add_argument("--ep", type=lambda t: int(t, 16), default=0x81, help="bulk IN endpoint (hex)")
    a = ap.parse_args(argv)
    if a.cmd == "device":
        with open(a.out, "w") as f:
            f.write(device_file(a.boards, a.other_bus, a.composite))
        return 0
    try:
        with open(a.stream, "rb") as f:
            stream = f.read()
    except OSError as e:
        print(f"mkioctl: cannot read {a.stream}: {e.strerror}", file=sys.stderr)
        return 2
    if not stream:
        print(f"mkioctl: {a.stream} is empty", file=sys.stderr)
        return 2
    if a.fault and a.at is None:
        a.at = len(stream) // 2
    try:
        text, replies, delivered = ioctl_script(stream, a.fault, a.at, a.addr, a.bus, a.ep)
    except ValueError as e:
        print(f"mkioctl: {e}", file=sys.stderr)
        return 2
    with open(a.out, "w") as f:
        f.write(text)
    print(f"{replies} {delivered}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
