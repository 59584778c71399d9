"""capture.py - reading a frame source through the decoder (rast8 decode,
stats, view, demo): good frames to a callback, REQUEST when the decoder
needs a full frame, progress on stderr."""
import sys
import time

from .protocol import StreamDecoder, request_packet


class Capture:
    """Read a source through a StreamDecoder; call on_frame for every good
    frame; ask for a full frame when the decoder needs one; show progress."""

    def __init__(self, src, frames=None, progress=False, request=True,
                 max_frame_bytes=1 << 20):
        self.src = src
        self.dec = StreamDecoder(max_frame_bytes)
        self.limit = frames
        self.progress = progress
        self.request = request
        self.count = 0
        self.t_first = None     # first byte
        self.t_last = None      # last good frame
        self.t_start = time.monotonic()
        self._last_req = 0.0
        self._last_prog = 0.0
        self.requests = 0
        self.eof = False        # the source ended (not stopped by --frames)

    def done(self):
        return self.limit is not None and self.count >= self.limit

    def step(self, on_frame):
        """Read once; returns False at end of input or when done."""
        if self.done():
            return False
        data = self.src.read(4096)
        if not data:
            if not self.eof:
                self.eof = True
                self.dec.finish()       # an unterminated tail or open frame counts
            return False
        now = time.monotonic()
        if self.t_first is None:
            self.t_first = now
        for fr in self.dec.feed(data):
            self.count += 1
            self.t_last = time.monotonic()
            on_frame(fr)
            if self.done():
                break
        if self.request and self.dec.need_full and now - self._last_req > 0.5:
            if self.src.write(request_packet()):
                self.requests += 1
            self._last_req = now
        if self.progress and now - self._last_prog >= 1.0:
            self._last_prog = now
            c = self.dec
            msg = "  %d frames, %d bytes, bad packets %d, dropped %d, incomplete %d" % (
                self.count, c.bytes, c.bad_packets, c.dropped, c.incomplete)
            if sys.stderr.isatty():
                sys.stderr.write("\r" + msg)
            else:
                sys.stderr.write(msg + "\n")
            sys.stderr.flush()
        return not self.done()

    def run(self, on_frame):
        while self.step(on_frame):
            pass
        if self.progress and sys.stderr.isatty():
            sys.stderr.write("\n")

    def stats(self):
        c = self.dec
        frames = c.frames
        span = (self.t_last - self.t_first) if (self.t_first and self.t_last) else 0.0
        live = getattr(self.src, "kind", "file") != "file"     # a file has no frame rate
        return {
            "frames": frames,
            "fps": round(frames / span, 2) if span > 0 and live else None,
            "bytes": c.bytes,
            "bytes_per_frame": round(c.bytes / frames, 1) if frames else None,
            "raw_bytes": c.raw_bytes,
            "compression_ratio": round(c.raw_bytes / c.bytes, 2) if c.bytes and frames else None,
            "bad_packets": c.bad_packets,
            "dropped": c.dropped,
            "incomplete": c.incomplete,
            "skipped": c.skipped,
            "ignored": c.ignored,
            "errors": c.bad_packets + c.dropped + c.incomplete,
            "requests": self.requests,
        }
