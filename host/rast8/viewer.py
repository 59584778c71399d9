"""rast8 view: a live Tk window showing frames as they arrive, scaled up,
with fps, bytes/s and error counts.  A reader thread does the (blocking)
serial reads; the Tk loop shows the newest frame.  Headless use: run
under Xvfb (xvfb-run) with --screenshot PNG to capture the frame area
after the last frame."""
import base64
import io
import os
import queue
import sys
import threading
import time

from .cli import Capture


def _photo(tk, img):
    buf = io.BytesIO()
    img.save(buf, format="PNG")
    return tk.PhotoImage(data=base64.b64encode(buf.getvalue()))


def run_viewer(src, args):
    try:
        import tkinter as tk
    except ImportError:
        print("rast8 view: tkinter is not available", file=sys.stderr)
        return 2
    try:
        root = tk.Tk()
    except tk.TclError as e:
        print("rast8 view: cannot open a window (%s); set DISPLAY or run "
              "under xvfb-run" % e, file=sys.stderr)
        return 2
    root.title("rast8 - %s" % getattr(src, "name", "stream"))
    root.configure(background="black")
    cap = Capture(src, args.frames, progress=False, request=not args.no_request)
    frames = queue.Queue(maxsize=4)
    state = {"eof": False, "shown": 0, "last": None, "photo": None, "t0": time.monotonic(),
             "rate": []}

    def reader():
        def on_frame(fr):
            try:
                frames.put(fr, timeout=5)
            except queue.Full:
                pass
        try:
            cap.run(on_frame)
        except OSError as e:    # the source failed: say so, keep the last frame up
            state["error"] = str(e)
            print("rast8 view: %s" % e, file=sys.stderr)
        finally:
            state["eof"] = True

    th = threading.Thread(target=reader, daemon=True)
    canvas = tk.Label(root, borderwidth=0, highlightthickness=0, background="black")
    canvas.pack(padx=0, pady=0)
    status = tk.Label(root, text="waiting for frames...", anchor="w",
                      font=("TkFixedFont", 9), foreground="#8f8", background="black")
    status.pack(fill="x")

    def status_text():
        now = time.monotonic()
        st = state["rate"]
        st.append((now, cap.dec.bytes, state["shown"]))
        while st and now - st[0][0] > 2.0:
            st.pop(0)
        dt = now - st[0][0] if len(st) > 1 else 0
        fps = (st[-1][2] - st[0][2]) / dt if dt > 0 else 0.0
        bps = (st[-1][1] - st[0][1]) / dt if dt > 0 else 0.0
        d = cap.dec
        fr = state["last"]
        return ("frame %s  %.1f fps  %.0f B/s  bad %d  dropped %d  incomplete %d%s" % (
            fr.number if fr else "-", fps, bps, d.bad_packets, d.dropped, d.incomplete,
            "  [end]" if state["eof"] else ""))

    def finish():
        if args.screenshot and state["last"] is not None:
            root.update_idletasks()
            root.update()
            from PIL import ImageGrab
            x, y = canvas.winfo_rootx(), canvas.winfo_rooty()
            w, h = canvas.winfo_width(), canvas.winfo_height()
            shot = ImageGrab.grab(bbox=(x, y, x + w, y + h),
                                  xdisplay=os.environ.get("DISPLAY"))
            shot.save(args.screenshot)
            print("rast8 view: screenshot of frame %d -> %s" % (state["last"].number, args.screenshot))
        root.destroy()

    def poll():
        fr = None
        while True:
            try:
                fr = frames.get_nowait()
            except queue.Empty:
                break
            state["shown"] += 1
        if fr is not None:
            state["last"] = fr
            state["photo"] = _photo(tk, fr.to_image(args.scale))
            canvas.configure(image=state["photo"])
        status.configure(text=status_text())
        if state["eof"] and frames.empty():
            if args.screenshot or args.exit_at_end:
                root.after(300, finish)
                return
        root.after(15, poll)

    th.start()
    root.after(15, poll)
    try:
        root.mainloop()
    except KeyboardInterrupt:
        pass
    st = cap.stats()
    print("rast8 view: %d frames, errors %d" % (st["frames"], st["errors"]))
    return 0 if st["frames"] else 1
