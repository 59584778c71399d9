"""formats.py - the framebuffer layouts (include/r8fb.h: R8_FMT_*), shared by
the protocol decoder and the image conversion."""
FMT_PAGE1, FMT_ROW1, FMT_IDX8 = 0, 1, 2
FORMAT_NAMES = {"page1": FMT_PAGE1, "row1": FMT_ROW1, "idx8": FMT_IDX8}
FORMAT_BY_ID = {v: k for k, v in FORMAT_NAMES.items()}
