"""The seed's RLE and LZ77 codecs, CRC-16/CCITT-FALSE and COBS.

Byte-for-byte the same as the C library (src/rle.c, src/lz77.c,
src/crc16.c, src/cobs.c); tests/vectors/ holds the shared vectors.
"""
import binascii

RAW, RLE, LZ77 = 0, 1, 2
CODEC_NAMES = {"raw": RAW, "rle": RLE, "lz77": LZ77}
CODEC_BY_ID = {v: k for k, v in CODEC_NAMES.items()}

RLE_MAX = 127
LZ77_WINDOW = 1024      # must match R8_LZ77_WINDOW
LZ77_MIN_MATCH = 5      # must match R8_LZ77_MIN_MATCH


class CodecError(ValueError):
    """Malformed or truncated input, or output larger than allowed."""


def rle_bound(n):
    return n + (n + 126) // 127


def rle_encode(data):
    data = bytes(data)
    n = len(data)
    out = bytearray()
    i = lit = 0

    def flush(start, length):
        if length:
            out.append(0x80 | length)
            out.extend(data[start:start + length])

    while i < n:
        run = 1
        b = data[i]
        while i + run < n and run < RLE_MAX and data[i + run] == b:
            run += 1
        if run >= 3:
            flush(i - lit, lit)
            lit = 0
            out.append(run)
            out.append(b)
            i += run
        else:
            lit += 1
            i += 1
            if lit == RLE_MAX:
                flush(i - lit, lit)
                lit = 0
    flush(i - lit, lit)
    return bytes(out)


def rle_decode(data, limit=None):
    """Decode; raise CodecError on a 0x00/0x80 count, a truncated run, or
    output beyond `limit` bytes."""
    data = bytes(data)
    out = bytearray()
    i, n = 0, len(data)
    while i < n:
        c = data[i]
        i += 1
        cnt = c & 0x7F
        if cnt == 0:
            raise CodecError("rle: count byte 0x%02x at %d" % (c, i - 1))
        if c & 0x80:
            if n - i < cnt:
                raise CodecError("rle: raw run truncated at %d" % (i - 1))
            chunk = data[i:i + cnt]
            i += cnt
        else:
            if i >= n:
                raise CodecError("rle: repeat truncated at %d" % (i - 1))
            chunk = bytes([data[i]]) * cnt
            i += 1
        if limit is not None and len(out) + cnt > limit:
            raise CodecError("rle: output larger than %d" % limit)
        out.extend(chunk)
    return bytes(out)


def lz77_bound(n):
    return n + 2 * ((n + 32766) // 32767)


def lz77_encode(data, window=LZ77_WINDOW):
    data = bytes(data)
    n = len(data)
    out = bytearray()
    i = lit = 0

    def flush(start, length):
        while length:
            part = min(length, 32767)
            out.extend(part.to_bytes(2, "big"))
            out.extend(data[start:start + part])
            start += part
            length -= part

    while i < n:
        best = dist = 0
        lim = min(n - i, 65535)
        j = i - window if i > window else 0
        # brute force, as the C encoder; bytes.find would not give the
        # same tie-break on every input
        while j < i:
            l = 0
            while l < lim and data[j + l] == data[i + l]:
                l += 1
            if l >= best and l > 0:
                best, dist = l, i - j
            j += 1
        need = LZ77_MIN_MATCH + 2 if lit else LZ77_MIN_MATCH
        if best >= need:
            flush(i - lit, lit)
            lit = 0
            out.extend(((-dist) & 0xFFFF).to_bytes(2, "big"))
            out.extend(best.to_bytes(2, "big"))
            i += best
        else:
            lit += 1
            i += 1
    flush(i - lit, lit)
    return bytes(out)


def lz77_decode(data, limit=None):
    data = bytes(data)
    out = bytearray()
    i, n = 0, len(data)
    while i < n:
        if n - i < 2:
            raise CodecError("lz77: word truncated at %d" % i)
        w = int.from_bytes(data[i:i + 2], "big")
        i += 2
        if w == 0:
            raise CodecError("lz77: zero word at %d" % (i - 2))
        if w < 0x8000:
            if n - i < w:
                raise CodecError("lz77: literal run truncated at %d" % (i - 2))
            if limit is not None and len(out) + w > limit:
                raise CodecError("lz77: output larger than %d" % limit)
            out.extend(data[i:i + w])
            i += w
        else:
            dist = 0x10000 - w
            if n - i < 2:
                raise CodecError("lz77: length truncated at %d" % i)
            ln = int.from_bytes(data[i:i + 2], "big")
            i += 2
            if ln == 0 or dist > len(out):
                raise CodecError("lz77: bad back-reference at %d" % (i - 4))
            if limit is not None and len(out) + ln > limit:
                raise CodecError("lz77: output larger than %d" % limit)
            start = len(out) - dist
            if ln <= dist:
                out.extend(out[start:start + ln])
            else:
                for k in range(ln):
                    out.append(out[start + k])
    return bytes(out)


def encode(codec, data):
    if codec == RAW:
        return bytes(data)
    if codec == RLE:
        return rle_encode(data)
    if codec == LZ77:
        return lz77_encode(data)
    raise CodecError("unknown codec %r" % codec)


def decode(codec, data, limit=None):
    if codec == RAW:
        if limit is not None and len(data) > limit:
            raise CodecError("raw: output larger than %d" % limit)
        return bytes(data)
    if codec == RLE:
        return rle_decode(data, limit)
    if codec == LZ77:
        return lz77_decode(data, limit)
    raise CodecError("unknown codec %r" % codec)


# ---- CRC-16/CCITT-FALSE: poly 0x1021, init 0xFFFF, no reflection: the
# standard library's binascii.crc_hqx with init 0xFFFF.
def crc16(data, crc=0xFFFF):
    return binascii.crc_hqx(data, crc)


# ---- COBS
def cobs_encode(data):
    data = bytes(data)
    out = bytearray([0])
    code_at = 0
    code = 1
    n = len(data)
    for i, b in enumerate(data):
        if b == 0:
            out[code_at] = code
            code_at = len(out)
            out.append(0)
            code = 1
        else:
            out.append(b)
            code += 1
            if code == 0xFF and i + 1 < n:
                out[code_at] = code
                code_at = len(out)
                out.append(0)
                code = 1
    out[code_at] = code
    return bytes(out)


def cobs_decode(data):
    data = bytes(data)
    if b"\x00" in data:
        raise CodecError("cobs: zero byte inside a packet")
    out = []
    i, n = 0, len(data)
    while i < n:
        code = data[i]
        j = i + code
        if j > n:
            raise CodecError("cobs: block truncated")
        out.append(data[i + 1:j])
        if code != 0xFF and j < n:
            out.append(b"\x00")
        i = j
    return b"".join(out)
