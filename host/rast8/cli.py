"""rast8 command line: decode, stats, view, scene.

decode, stats and view read a SOURCE: a serial device (/dev/ttyUSB0,
/dev/pts/3), a pyserial URL (socket://host:port, loop://,
rfc2217://host:port), usb:..., a file, or - for stdin.

Exit status: 0 ok; 1 the stream had errors (bad packets, dropped or
incomplete frames) or no frame at all (--lossy: only no frame); 2 bad
usage, a source or output that cannot be opened; 3..9 USB errors
(docs/usb.md).  Errors are one line on stderr, never a traceback.
"""
import argparse
import json
import os
import sys

from . import __version__
from .protocol import VERSION
from .capture import Capture
from .source import open_source, DEFAULT_BAUD

SOURCE_HELP = ("SOURCE: a serial device (/dev/ttyUSB0, /dev/pts/3), a pyserial URL "
               "(socket://HOST:PORT, rfc2217://HOST:PORT, loop://), usb:VID:PID[:EP][,options] "
               "(docs/usb.md), a stream file, or - for stdin.")


class UsageError(Exception):
    """Bad arguments or an output that cannot be written: exit 2."""


def _open(args):
    try:
        src = open_source(args.source, baud=args.baud, idle=args.idle)
    except Exception as e:      # noqa: BLE001 - report any open failure
        print("rast8: %s" % e, file=sys.stderr)
        sys.exit(getattr(e, "exit_code", 2))
    for w in getattr(src, "warnings", ()):     # e.g. several USB boards match
        print("rast8: warning: %s" % w, file=sys.stderr)
    return src


def _fmt(v, suffix=""):
    return "-" if v is None else "%s%s" % (v, suffix)


def _summary(st):
    return ("%d frames, %s bytes/frame, compression %s, errors %d "
            "(bad packets %d, dropped %d, incomplete %d)" % (
                st["frames"], _fmt(st["bytes_per_frame"]), _fmt(st["compression_ratio"], ":1"),
                st["errors"], st["bad_packets"], st["dropped"], st["incomplete"]))


def _exit_code(st, args, err):
    """0 only for a clean stream with frames (--lossy: any frame)."""
    if err is not None:
        print("rast8: %s" % err, file=sys.stderr)
        return getattr(err, "exit_code", 1)
    if not st["frames"]:
        print("rast8: no frame decoded", file=sys.stderr)
        return 1
    if st["errors"] and not args.lossy:
        print("rast8: the stream had errors (%d bad packets, %d dropped, %d incomplete "
              "frames); --lossy accepts that" % (st["bad_packets"], st["dropped"],
                                                 st["incomplete"]), file=sys.stderr)
        return 1
    return 0


def _check_outputs(args):
    """Refuse, before reading anything, outputs that cannot be written."""
    out = args.output
    if os.path.exists(out) and not os.path.isdir(out):
        raise UsageError("-o %s: exists and is not a directory" % out)
    try:
        os.makedirs(out, exist_ok=True)
    except OSError as e:
        raise UsageError("-o %s: cannot create the directory: %s" % (out, e.strerror or e))
    if not os.access(out, os.W_OK):
        raise UsageError("-o %s: the directory is not writable" % out)
    if args.gif:
        if os.path.isdir(args.gif):
            raise UsageError("--gif %s: is a directory; give a file name, e.g. %s" % (
                args.gif, os.path.join(args.gif, "anim.gif")))
        parent = os.path.dirname(os.path.abspath(args.gif))
        if not os.path.isdir(parent) or not os.access(parent, os.W_OK):
            raise UsageError("--gif %s: cannot write there (no such or unwritable directory)"
                             % args.gif)


def cmd_decode(args):
    _check_outputs(args)
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
    except OSError as e:        # the source failed (USB unplug, stall...), or a PNG write
        err = e
    finally:
        src.close()
    gif = args.gif or os.path.join(args.output, "anim.gif")
    if images:
        try:
            images[0].save(gif, save_all=True, append_images=images[1:],
                           duration=max(10, int(1000 / args.gif_fps)), loop=0)
        except OSError as e:
            err = err or OSError("cannot write %s: %s" % (gif, e.strerror or e))
    st = cap.stats()
    if args.json:
        print(json.dumps(st))
    else:
        print("decoded %s -> %s" % (_summary(st), args.output if images else "(no frames)"))
    return _exit_code(st, args, err)


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
        if st["fps"] is not None:
            print("frames/s          %s" % st["fps"])
        print("bytes             %d" % st["bytes"])
        print("bytes/frame       %s" % _fmt(st["bytes_per_frame"]))
        print("compression       %s (raw %d bytes)" % (_fmt(st["compression_ratio"], ":1"),
                                                       st["raw_bytes"]))
        print("bad packets       %d" % st["bad_packets"])
        print("dropped frames    %d" % st["dropped"])
        print("incomplete frames %d" % st["incomplete"])
        if st["skipped"]:
            print("skipped (joining) %d" % st["skipped"])
    return _exit_code(st, args, err)


def cmd_view(args):
    from .viewer import run_viewer
    src = _open(args)
    try:
        return run_viewer(src, args)
    finally:
        src.close()


def cmd_scene(args):
    from . import scene as S

    def load(name):
        if os.path.exists(name):
            return S.load_any(name)
        if name in S.BUILTIN_ORDER:
            return S.builtin(name)
        raise UsageError("%s: no such file, and not a built-in scene (%s)" % (
            name, ", ".join(S.BUILTIN_ORDER)))
    try:
        if args.scene_cmd == "list":
            for n in S.BUILTIN_ORDER:
                sc = S.builtin(n)
                print("%-9s %d objects, %d faces" % (n, len(sc.objects),
                                                    sum(len(m.faces) for m in sc.meshes.values())))
        elif args.scene_cmd == "check":
            sc = load(args.scene)
            for n, m in sc.meshes.items():
                print("%s: %d vertices, %d faces, %s, radius %d" % (
                    n, len(m.verts), len(m.faces), "convex" if m.convex else "not convex",
                    m.radius()))
            print("%d objects" % len(sc.objects))
            if sc.world is not None:
                w = sc.world
                walls, portals = w.faces()
                print("world %s: %d sectors, %d walls, %d portals, camera path of %d points "
                      "(%d frames)" % (w.name, len(w.sectors), len(walls), len(portals),
                                       len(w.path), len(S.sectors.frames(w))))
        elif args.scene_cmd == "texture":
            from . import texture as T
            try:
                tex = T.load_png(args.png, args.format, args.name)
            except T.TextureError as e:
                print("rast8 scene: %s" % e, file=sys.stderr)
                return 1
            cid = "".join(ch if ch.isalnum() else "_" for ch in tex.name)
            with open(args.out, "w") as f:
                f.write("/* Generated by rast8 scene texture from %s: do not edit. */\n"
                        "#include \"r8scene.h\"\n" % os.path.basename(args.png))
                f.write("\n".join(T.to_c(tex, cid)).replace("static const r8_texture", "const r8_texture") + "\n")
            print("wrote %s: texture %s, %dx%d %s, %d bytes of texels" % (
                args.out, cid, tex.side, tex.side, args.format, len(tex.data())))
        elif args.scene_cmd == "c":
            scenes = [load(p) for p in args.scenes] or [S.builtin(n) for n in S.BUILTIN_ORDER]
            if args.texture:
                from . import texture as T
                try:
                    tex = T.load_png(args.texture, args.texture_format)
                except T.TextureError as e:
                    print("rast8 scene: %s" % e, file=sys.stderr)
                    return 1
                for sc in scenes:     # OBJ models: their vt on this texture
                    sc.textures.setdefault(tex.name, tex)
                    for m in sc.meshes.values():
                        if m.uvs and not m.texture:
                            m.texture = tex.name
            paths = S.to_c(scenes, args.out)
            print("wrote %s: %d scenes in %d file(s)" % (args.out, len(scenes), len(paths)))
        elif args.scene_cmd == "blob":
            data = S.to_blob(load(args.scene))
            with open(args.out, "wb") as f:
                f.write(data)
            print("wrote %s: %d bytes" % (args.out, len(data)))
    except S.SceneError as e:
        print("rast8 scene: %s" % e, file=sys.stderr)
        return 1
    except OSError as e:
        print("rast8 scene: %s: %s" % (getattr(e, "filename", "") or "", e.strerror or e),
              file=sys.stderr)
        return 2
    return 0


class _Parser(argparse.ArgumentParser):
    """argparse that reports a usage error as one line (and exit 2)."""

    def error(self, message):
        self.exit(2, "%s: error: %s (see --help)\n" % (self.prog, message))


def _int_at_least(lo):
    def conv(text):
        try:
            v = int(text)
        except ValueError:
            raise argparse.ArgumentTypeError("%r is not a whole number" % text) from None
        if v < lo:
            raise argparse.ArgumentTypeError("must be at least %d, not %d" % (lo, v))
        return v
    return conv


def _positive_float(text):
    try:
        v = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError("%r is not a number" % text) from None
    if not v > 0:
        raise argparse.ArgumentTypeError("must be more than 0, not %s" % text)
    return v


def build_parser():
    p = _Parser(
        prog="rast8",
        description="Decode, measure and view rast8 frame streams (protocol v%d); "
                    "convert scenes." % VERSION,
        epilog=SOURCE_HELP + " Exit status: 0 ok, 1 stream errors or no frame, 2 usage "
               "or I/O error, 3-9 USB errors (docs/usb.md).")
    p.add_argument("--version", action="version", version="rast8 %s (protocol v%d)" % (__version__, VERSION))
    sub = p.add_subparsers(dest="cmd", metavar="COMMAND", parser_class=_Parser)

    def common(sp):
        sp.add_argument("source", metavar="SOURCE", help="where the stream comes from (below)")
        sp.add_argument("--baud", type=_int_at_least(1), default=DEFAULT_BAUD,
                        help="serial baud rate (default %(default)s)")
        sp.add_argument("--frames", type=_int_at_least(1), default=None, metavar="N",
                        help="stop after N good frames")
        sp.add_argument("--idle", type=_positive_float, default=None, metavar="S",
                        help="serial/URL sources: stop after S seconds without data")
        sp.add_argument("--no-request", action="store_true",
                        help="never ask the device for a full frame")

    def lossy(sp):
        sp.add_argument("--lossy", action="store_true",
                        help="accept a stream with errors: exit 0 if any frame decoded "
                             "(default: exit 1 on bad packets, dropped or incomplete frames)")

    d = sub.add_parser("decode", help="write one PNG per frame and an animated GIF",
                       description="Decode SOURCE: one PNG per good frame and an animated "
                                   "GIF, then a summary line.",
                       epilog=SOURCE_HELP)
    common(d)
    d.add_argument("-o", "--output", required=True, metavar="DIR",
                   help="directory for frame_NNNNN.png and anim.gif (created if missing)")
    d.add_argument("--gif", metavar="PATH", help="GIF path (default DIR/anim.gif)")
    d.add_argument("--scale", type=_int_at_least(1), default=1,
                   help="PNG scale (default 1: exact framebuffer)")
    d.add_argument("--gif-scale", type=_int_at_least(1), default=2, help="GIF scale (default 2)")
    d.add_argument("--gif-fps", type=_positive_float, default=20.0,
                   help="GIF frames per second (default 20)")
    d.add_argument("--json", action="store_true", help="print the summary as JSON")
    d.add_argument("-q", "--quiet", action="store_true", help="no progress")
    lossy(d)
    d.set_defaults(func=cmd_decode)

    s = sub.add_parser("stats", help="frames, frames/s, bytes/frame, compression, errors",
                       description="Measure SOURCE: frames, frames/s (live sources), "
                                   "bytes/frame, compression ratio and error counts.",
                       epilog=SOURCE_HELP)
    common(s)
    s.add_argument("--json", action="store_true", help="print the numbers as JSON")
    s.add_argument("--progress", action="store_true",
                   help="show progress on stderr (default when stderr is a terminal)")
    lossy(s)
    s.set_defaults(func=cmd_stats)

    v = sub.add_parser("view", help="live window with fps, bytes/s, bytes/frame and errors; "
                                    "sends keys",
                       description="Show SOURCE live in a window.  Keys go back to the device "
                                   "as INPUT packets (docs/protocol.md): arrows, z = A, x = B, "
                                   "Return = START, BackSpace = SELECT, a = X, s = Y, q = L, "
                                   "w = R.",
                       epilog=SOURCE_HELP)
    common(v)
    v.add_argument("--scale", type=_int_at_least(1), default=4, help="window scale (default 4)")
    v.add_argument("--screenshot", metavar="PNG",
                   help="after the last frame, save a screenshot of the frame area and exit")
    v.add_argument("--exit-at-end", action="store_true", help="close the window at end of input")
    v.set_defaults(func=cmd_view)

    sc = sub.add_parser("scene", help="check a scene, convert it to C or to a blob",
                        description="Scenes: a built-in name (rast8 scene list), a .r8s file "
                                    "or an .obj file (docs/scene-format.md).")
    ss = sc.add_subparsers(dest="scene_cmd", metavar="ACTION", required=True,
                           parser_class=_Parser)
    ss.add_parser("list", help="the built-in scenes")
    x = ss.add_parser("check", help="parse a scene and report its meshes")
    x.add_argument("scene", metavar="SCENE", help="built-in name, .r8s or .obj file")
    x = ss.add_parser("c", help="C arrays for firmware (default: every built-in scene)")
    x.add_argument("out", metavar="OUT", help="a .c file to write, or a directory for one file per scene")
    x.add_argument("scenes", metavar="SCENE", nargs="*", help="built-in names or files")
    x.add_argument("--texture", metavar="PNG",
                   help="texture for meshes with texture coordinates but none named (.obj vt)")
    x.add_argument("--texture-format", choices=("idx8", "1bpp"), default="idx8")
    x = ss.add_parser("texture", help="a PNG (8..64 texels square) as a C texture (r8_texture)")
    x.add_argument("png", metavar="PNG")
    x.add_argument("out", metavar="OUT.c")
    x.add_argument("--format", choices=("idx8", "1bpp"), default="idx8",
                   help="8-bit grey (default) or 1 bit per texel (lit from grey 128)")
    x.add_argument("--name", help="C name (default: the file's)")
    x = ss.add_parser("blob", help="the binary scene blob (docs/scene-format.md)")
    x.add_argument("scene", metavar="SCENE", help="built-in name, .r8s or .obj file")
    x.add_argument("out", metavar="OUT.bin", help="the blob file to write")
    sc.set_defaults(func=cmd_scene)
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
    except KeyboardInterrupt:
        return 130
    except UsageError as e:
        print("rast8: %s" % e, file=sys.stderr)
        return 2
    except Exception as e:      # noqa: BLE001 - one line, never a traceback
        if os.environ.get("RAST8_DEBUG"):
            raise
        print("rast8: %s: %s (RAST8_DEBUG=1 shows the traceback)" % (type(e).__name__, e),
              file=sys.stderr)
        return 1


if __name__ == "__main__":
    sys.exit(main())
