"""Frames to PIL images (layouts from include/r8fb.h)."""
from PIL import Image

from .formats import FMT_PAGE1, FMT_ROW1, FMT_IDX8


def frame_to_image(frame, scale=1):
    """A PIL image of a Frame: 1 bpp formats as mode 'L' (lit = 255),
    IDX8 as 'RGB' through the frame's palette (indices past the palette
    show as grey level = index)."""
    w, h, px = frame.width, frame.height, frame.pixels
    if frame.format == FMT_PAGE1:
        out = bytearray(w * h)
        for page in range((h + 7) // 8):
            row = px[page * w:(page + 1) * w]
            for bit in range(8):
                y = page * 8 + bit
                if y >= h:
                    break
                m = 1 << bit
                base = y * w
                out[base:base + w] = bytes(255 if b & m else 0 for b in row)
        img = Image.frombytes("L", (w, h), bytes(out))
    elif frame.format == FMT_ROW1:
        stride = (w + 7) // 8
        # PIL mode '1' raw is MSB-first rows padded to bytes: the ROW1 layout
        img = Image.frombytes("1", (w, h), bytes(px[:stride * h])).convert("L")
    elif frame.format == FMT_IDX8:
        pal = list(frame.palette)
        flat = []
        for i in range(256):
            flat.extend(pal[i] if i < len(pal) else (i, i, i))
        img = Image.frombytes("P", (w, h), bytes(px[:w * h]))
        img.putpalette(flat)
        img = img.convert("RGB")
    else:
        raise ValueError("unknown pixel format %r" % frame.format)
    if scale != 1:
        img = img.resize((w * scale, h * scale), Image.NEAREST)
    return img
