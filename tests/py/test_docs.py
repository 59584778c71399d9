"""docs/protocol.md's worked byte examples are what the code produces."""
import os
import re

from rast8.protocol import Encoder, request_packet, VERSIONS
from rast8 import codec as C
from conftest import ROOT

DOC = open(os.path.join(ROOT, "docs", "protocol.md")).read()


def block(tag):
    m = re.search(r"<!-- %s -->\n```\n(.*?)```" % tag, DOC, re.S)
    assert m, tag
    return bytes.fromhex(m.group(1).replace("\n", " "))


def test_example_stream():
    px = bytes([0] * 6 + [0xFF] * 4 + [0] * 6)
    enc = Encoder(0, 16, 8, 8, C.RLE, full_period=32, dirty=True)
    assert block("example-stream-0") == enc.sync() + enc.frame(0, px)
    assert block("example-stream-1") == enc.frame(1, px)
    enc2 = Encoder(0, 16, 8, 8, C.RLE, full_period=32, dirty=True, version=2)
    assert block("example-stream-v2") == enc2.sync() + enc2.frame(0, px)


def test_request_bytes_and_version():
    assert "`00 04 10 F3 C1 00`" in DOC
    assert request_packet() == bytes.fromhex("000410F3C100")
    assert DOC.startswith("# rast8 serial display protocol — versions %s\n"
                          % " and ".join(str(v) for v in VERSIONS))


def test_seed_examples_in_doc():
    assert C.rle_encode(bytes([1] + [3] * 9 + [8, 7, 6, 5])).hex(" ").upper() in DOC
    seed = bytes.fromhex("0005 0102030405 FFFC 0003 0002 0302 FFF6 0002 FFFB 0005".replace(" ", ""))
    assert C.lz77_decode(seed) == bytes([1, 2, 3, 4, 5, 2, 3, 4, 3, 2, 1, 2, 4, 3, 2, 1, 2])


def test_input_example_bytes():
    from rast8.protocol import input_packet, KEY_BITS
    m = re.search(r"<!-- input-example -->`([0-9A-F ]+)`", DOC)
    assert m and bytes.fromhex(m.group(1)) == input_packet(KEY_BITS["a"] | KEY_BITS["left"])


def test_every_vector_named_in_the_spec_exists():
    from rast8.vectors import load
    from conftest import VECTORS
    names = {"%s %s" % (v["kind"], v["name"]) for v in load(os.path.join(VECTORS, "codec.txt"))}
    cited = set(re.findall(r"`((?:dec|dev) [a-z0-9_]+)`", DOC.replace("\n", " ")))
    cited |= {"%s %s" % m for m in re.findall(r"`(dec|dev)\s+([a-z0-9_]+)`", DOC)}
    cited = {c for c in cited if not c.endswith("_")}
    assert cited and cited <= names, sorted(cited - names)


def test_seed_table_names_real_files():
    import glob
    doc = open(os.path.join(ROOT, "docs", "pipeline.md")).read()
    part = doc.split("## The seed's algorithms", 1)[1].split("\n## ", 1)[0]
    rows = [l for l in part.splitlines() if l.startswith("| ") and "---" not in l][1:]
    assert len(rows) >= 14
    for row in rows:
        cells = [c.strip() for c in row.strip("|").split("|")]
        assert cells[1].split(" (")[0].split(",")[0] in ("built", "not built"), row
        for path in re.findall(r"`([^`]+)`", cells[2]):
            assert glob.glob(os.path.join(ROOT, path)), (row, path)
