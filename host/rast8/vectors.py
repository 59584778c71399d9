"""Shared codec vectors (tests/vectors/codec.txt) and the C header made
from them (tests/vectors/vectors.h), so C and Python check the same bytes.

    python -m rast8.vectors tests/vectors/codec.txt tests/vectors/vectors.h
"""
import sys


def parse_bytes(text):
    out = bytearray()
    for tok in text.split():
        if tok == "-":
            continue
        if "*" in tok:
            b, n = tok.split("*")
            out.extend(bytes([int(b, 16)]) * int(n))
        elif ".." in tok:
            a, b = tok.split("..")
            out.extend(range(int(a, 16), int(b, 16) + 1))
        else:
            out.append(int(tok, 16))
    return bytes(out)


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
            if kind.endswith("_bad"):
                err = outp.split(":")
                v["error"] = err[0]
                if len(err) > 1:
                    v["limit"] = int(err[1])
            else:
                v["output"] = parse_bytes(outp)
            vecs.append(v)
    return vecs


KIND_IDS = {"rle": 1, "lz77": 2, "lz77_dec": 3, "cobs": 4, "crc": 5,
            "rle_bad": 6, "lz77_bad": 7, "cobs_bad": 8, "stream": 9}
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
