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
import binascii
from dataclasses import dataclass, field

from . import codec as _codec
from .codec import crc16, CodecError
from .formats import FMT_PAGE1, FMT_ROW1, FMT_IDX8, FORMAT_NAMES, FORMAT_BY_ID  # noqa: F401

VERSION = 1          # what Encoder writes by default (R8_WIRE_VERSION)
VERSION2 = 2         # FRAME_END carries a CRC-32 of the frame (section 4.1)
VERSIONS = (VERSION, VERSION2)    # what the decoders accept
PKT_FRAME_START, PKT_BAND, PKT_FRAME_END, PKT_REQUEST = 0x01, 0x02, 0x03, 0x10
PKT_INPUT = 0x11
PKT_TO_DEVICE_FIRST, PKT_TO_DEVICE_LAST = 0x10, 0x1F     # display -> device kinds
# INPUT key bits (docs/protocol.md section 2.1), 1 = pressed
KEY_BITS = {"up": 0x0001, "down": 0x0002, "left": 0x0004, "right": 0x0008,
            "a": 0x0010, "b": 0x0020, "start": 0x0040, "select": 0x0080,
            "x": 0x0100, "y": 0x0200, "l": 0x0400, "r": 0x0800}
FLAG_FULL = 0x01
START_BYTES, BAND_HDR, END_BYTES, CRC_BYTES = 14, 6, 7, 2
END2_BYTES = 9                       # FRAME_END body, version 2
MAX_DIM = 4095
MAX_BAND = 32767


def fb_bytes(fmt, width, rows):
    """Bytes of `rows` rows of a `width`-wide frame (include/r8fb.h)."""
    if fmt == FMT_PAGE1:
        return width * ((rows + 7) >> 3)
    if fmt == FMT_ROW1:
        return ((width + 7) >> 3) * rows
    return width * rows


def crc32(data):
    """CRC-32 (ISO-HDLC, zlib's): the version-2 frame check (r8_crc32)."""
    return binascii.crc32(data) & 0xFFFFFFFF


def frame_check(version, pixels):
    """FRAME_END's fcrc field for a frame: CRC-16 (version 1) or CRC-32
    (version 2) of its raw bytes."""
    if version == VERSION2:
        return crc32(pixels).to_bytes(4, "big")
    return crc16(pixels).to_bytes(2, "big")


def pkt_bytes(band_bytes, npal):
    """R8_WIRE_PKT_BYTES: the largest packet body + CRC."""
    return max(band_bytes + BAND_HDR, START_BYTES + 3 * npal) + CRC_BYTES


def request_packet():
    """The display -> device REQUEST (send a full frame), with delimiters."""
    body = bytes([PKT_REQUEST])
    body += crc16(body).to_bytes(2, "big")
    return b"\x00" + _codec.cobs_encode(body) + b"\x00"


def input_packet(keys):
    """The display -> device INPUT packet (key state, KEY_BITS), with
    delimiters: r8_dec_input() in C."""
    if not 0 <= keys <= 0xFFFF:
        raise ValueError("keys must be a 16-bit mask, not %r" % (keys,))
    body = bytes([PKT_INPUT]) + keys.to_bytes(2, "big")
    body += crc16(body).to_bytes(2, "big")
    return b"\x00" + _codec.cobs_encode(body) + b"\x00"


def parse_to_device(data):
    """What a device (r8_tx_rx) makes of display -> device bytes: a list
    of ("request", None) / ("input", keys) for each valid packet; other
    packets are ignored, as the device ignores them."""
    out = []
    for raw in bytes(data).split(b"\x00"):
        if not raw:
            continue
        try:
            body = _codec.cobs_decode(raw)
        except CodecError:
            continue
        if len(body) < 3 or crc16(body[:-2]) != int.from_bytes(body[-2:], "big"):
            continue
        body = body[:-2]
        if body[0] == PKT_REQUEST and len(body) == 1:
            out.append(("request", None))
        elif body[0] == PKT_INPUT and len(body) == 3:
            out.append(("input", int.from_bytes(body[1:3], "big")))
    return out


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
    """Decoder with fixed limits, as src/decoder.c: same packets accepted,
    same frames good, same counters (docs/protocol.md sections 4, 5).
    It works a packet at a time (bytes.find for the delimiters) instead
    of a byte at a time; the result is the same.

    max_frame_bytes plays the C decoder's fb_size; packets longer than
    pkt_bytes(max_frame_bytes, 256) are dropped (counted bad)."""

    def __init__(self, max_frame_bytes=65536):
        self.fb_size = max_frame_bytes
        self.pkt_size = pkt_bytes(max_frame_bytes, 256)
        # raw (COBS) bytes beyond this always decode to more than pkt_size
        self._raw_cap = self.pkt_size + self.pkt_size // 254 + 4
        self.fb = bytearray(max_frame_bytes)
        self._pkt = bytearray()        # raw bytes of the packet so far
        self._overflow = False
        self.synced = False
        self.in_frame = False
        self.full = False
        self.format = self.codec = 0
        self.valid = False
        self.npal = 0
        self.version = 0
        self.palette = []
        self.frame = 0
        self.nbands_got = 0
        self.width = self.height = self.band = 0
        self.next_y = self.last_y0 = 0
        self.start_crc = self.band_crc = 0
        self.last_seen = 0
        self.have_last = False
        self.base_ok = False
        self.good_no = 0
        self.ever_good = False
        self.failed_no = None
        self.need_full = False
        self.frame_bytes = 0
        # counters
        self.bytes = 0
        self.packets = 0
        self.bad_packets = 0
        self.frames = 0
        self.dropped = 0
        self.incomplete = 0
        self.skipped = 0
        self.ignored = 0
        self.raw_bytes = 0             # raw bytes of good frames
        self._since = 0                # stream bytes since the last good frame
        self.errors = []               # last few error descriptions

    def counters(self):
        return {"bytes": self.bytes, "packets": self.packets,
                "bad_packets": self.bad_packets, "frames": self.frames,
                "dropped": self.dropped, "incomplete": self.incomplete,
                "skipped": self.skipped, "ignored": self.ignored}

    # ---- byte level
    def feed(self, data):
        """Feed bytes; returns the list of good frames they completed."""
        data = bytes(data)
        n = len(data)
        out = []
        self.bytes += n
        i = 0
        mark = 0                       # wire bytes before `mark` are in _since
        if not self.synced:
            j = data.find(0)
            if j < 0:
                self._since += n
                return out             # before the first 0x00: a late join
            self.synced = True
            i = j + 1
            self._pkt.clear()
        find = data.find
        while True:
            j = find(0, i)
            if j < 0:
                if not self._overflow:
                    self._pkt += data[i:]
                    if len(self._pkt) > self._raw_cap:
                        self._overflow = True
                        self._pkt.clear()
                break
            if self._pkt:
                raw = bytes(self._pkt) + data[i:j]
                self._pkt.clear()
            else:
                raw = data[i:j]
            if self._overflow or len(raw) > self._raw_cap:
                self._overflow = False
                self._bad("framing: packet too long")
            elif raw:
                f = self._on_raw(raw)
                if f is not None:
                    f.wire_bytes = self._since + j + 1 - mark
                    self._since = 0
                    mark = j + 1
                    out.append(f)
            i = j + 1
        self._since += n - mark
        return out

    def finish(self):
        """End of input: an unterminated packet counts as bad, an open
        frame as incomplete (r8_dec_end)."""
        if self._pkt or self._overflow:
            self._bad("stream ends inside a packet (truncated)")
        self._pkt.clear()
        self._overflow = False
        if self.in_frame:
            self._frame_fail()

    def _on_raw(self, raw):
        try:
            p = _codec.cobs_decode(raw)
        except CodecError:
            return self._bad("framing: packet cut short")
        if len(p) > self.pkt_size:
            return self._bad("framing: packet too long")
        return self._on_packet(p)

    def _bad(self, why):
        self.bad_packets += 1
        self.errors = (self.errors + [why])[-8:]
        return None

    def _relation(self, f):
        if not self.have_last:
            return 1
        gap = (f - self.last_seen) & 0xFFFF
        if gap == 0:
            return 0
        return 1 if gap < 0x8000 else -1

    def _seen_frame(self, f):
        if self.have_last and self._relation(f) > 0:
            self.dropped += ((f - self.last_seen) & 0xFFFF) - 1
        self.last_seen = f
        self.have_last = True

    def _count_lost(self, f, delta):
        self.need_full = True
        if self.failed_no == f:
            return
        self.failed_no = f
        if delta and not self.ever_good:
            self.skipped += 1
        else:
            self.incomplete += 1

    def _frame_fail(self):
        if self.in_frame:
            self._count_lost(self.frame, not self.full)
        self.in_frame = False

    def _other_frame(self, f):
        rel = self._relation(f)
        if rel < 0 or (rel == 0 and not self.in_frame) or not self.have_last:
            self.ignored += 1          # late, a repeat, or joining
            return None
        self._frame_fail()             # a newer frame whose start was lost
        self._seen_frame(f)
        self._count_lost(f, False)
        return None

    # ---- packet level
    def _on_packet(self, p):
        n = len(p)
        if n < 1 + CRC_BYTES:
            return self._bad("crc")
        crc = (p[-2] << 8) | p[-1]
        p = p[:-2]
        if crc16(p) != crc:
            return self._bad("crc")
        t = p[0]
        if PKT_TO_DEVICE_FIRST <= t <= PKT_TO_DEVICE_LAST:
            self.packets += 1          # display -> device (an echo): ignore
            self.ignored += 1
            return None
        if t == PKT_FRAME_START:
            return self._on_start(p, crc)
        if t == PKT_BAND:
            return self._on_band(p, crc)
        if t == PKT_FRAME_END:
            return self._on_end(p)
        return self._bad("unknown packet type 0x%02x" % t)

    def _on_start(self, p, crc):
        n = len(p)
        if n < START_BYTES:
            return self._bad("short frame start")
        npal = p[13]
        w = (p[4] << 8) | p[5]
        h = (p[6] << 8) | p[7]
        fmt = p[8]
        band = (p[9] << 8) | p[10]
        codec = p[11]
        if (p[1] not in VERSIONS or n != START_BYTES + 3 * npal or fmt > FMT_IDX8 or
                codec >= _codec.CODEC_COUNT or w == 0 or h == 0 or w > MAX_DIM or h > MAX_DIM or
                band == 0 or band > h or (fmt == FMT_PAGE1 and band & 7)):
            return self._bad("bad frame start (version %d)" % p[1])
        f = (p[2] << 8) | p[3]
        self.packets += 1
        if self.in_frame and f == self.frame and crc == self.start_crc:
            self.ignored += 1          # the same FRAME_START again
            return None
        self._frame_fail()
        self._seen_frame(f)
        fbytes = fb_bytes(fmt, w, h)
        if (w, h, fmt, band) != (self.width, self.height, self.format, self.band):
            self.base_ok = False
        self.frame = f
        self.width, self.height, self.format, self.band = w, h, fmt, band
        self.codec = codec
        self.version = p[1]
        self.full = bool(p[12] & FLAG_FULL)
        self.start_crc = crc
        self.nbands_got = 0
        self.next_y = 0
        self.in_frame = True
        self.valid = True
        if fbytes > self.fb_size:
            self.valid = False
            self.frame_bytes = 0
        else:
            self.frame_bytes = fbytes
        if not self.full and (not self.base_ok or f != (self.good_no + 1) & 0xFFFF):
            self.valid = False
        self.npal = npal
        pal = p[START_BYTES:START_BYTES + 3 * npal]
        self.palette = [tuple(pal[i:i + 3]) for i in range(0, len(pal), 3)]
        return None

    def _on_band(self, p, crc):
        n = len(p)
        if n < BAND_HDR or p[5] >= _codec.CODEC_COUNT:
            return self._bad("bad band header")
        f = (p[1] << 8) | p[2]
        y0 = (p[3] << 8) | p[4]
        if not self.in_frame or f != self.frame:
            self.packets += 1
            return self._other_frame(f)
        if y0 >= self.height or y0 % self.band:
            self.valid = False
            return self._bad("band row %d outside the frame" % y0)
        self.packets += 1
        if self.nbands_got and y0 == self.last_y0 and crc == self.band_crc:
            self.ignored += 1          # the same BAND again
            return None
        if y0 < self.next_y:
            self.valid = False         # out of order
            return None
        self.nbands_got += 1
        self.last_y0 = y0
        self.band_crc = crc
        self.next_y = y0 + self.band
        if not self.valid:
            return None
        self.base_ok = False
        rows = min(self.height - y0, self.band)
        off = fb_bytes(self.format, self.width, y0)
        bb = fb_bytes(self.format, self.width, rows)
        try:
            data = _codec.decode(p[5], p[BAND_HDR:], limit=bb)
        except CodecError as e:
            self.valid = False
            self.packets -= 1
            return self._bad(str(e))
        # the C decoder writes what it decoded before failing on length
        self.fb[off:off + len(data)] = data
        if len(data) != bb:
            self.valid = False
            self.packets -= 1
            return self._bad("band decodes to %d bytes, not %d" % (len(data), bb))
        return None

    def _on_end(self, p):
        if len(p) not in (END_BYTES, END2_BYTES):
            return self._bad("bad frame end")
        f = (p[1] << 8) | p[2]
        self.packets += 1
        if not self.in_frame or f != self.frame:
            return self._other_frame(f)
        if (not self.valid or ((p[3] << 8) | p[4]) != self.nbands_got or
                (self.full and self.nbands_got != (self.height + self.band - 1) // self.band) or
                p[5:] != frame_check(self.version, memoryview(self.fb)[:self.frame_bytes])):
            self._frame_fail()
            return None
        self.in_frame = False
        self.base_ok = True
        self.good_no = f
        self.ever_good = True
        self.need_full = False
        self.frames += 1
        self.raw_bytes += self.frame_bytes
        return Frame(f, self.width, self.height, self.format,
                     bytes(self.fb[:self.frame_bytes]), list(self.palette),
                     self.full, 0)


class Encoder:
    """The C band encoder (src/wire.c) in Python: same bytes out."""

    def __init__(self, fmt, width, height, band, codec=_codec.RLE,
                 full_period=32, dirty=True, palette=None, version=VERSION):
        if version not in VERSIONS:
            raise ValueError("protocol version must be one of %r" % (VERSIONS,))
        self.version = version
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
        body = bytes([PKT_FRAME_START, self.version]) + number.to_bytes(2, "big")
        body += self.width.to_bytes(2, "big") + self.height.to_bytes(2, "big")
        body += bytes([self.fmt]) + self.band.to_bytes(2, "big")
        announced = _codec.RAW if self.codec == _codec.BEST else self.codec
        body += bytes([announced, FLAG_FULL if full else 0, len(self.palette)]) + pal
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
            if codec == _codec.BEST:
                codec, enc = _codec.best_encode(data)
            else:
                enc = _codec.encode(codec, data) if codec != _codec.RAW else None
            if enc is None or len(enc) > len(data) - 1:
                codec, enc = _codec.RAW, data
            out += packet(bytes([PKT_BAND]) + number.to_bytes(2, "big") +
                          y0.to_bytes(2, "big") + bytes([codec]) + enc)
            sent += 1
        out += packet(bytes([PKT_FRAME_END]) + number.to_bytes(2, "big") +
                      sent.to_bytes(2, "big") + frame_check(self.version, pixels))
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
