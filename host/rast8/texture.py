"""Textures for rast8 (docs/pipeline.md "Texture mapping"): PNG images to
flash textures, the built-in crate texture, texel fetches as the C
library does them (src/texture.c) for the float reference.

A texture is square, 8, 16, 32 or 64 texels a side, in one of two
formats (include/r8scene.h):
  1bpp  a row is side/8 bytes, MSB = leftmost texel, a set bit is lit
  idx8  one byte per texel, an index into a grey ramp 0 (black)..255
Texture coordinates in a mesh are bytes, 128 = one texture width, so a
face spans up to two repeats (the texture wraps)."""
import os
from dataclasses import dataclass

FMT_1BPP, FMT_IDX8 = 0, 1
FORMATS = {"1bpp": FMT_1BPP, "idx8": FMT_IDX8}
SIDES = (8, 16, 32, 64)


class TextureError(Exception):
    """A texture that cannot be used: the message says why."""


@dataclass
class Texture:
    name: str
    side: int
    fmt: int
    grey: bytes          # side * side grey levels 0..255, row-major

    def data(self):
        """The flash bytes of the texture in its format."""
        if self.fmt == FMT_IDX8:
            return bytes(self.grey)
        out = bytearray()
        for y in range(self.side):
            for x0 in range(0, self.side, 8):
                b = 0
                for k in range(8):
                    if self.grey[y * self.side + x0 + k] >= 128:
                        b |= 0x80 >> k
                out.append(b)
        return bytes(out)

    def texel(self, tu, tv):
        """Grey level 0..255 of texel (tu, tv), wrapped, as the C fetch."""
        s = self.side
        g = self.grey[(tv % s) * s + tu % s]
        if self.fmt == FMT_1BPP:
            return 255 if g >= 128 else 0
        return g

    def log2(self):
        return self.side.bit_length() - 1


def load_png(path, fmt="idx8", name=None):
    """A PNG (any mode PIL reads) as a texture; colour is turned to grey."""
    if fmt not in FORMATS:
        raise TextureError(f"{path}: unknown texture format '{fmt}' (1bpp, idx8)")
    try:
        from PIL import Image
        with Image.open(path) as im:
            im.load()
            grey = im.convert("L")
    except OSError as e:
        raise TextureError(f"{path}: cannot read the image ({e})") from None
    w, h = grey.size
    if w != h or w not in SIDES:
        raise TextureError(f"{path}: {w}x{h}: a texture is square, 8, 16, 32 or 64 texels a side")
    return Texture(name or os.path.splitext(os.path.basename(path))[0], w, FORMATS[fmt],
                   grey.tobytes())


def crate(side=32):
    """The built-in crate texture: a light frame of boards, planks with
    dark seams, and a diagonal brace (idx8)."""
    g = bytearray(side * side)
    b = max(2, side // 8)              # frame width
    for y in range(side):
        for x in range(side):
            edge = min(x, y, side - 1 - x, side - 1 - y)
            if edge < b:
                v = 200 if edge in (0, b - 1) else 230
                if edge == 0:
                    v = 90
            else:
                ph = max(1, (side - 2 * b) // 4)      # plank height
                v = 140 + 20 * (((y - b) // ph) % 2)
                if (y - b) % ph == 0:
                    v = 70        # the seam between two planks
                d = x - y
                if abs(d) <= b // 2 + 1:
                    v = 215 if abs(d) <= b // 2 else 100    # the brace
            g[y * side + x] = v
    return Texture("crate", side, FMT_IDX8, bytes(g))


def uv_byte(t):
    """A texture coordinate (1.0 = one texture width) as the mesh byte."""
    return max(0, min(255, round(t * 128)))


def to_c(tex, cid):
    """C lines: the texel data and the r8_texture struct named cid."""
    data = tex.data()
    out = [f"static const r8_u8 {cid}_d[{len(data)}] R8_FLASH = {{"]
    for k in range(0, len(data), 16):
        out.append("    " + ", ".join(str(x) for x in data[k:k + 16]) + ",")
    out.append("};")
    out.append(f"static const r8_texture {cid} = {{{cid}_d, {tex.log2()}, {tex.log2()}, {tex.fmt}}};")
    return out
