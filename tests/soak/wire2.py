"""Rewrite a version-1 stream (what rast8-emu writes today) as version 2
(docs/protocol.md section 4.1): every FRAME_START's version byte becomes
2 and every FRAME_END's CRC-16 of the frame a CRC-32 of it (FRAME_END
grows from 7 to 9 bytes); each rewritten packet gets its packet CRC and
COBS again.  Every other byte is copied, damaged packets too.  Used by
`make soak` until the encoder (src/wire.c) writes version 2 itself.

    python tests/soak/wire2.py STREAM DUMP OUT     (DUMP: rast8-emu --dump)
"""
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "host"))

from rast8 import codec as C  # noqa: E402
from rast8.protocol import (read_dump, crc32, PKT_FRAME_START, PKT_FRAME_END,  # noqa: E402
                            VERSION, VERSION2, START_BYTES, END_BYTES, CRC_BYTES)


def _packet(body):
    return C.cobs_encode(body + C.crc16(body).to_bytes(2, "big"))


def to_v2(stream, pixels):
    """stream: version-1 bytes; pixels: {frame number: raw frame bytes}
    (the frames as the device rendered them)."""
    out = []
    for raw in bytes(stream).split(b"\x00"):
        try:
            p = C.cobs_decode(raw) if raw else b""
        except C.CodecError:
            p = b""
        ok = len(p) > CRC_BYTES and C.crc16(p[:-2]) == int.from_bytes(p[-2:], "big")
        body = p[:-2]
        if ok and body[0] == PKT_FRAME_START and len(body) >= START_BYTES and body[1] == VERSION:
            raw = _packet(body[:1] + bytes([VERSION2]) + body[2:])
        elif ok and body[0] == PKT_FRAME_END and len(body) == END_BYTES:
            f = int.from_bytes(body[1:3], "big")
            raw = _packet(body[:5] + crc32(pixels[f]).to_bytes(4, "big"))
        out.append(raw)
    return b"\x00".join(out)


def main(argv=None):
    a = sys.argv[1:] if argv is None else argv
    if len(a) != 3 or a[0] in ("-h", "--help"):
        print(__doc__.strip(), file=sys.stderr)
        return 2
    try:
        with open(a[0], "rb") as f:
            stream = f.read()
        frames = read_dump(a[1])
        data = to_v2(stream, {fr.number: fr.pixels for fr in frames})
        with open(a[2], "wb") as f:
            f.write(data)
    except (OSError, ValueError, KeyError) as e:
        print("wire2: %s" % (e,), file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
