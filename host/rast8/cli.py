"""rast8 command line: decode, stats, view.

Every subcommand reads a SOURCE: a serial device (/dev/ttyUSB0,
/dev/pts/3), a pyserial URL (socket://host:port, loop://,
rfc2217://host:port), usb:..., a file, or - for stdin.
"""
import argparse
import json
import os
import sys
import time

from . import __version__
from .protocol import StreamDecoder, request_packet, VERSION
from .source import open_source, DEFAULT_BAUD


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

    def done(self):
        return self.limit is not None and self.count >= self.limit

    def step(self, on_frame):
        """Read once; returns False at end of input or when done."""
        if self.done():
            return False
        data = self.src.read(4096)
        if not data:
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
        return {
            "frames": frames,
            "fps": round(frames / span, 2) if span > 0 else None,
            "bytes": c.bytes,
            "bytes_per_frame": round(c.bytes / frames, 1) if frames else None,
            "raw_bytes": c.raw_bytes,
            "compression_ratio": round(c.raw_bytes / c.bytes, 2) if c.bytes and frames else None,
            "bad_packets": c.bad_packets,
            "dropped": c.dropped,
            "incomplete": c.incomplete,
            "errors": c.bad_packets + c.dropped + c.incomplete,
            "requests": self.requests,
        }


def _open(args):
    try:
        return open_source(args.source, baud=args.baud, idle=args.idle)
    except Exception as e:      # noqa: BLE001 - report any open failure
        print("rast8: %s" % e, file=sys.stderr)
        sys.exit(getattr(e, "exit_code", 2))


def _summary(st):
    return ("%d frames, %s bytes/frame, compression %s:1, errors %d "
            "(bad packets %d, dropped %d, incomplete %d)" % (
                st["frames"], st["bytes_per_frame"], st["compression_ratio"],
                st["errors"], st["bad_packets"], st["dropped"], st["incomplete"]))


def cmd_decode(args):
    os.makedirs(args.output, exist_ok=True)
    src = _open(args)
    cap = Capture(src, args.frames, progress=not args.quiet, request=not args.no_request)
    images = []

    def on_frame(fr):
        img = fr.to_image(args.scale)
        img.save(os.path.join(args.output, "frame_%05d.png" % fr.number))
        images.append(fr.to_image(args.gif_scale).convert("P"))

    err = None
    try:
        cap.run(on_frame)
    except KeyboardInterrupt:
        pass
    except OSError as e:        # the source failed (USB unplug, stall...): keep what came
        err = e
    finally:
        src.close()
    gif = args.gif or os.path.join(args.output, "anim.gif")
    if images:
        images[0].save(gif, save_all=True, append_images=images[1:],
                       duration=max(10, int(1000 / args.gif_fps)), loop=0)
    st = cap.stats()
    if args.json:
        print(json.dumps(st))
    else:
        print("decoded %s -> %s" % (_summary(st), args.output if images else "(no frames)"))
    if err is not None:
        print("rast8: %s" % err, file=sys.stderr)
        return getattr(err, "exit_code", 1)
    return 0 if st["frames"] else 1


def cmd_stats(args):
    src = _open(args)
    cap = Capture(src, args.frames, progress=args.progress or (sys.stderr.isatty() and not args.json),
                  request=not args.no_request)
    err = None
    try:
        cap.run(lambda fr: None)
    except KeyboardInterrupt:
        pass
    except OSError as e:        # the source failed: report what came before it
        err = e
    finally:
        src.close()
    st = cap.stats()
    if args.json:
        print(json.dumps(st))
    else:
        print("frames            %d" % st["frames"])
        print("frames/s          %s" % st["fps"])
        print("bytes             %d" % st["bytes"])
        print("bytes/frame       %s" % st["bytes_per_frame"])
        print("compression       %s:1 (raw %d bytes)" % (st["compression_ratio"], st["raw_bytes"]))
        print("bad packets       %d" % st["bad_packets"])
        print("dropped frames    %d" % st["dropped"])
        print("incomplete frames %d" % st["incomplete"])
    if err is not None:
        print("rast8: %s" % err, file=sys.stderr)
        return getattr(err, "exit_code", 1)
    return 0 if st["frames"] else 1


def cmd_view(args):
    from .viewer import run_viewer
    src = _open(args)
    try:
        return run_viewer(src, args)
    finally:
        src.close()


def build_parser():
    p = argparse.ArgumentParser(
        prog="rast8",
        description="Decode, measure and view rast8 frame streams (protocol v%d)." % VERSION,
        epilog="SOURCE: serial device (/dev/ttyUSB0), pyserial URL (socket://host:port, "
               "loop://, rfc2217://host:port), usb:..., a file, or - for stdin.")
    p.add_argument("--version", action="version", version="rast8 %s (protocol v%d)" % (__version__, VERSION))
    sub = p.add_subparsers(dest="cmd", metavar="COMMAND")

    def common(sp):
        sp.add_argument("source", metavar="SOURCE")
        sp.add_argument("--baud", type=int, default=DEFAULT_BAUD,
                        help="serial baud rate (default %(default)s)")
        sp.add_argument("--frames", type=int, default=None, metavar="N",
                        help="stop after N good frames")
        sp.add_argument("--idle", type=float, default=None, metavar="S",
                        help="serial/URL sources: stop after S seconds without data")
        sp.add_argument("--no-request", action="store_true",
                        help="never ask the device for a full frame")

    d = sub.add_parser("decode", help="write one PNG per frame and an animated GIF")
    common(d)
    d.add_argument("-o", "--output", required=True, metavar="DIR")
    d.add_argument("--gif", metavar="PATH", help="GIF path (default DIR/anim.gif)")
    d.add_argument("--scale", type=int, default=1, help="PNG scale (default 1: exact framebuffer)")
    d.add_argument("--gif-scale", type=int, default=2, help="GIF scale (default 2)")
    d.add_argument("--gif-fps", type=float, default=20.0)
    d.add_argument("--json", action="store_true", help="print the summary as JSON")
    d.add_argument("-q", "--quiet", action="store_true", help="no progress")
    d.set_defaults(func=cmd_decode)

    s = sub.add_parser("stats", help="frames, frames/s, bytes/frame, compression, errors")
    common(s)
    s.add_argument("--json", action="store_true")
    s.add_argument("--progress", action="store_true",
                   help="show progress on stderr (default when stderr is a terminal)")
    s.set_defaults(func=cmd_stats)

    v = sub.add_parser("view", help="live window with fps, bytes/s and error counts")
    common(v)
    v.add_argument("--scale", type=int, default=4, help="window scale (default 4)")
    v.add_argument("--screenshot", metavar="PNG",
                   help="after the last frame, save a screenshot of the frame area and exit")
    v.add_argument("--exit-at-end", action="store_true", help="close the window at end of input")
    v.set_defaults(func=cmd_view)
    return p


def main(argv=None):
    p = build_parser()
    args = p.parse_args(argv)
    if not args.cmd:
        p.print_help()
        return 2
    try:
        return args.func(args)
    except BrokenPipeError:
        return 1


if __name__ == "__main__":
    sys.exit(main())
