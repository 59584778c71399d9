"""Shared codec vectors (tests/vectors/codec.txt) and the C header made
from them (tests/vectors/vectors.h), so C and Python check the same bytes.

    python -m rast8.vectors tests/vectors/codec.txt tests/vectors/vectors.h
"""
import sys


def _plain_bytes(tokens):
    out = bytearray()
    for tok in tokens:
        if tok == "-":
            continue
        if "*" in tok:
            b, n = tok.split("*")
            out.extend(bytes([int(b, 16)]) * int(n))
        elif ".." in tok:
            a, b = tok.split("..")
            out.extend(range(int(a, 16), int(b, 16) + 1))
        else:
            out.extend(bytes.fromhex(tok))    # 2, 4, ... hex digits
    return out


def parse_bytes(text):
    """Hex bytes; XX*N repeats, XX..YY counts; [ body ] is one packet:
    body + CRC-16, COBS-encoded, then the 0x00 delimiter."""
    from .codec import crc16, cobs_encode
    out = bytearray()
    rest = text.replace("[", " [ ").replace("]", " ] ").split()
    i = 0
    while i < len(rest):
        if rest[i] == "[":
            j = rest.index("]", i)
            body = bytes(_plain_bytes(rest[i + 1:j]))
            out += cobs_encode(body + crc16(body).to_bytes(2, "big")) + b"\x00"
            i = j + 1
        else:
            j = i
            while j < len(rest) and rest[j] != "[":
                j += 1
            out += _plain_bytes(rest[i:j])
            i = j
    return bytes(out)


DEC_COUNTERS = ("bad", "dropped", "incomplete", "skipped", "ignored")


def parse_expect(kind, text):
    """dec: fb=N frames=a,b,... [bad= dropped= incomplete= skipped= ignored=]
    (counters not given are 0); dev: requests= inputs= keys=HEX."""
    kv = dict(t.split("=", 1) for t in text.split())
    if kind == "dec":
        e = {"fb": int(kv["fb"]),
             "frames": [int(x) for x in kv.get("frames", "").split(",") if x]}
        for c in DEC_COUNTERS:
            e[c] = int(kv.get(c, 0))
        return e
    return {"requests": int(kv.get("requests", 0)), "inputs": int(kv.get("inputs", 0)),
            "keys": int(kv.get("keys", "0"), 16)}


def expect_bytes(kind, e):
    """The expectation packed for vectors.h (big-endian):
    dec: fb:2 nframes:1 frame:2... bad:2 dropped:2 incomplete:2 skipped:2
    ignored:2;  dev: requests:1 inputs:1 keys:2."""
    if kind == "dec":
        out = e["fb"].to_bytes(2, "big") + bytes([len(e["frames"])])
        out += b"".join(f.to_bytes(2, "big") for f in e["frames"])
        return out + b"".join(e[c].to_bytes(2, "big") for c in DEC_COUNTERS)
    return bytes([e["requests"], e["inputs"]]) + e["keys"].to_bytes(2, "big")


def load(path):
    """List of dicts: kind, name, input (bytes), output (bytes) or
    error ('MALFORMED' / 'TRUNC' / 'SPACE') and limit (int or None)."""
    vecs = []
    with open(path) as f:
        for ln, line in enumerate(f, 1):
            line = line.strip()
            if not line or line.startswith("#"):
                continue
            head, inp, outp = [p.strip() for p in line.split("|")]
            kind, name = head.split()
            v = {"kind": kind, "name": name, "input": parse_bytes(inp), "line": ln,
                 "output": None, "error": None, "limit": None}
            if kind in ("dec", "dev"):
                v["expect"] = parse_expect(kind, outp)
                v["output"] = expect_bytes(kind, v["expect"])
            elif kind.endswith("_bad"):
                err = outp.split(":")
                v["error"] = err[0]
                if len(err) > 1:
                    v["limit"] = int(err[1])
            else:
                v["output"] = parse_bytes(outp)
            vecs.append(v)
    return vecs


KIND_IDS = {"rle": 1, "lz77": 2, "lz77_dec": 3, "cobs": 4, "crc": 5,
            "rle_bad": 6, "lz77_bad": 7, "cobs_bad": 8, "stream": 9,
            "dec": 10, "dev": 11}
ERR_IDS = {"SPACE": -1, "MALFORMED": -2, "TRUNC": -3}


def c_header(vecs):
    lines = ["/* vectors.h - GENERATED from tests/vectors/codec.txt by",
             " *   python -m rast8.vectors tests/vectors/codec.txt tests/vectors/vectors.h",
             " * Do not edit.  Kinds: VK_*; err is R8_E_* for *_bad kinds. */",
             "#ifndef R8_TEST_VECTORS_H", "#define R8_TEST_VECTORS_H", ""]
    for k, i in KIND_IDS.items():
        lines.append("#define VK_%s %d" % (k.upper(), i))
    lines += ["", "typedef struct tvec {", "    const char *name;", "    int kind;",
              "    const unsigned char *in;", "    unsigned in_len;",
              "    const unsigned char *out;", "    unsigned out_len;",
              "    int err;", "    unsigned limit;", "} tvec;", ""]

    def arr(name, data):
        if not data:
            return "static const unsigned char %s[1] = { 0 };" % name
        body = ", ".join("0x%02X" % b for b in data)
        # wrap at ~16 per line
        parts = body.split(", ")
        rows = [", ".join(parts[i:i + 16]) for i in range(0, len(parts), 16)]
        return "static const unsigned char %s[%d] = {\n    %s\n};" % (
            name, len(data), ",\n    ".join(rows))

    for i, v in enumerate(vecs):
        lines.append(arr("tv_in_%d" % i, v["input"]))
        lines.append(arr("tv_out_%d" % i, v["output"] or b""))
    lines.append("")
    lines.append("static const tvec tvecs[] = {")
    for i, v in enumerate(vecs):
        lines.append('    { "%s", VK_%s, tv_in_%d, %du, tv_out_%d, %du, %d, %du },' % (
            v["name"], v["kind"].upper(), i, len(v["input"]), i,
            len(v["output"] or b""), ERR_IDS.get(v["error"], 0),
            v["limit"] if v["limit"] is not None else 0xFFFF))
    lines.append("};")
    lines.append("#define TVEC_COUNT (sizeof tvecs / sizeof tvecs[0])")
    lines.append("")
    lines.append("#endif")
    return "\n".join(lines) + "\n"


def main(argv=None):
    argv = sys.argv[1:] if argv is None else argv
    if len(argv) != 2:
        print("usage: python -m rast8.vectors codec.txt vectors.h", file=sys.stderr)
        return 2
    text = c_header(load(argv[0]))
    with open(argv[1], "w") as f:
        f.write(text)
    return 0


if __name__ == "__main__":
    sys.exit(main())
