"""rast8 serial display protocol, version 1 (docs/protocol.md).

StreamDecoder mirrors the C decoder (src/decoder.c) exactly: same
packets accepted, same frames reported good, same counters.  Encoder
mirrors the C band encoder (src/wire.c): given the same frames it writes
the same bytes.

    from rast8.protocol import StreamDecoder
    dec = StreamDecoder()
    for frame in dec.feed(chunk):      # bytes in, good frames out
        frame.to_image().save(...)
    dec.counters()                     # bad packets, dropped, incomplete...
"""
from dataclasses import dataclass, field

from . import codec as _codec
from .codec import crc16, CodecError

VERSION = 1
PKT_FRAME_START, PKT_BAND, PKT_FRAME_END, PKT_REQUEST = 0x01, 0x02, 0x03, 0x10
FLAG_FULL = 0x01
START_BYTES, BAND_HDR, END_BYTES, CRC_BYTES = 14, 6, 7, 2
MAX_DIM = 4095
MAX_BAND = 32767
FMT_PAGE1, FMT_ROW1, FMT_IDX8 = 0, 1, 2
FORMAT_NAMES = {"page1": FMT_PAGE1, "row1": FMT_ROW1, "idx8": FMT_IDX8}
FORMAT_BY_ID = {v: k for k, v in FORMAT_NAMES.items()}


def fb_bytes(fmt, width, rows):
    """Bytes of `rows` rows of a `width`-wide frame (include/r8fb.h)."""
    if fmt == FMT_PAGE1:
        return width * ((rows + 7) >> 3)
    if fmt == FMT_ROW1:
        return ((width + 7) >> 3) * rows
    return width * rows


def pkt_bytes(band_bytes, npal):
    """R8_WIRE_PKT_BYTES: the largest packet body + CRC."""
    return max(band_bytes + BAND_HDR, START_BYTES + 3 * npal) + CRC_BYTES


def request_packet():
    """The display -> device REQUEST (send a full frame), with delimiters."""
    body = bytes([PKT_REQUEST])
    body += crc16(body).to_bytes(2, "big")
    return b"\x00" + _codec.cobs_encode(body) + b"\x00"


def packet(body):
    """body + CRC, COBS-encoded, with the trailing delimiter."""
    return _codec.cobs_encode(body + crc16(body).to_bytes(2, "big")) + b"\x00"


@dataclass
class Frame:
    """One good (complete, CRC-checked) frame."""
    number: int
    width: int
    height: int
    format: int
    pixels: bytes                      # the framebuffer, layout per r8fb.h
    palette: list = field(default_factory=list)   # [(r, g, b), ...]
    full: bool = True                  # sent as a full frame
    wire_bytes: int = 0                # stream bytes since the previous frame

    @property
    def format_name(self):
        return FORMAT_BY_ID.get(self.format, str(self.format))

    def to_image(self, scale=1):
        from .image import frame_to_image
        return frame_to_image(self, scale)


class StreamDecoder:
    """Byte-at-a-time decoder with fixed limits, as src/decoder.c.

    max_frame_bytes plays the C decoder's fb_size; packets longer than
    pkt_bytes(max_frame_bytes, 256) are dropped (counted bad)."""

    def __init__(self, max_frame_bytes=65536):
        self.fb_size = max_frame_bytes
        self.pkt_size = pkt_bytes(max_frame_bytes, 256)
        self.fb = bytearray(max_frame_bytes)
        self._pkt = bytearray()
        self._code = 0
        self._left = 0
        self._overflow = False
        self.in_frame = False
        self.full = False
        self.format = self.codec = 0
        self.valid = False
        self.npal = 0
        self.palette = []
        self.frame = 0
        self.nbands_got = 0
        self.width = self.height = self.band = 0
        self.last_seen = 0
        self.have_last = False
        self.base_ok = False
        self.need_full = False
        self.frame_bytes = 0
        # counters
        self.bytes = 0
        self.packets = 0
        self.bad_packets = 0
        self.frames = 0
        self.dropped = 0
        self.incomplete = 0
        self.raw_bytes = 0             # raw bytes of good frames
        self._since = 0                # stream bytes since the last good frame
        self.errors = []               # last few error descriptions

    def counters(self):
        return {"bytes": self.bytes, "packets": self.packets,
                "bad_packets": self.bad_packets, "frames": self.frames,
                "dropped": self.dropped, "incomplete": self.incomplete}

    # ---- byte level
    def feed(self, data):
        """Feed bytes; returns the list of good frames they completed."""
        out = []
        pkt = self._pkt
        for c in bytes(data):
            self.bytes += 1
            self._since += 1
            if c == 0:
                if self._left or self._overflow:
                    self._bad("framing: packet %s" % ("too long" if self._overflow else "cut short"))
                elif self._code:
                    f = self._on_packet(bytes(pkt))
                    if f is not None:
                        out.append(f)
                pkt.clear()
                self._code = self._left = 0
                self._overflow = False
                continue
            if self._left == 0:
                if self._code and self._code != 0xFF:
                    self._put(0)
                self._code = c
                self._left = c - 1
            else:
                self._put(c)
                self._left -= 1
        return out

    def _put(self, v):
        if len(self._pkt) < self.pkt_size:
            self._pkt.append(v)
        else:
            self._overflow = True

    def _bad(self, why):
        self.bad_packets += 1
        self.errors = (self.errors + [why])[-8:]
        return None

    def _seen_frame(self, f):
        if self.have_last:
            gap = (f - self.last_seen - 1) & 0xFFFF
            if f != self.last_seen and gap < 0x8000:
                self.dropped += gap
        self.last_seen = f
        self.have_last = True

    def _frame_fail(self):
        if self.in_frame:
            self.incomplete += 1
        self.in_frame = False
        self.base_ok = False
        self.need_full = True

    def _orphan(self, f):
        if self.in_frame:
            self._frame_fail()
        elif self.have_last and f == self.last_seen:
            return
        self._seen_frame(f)
        self.incomplete += 1
        self.base_ok = False
        self.need_full = True

    # ---- packet level
    def _on_packet(self, p):
        n = len(p)
        if n < 1 + CRC_BYTES or crc16(p[:-2]) != int.from_bytes(p[-2:], "big"):
            return self._bad("crc")
        p = p[:-2]
        t = p[0]
        if t == PKT_FRAME_START:
            return self._on_start(p)
        if t == PKT_BAND:
            return self._on_band(p)
        if t == PKT_FRAME_END:
            return self._on_end(p)
        if t == PKT_REQUEST:
            return None         # our own request echoed back: ignore
        return self._bad("unknown packet type 0x%02x" % t)

    def _on_start(self, p):
        n = len(p)
        if n < START_BYTES:
            return self._bad("short frame start")
        npal = p[13]
        w = int.from_bytes(p[4:6], "big")
        h = int.from_bytes(p[6:8], "big")
        fmt = p[8]
        band = int.from_bytes(p[9:11], "big")
        codec = p[11]
        if (p[1] != VERSION or n != START_BYTES + 3 * npal or fmt > FMT_IDX8 or
                codec > 2 or w == 0 or h == 0 or w > MAX_DIM or h > MAX_DIM or
                band == 0 or band > h or (fmt == FMT_PAGE1 and band & 7)):
            return self._bad("bad frame start (version %d)" % p[1])
        if self.in_frame:
            self._frame_fail()
        f = int.from_bytes(p[2:4], "big")
        self._seen_frame(f)
        self.packets += 1
        fbytes = fb_bytes(fmt, w, h)
        if (w, h, fmt, band) != (self.width, self.height, self.format, self.band):
            self.base_ok = False
        self.frame = f
        self.width, self.height, self.format, self.band = w, h, fmt, band
        self.codec = codec
        self.full = bool(p[12] & FLAG_FULL)
        self.nbands_got = 0
        self.in_frame = True
        self.valid = True
        if fbytes > self.fb_size:
            self.valid = False
            self.frame_bytes = 0
        else:
            self.frame_bytes = fbytes
        if not self.full and not self.base_ok:
            self.valid = False
        self.npal = npal
        pal = p[START_BYTES:START_BYTES + 3 * npal]
        self.palette = [tuple(pal[i:i + 3]) for i in range(0, len(pal), 3)]
        return None

    def _on_band(self, p):
        n = len(p)
        if n < BAND_HDR or p[5] > 2:
            return self._bad("bad band header")
        f = int.from_bytes(p[1:3], "big")
        y0 = int.from_bytes(p[3:5], "big")
        self.packets += 1
        if not self.in_frame or f != self.frame:
            self._orphan(f)
            return None
        if y0 >= self.height or y0 % self.band:
            self.packets -= 1
            self.valid = False
            return self._bad("band row %d outside the frame" % y0)
        self.nbands_got += 1
        if not self.valid:
            return None
        rows = min(self.height - y0, self.band)
        off = fb_bytes(self.format, self.width, y0)
        bb = fb_bytes(self.format, self.width, rows)
        try:
            data = _codec.decode(p[5], p[BAND_HDR:], limit=bb)
        except CodecError as e:
            self.valid = False
            return self._bad(str(e))
        # the C decoder writes what it decoded before failing on length
        self.fb[off:off + len(data)] = data
        if len(data) != bb:
            self.valid = False
            return self._bad("band decodes to %d bytes, not %d" % (len(data), bb))
        return None

    def _on_end(self, p):
        if len(p) != END_BYTES:
            return self._bad("bad frame end")
        f = int.from_bytes(p[1:3], "big")
        self.packets += 1
        if not self.in_frame or f != self.frame:
            self._orphan(f)
            return None
        if (not self.valid or int.from_bytes(p[3:5], "big") != self.nbands_got or
                crc16(self.fb[:self.frame_bytes]) != int.from_bytes(p[5:7], "big")):
            self._frame_fail()
            return None
        self.in_frame = False
        self.base_ok = True
        self.need_full = False
        self.frames += 1
        self.raw_bytes += self.frame_bytes
        fr = Frame(f, self.width, self.height, self.format,
                   bytes(self.fb[:self.frame_bytes]), list(self.palette),
                   self.full, self._since)
        self._since = 0
        return fr


class Encoder:
    """The C band encoder (src/wire.c) in Python: same bytes out."""

    def __init__(self, fmt, width, height, band, codec=_codec.RLE,
                 full_period=32, dirty=True, palette=None):
        self.fmt, self.width, self.height, self.band = fmt, width, height, band
        self.codec = codec
        self.full_period = full_period
        self.dirty = dirty
        self.palette = palette or []
        self.nbands = (height + band - 1) // band
        self.fp = [b"\0\0\0\0"] * self.nbands
        self.since_full = 0
        self.want_full = True

    def sync(self):
        return b"\x00"

    def request_full(self):
        self.want_full = True

    @staticmethod
    def _fingerprint(data):
        f1 = f2 = 0
        for b in data:
            f1 = (f1 + b) & 0xFF
            f2 = (f2 + f1) & 0xFF
        return crc16(data).to_bytes(2, "big") + bytes([f1, f2])

    def frame(self, number, pixels):
        """Encode one whole frame (raw framebuffer bytes) -> stream bytes."""
        if self.full_period and self.since_full >= self.full_period:
            self.want_full = True
        full = self.want_full or not self.dirty
        if full:
            self.want_full = False
            self.since_full = 0
        self.since_full += 1
        out = bytearray()
        pal = b"".join(bytes(c) for c in self.palette)
        body = bytes([PKT_FRAME_START, VERSION]) + number.to_bytes(2, "big")
        body += self.width.to_bytes(2, "big") + self.height.to_bytes(2, "big")
        body += bytes([self.fmt]) + self.band.to_bytes(2, "big")
        body += bytes([self.codec, FLAG_FULL if full else 0, len(self.palette)]) + pal
        out += packet(body)
        sent = 0
        for i in range(self.nbands):
            y0 = i * self.band
            rows = min(self.band, self.height - y0)
            off = fb_bytes(self.fmt, self.width, y0)
            data = bytes(pixels[off:off + fb_bytes(self.fmt, self.width, rows)])
            fp = self._fingerprint(data)
            changed = fp != self.fp[i]
            self.fp[i] = fp
            if not full and not changed:
                continue
            codec = self.codec
            enc = _codec.encode(codec, data) if codec != _codec.RAW else None
            if enc is None or len(enc) > len(data) - 1:
                codec, enc = _codec.RAW, data
            out += packet(bytes([PKT_BAND]) + number.to_bytes(2, "big") +
                          y0.to_bytes(2, "big") + bytes([codec]) + enc)
            sent += 1
        out += packet(bytes([PKT_FRAME_END]) + number.to_bytes(2, "big") +
                      sent.to_bytes(2, "big") + crc16(pixels).to_bytes(2, "big"))
        return bytes(out)


def read_dump(path_or_bytes):
    """Frames from rast8-emu --dump (or rast8-codec dec): list of Frame."""
    if isinstance(path_or_bytes, (bytes, bytearray)):
        data = bytes(path_or_bytes)
    else:
        with open(path_or_bytes, "rb") as f:
            data = f.read()
    frames = []
    i = 0
    while i < len(data):
        if data[i:i + 4] != b"R8FB" or len(data) - i < 12:
            raise ValueError("bad dump record at offset %d" % i)
        num = int.from_bytes(data[i + 4:i + 6], "big")
        w = int.from_bytes(data[i + 6:i + 8], "big")
        h = int.from_bytes(data[i + 8:i + 10], "big")
        fmt = data[i + 10]
        n = fb_bytes(fmt, w, h)
        px = data[i + 12:i + 12 + n]
        if len(px) != n:
            raise ValueError("truncated dump record at offset %d" % i)
        frames.append(Frame(num, w, h, fmt, px))
        i += 12 + n
    return frames
