"""The band codecs (the seed's RLE and LZ77, static Huffman, LZW),
CRC-16/CCITT-FALSE and COBS.

Byte-for-byte the same as the C library (src/rle.c, src/lz77.c,
src/huff.c, src/lzw.c, src/crc16.c, src/cobs.c); tests/vectors/ holds the
shared vectors.
"""
import binascii

from .hufftab import HUFF_LEN

RAW, RLE, LZ77, HUFF, LZW = 0, 1, 2, 3, 4
BEST = 0x0F             # not a wire id: the smallest codec per band
CODEC_COUNT = 5
CODEC_NAMES = {"raw": RAW, "rle": RLE, "lz77": LZ77, "huff": HUFF, "lzw": LZW}
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


# ---- static canonical Huffman (docs/protocol.md 3.4)
HUFF_MAXLEN = 12


def _huff_tables():
    order = sorted(range(256), key=lambda s: (HUFF_LEN[s], s))
    codes = [0] * 256
    code = prev = 0
    for s in order:
        code <<= HUFF_LEN[s] - prev
        prev = HUFF_LEN[s]
        codes[s] = code
        code += 1
    # decoding: (length, code) -> byte
    return codes, {(HUFF_LEN[s], codes[s]): s for s in range(256)}


HUFF_CODE, _HUFF_DEC = _huff_tables()


def huff_bound(n):
    return n + (n + 1) // 2


def huff_encode(data):
    bits = "".join(format(HUFF_CODE[b], "0%db" % HUFF_LEN[b]) for b in bytes(data))
    bits += "1" * (-len(bits) % 8)
    return int(bits, 2).to_bytes(len(bits) // 8, "big") if bits else b""


def huff_decode(data, limit=None):
    data = bytes(data)
    out = bytearray()
    nbits = 8 * len(data)
    val = int.from_bytes(data, "big") if data else 0
    pos = 0
    while pos < nbits:
        rest = nbits - pos
        if rest < 8 and val & ((1 << rest) - 1) == (1 << rest) - 1:
            break                       # the padding: 1..7 one bits
        code = 0
        for ln in range(1, HUFF_MAXLEN + 1):
            if pos >= nbits:
                raise CodecError("huff: code truncated at bit %d" % pos)
            code = (code << 1) | ((val >> (nbits - 1 - pos)) & 1)
            pos += 1
            sym = _HUFF_DEC.get((ln, code))
            if sym is not None:
                break
        else:
            raise CodecError("huff: no code at bit %d" % pos)   # (a complete code: never)
        if limit is not None and len(out) + 1 > limit:
            raise CodecError("huff: output larger than %d" % limit)
        out.append(sym)
    return bytes(out)


# ---- LZW, 9-bit codes, 128 entries (docs/protocol.md 3.5)
LZW_DICT = 128
LZW_BITS = 9


def lzw_bound(n):
    return n + (n + 7) // 8


def lzw_encode(data):
    data = bytes(data)
    n = len(data)
    plen = []               # phrase lengths; entry d = data[start(d): start(d) + plen[d] + 1]
    starts = []
    codes = []
    i = 0
    while i < n:
        best, code = 1, data[i]
        for d in range(min(len(codes), LZW_DICT)):
            el = plen[d] + 1
            st = starts[d]
            if el > best and el <= n - i and data[st:st + el] == data[i:i + el]:
                best, code = el, 256 + d
        if len(codes) < LZW_DICT:
            plen.append(best)
            starts.append(i)
        codes.append(code)
        i += best
    bits = "".join(format(c, "09b") for c in codes)
    bits += "0" * (-len(bits) % 8)
    return int(bits, 2).to_bytes(len(bits) // 8, "big") if bits else b""


def lzw_decode(data, limit=None):
    data = bytes(data)
    nbits = 8 * len(data)
    val = int.from_bytes(data, "big") if data else 0
    out = bytearray()
    plen, starts = [], []
    pos = p = 0
    while nbits - pos >= LZW_BITS:
        code = (val >> (nbits - pos - LZW_BITS)) & 0x1FF
        pos += LZW_BITS
        start = len(out)
        if code < 256:
            el = 1
            if limit is not None and len(out) + 1 > limit:
                raise CodecError("lzw: output larger than %d" % limit)
            out.append(code)
        else:
            d = code - 256
            if d >= p or d >= LZW_DICT:
                raise CodecError("lzw: code %d before its entry at bit %d" % (code, pos - LZW_BITS))
            el = plen[d] + 1
            if limit is not None and len(out) + el > limit:
                raise CodecError("lzw: output larger than %d" % limit)
            st = starts[d]
            for k in range(el):
                out.append(out[st + k])
        if p < LZW_DICT:
            plen.append(el)
            starts.append(start)
        p += 1
    if nbits - pos >= 8:
        raise CodecError("lzw: code truncated at bit %d" % pos)
    if val & ((1 << (nbits - pos)) - 1):
        raise CodecError("lzw: padding bits not 0")
    return bytes(out)


def best_encode(data):
    """(codec, payload) of the smallest payload, ties to the lower id (src/wire.c
    tx_more); (RAW, data) when no codec makes it smaller."""
    data = bytes(data)
    best, enc = RAW, data
    for c in (RLE, LZ77, HUFF, LZW):
        e = encode(c, data)
        if len(e) < len(enc):
            best, enc = c, e
    return best, enc


def encode(codec, data):
    if codec == RAW:
        return bytes(data)
    if codec == RLE:
        return rle_encode(data)
    if codec == LZ77:
        return lz77_encode(data)
    if codec == HUFF:
        return huff_encode(data)
    if codec == LZW:
        return lzw_encode(data)
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
    if codec == HUFF:
        return huff_decode(data, limit)
    if codec == LZW:
        return lzw_decode(data, limit)
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
