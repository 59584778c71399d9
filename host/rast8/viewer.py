"""rast8 view: a live Tk window showing frames as they arrive, scaled up,
with fps, bytes/s, bytes/frame, compression and error counts.  A reader
thread does the (blocking) serial reads; the Tk loop shows the newest
frame.  Keys pressed in the window go back to the device as INPUT packets
(KeyPad): the viewer is the display and the gamepad.  Headless use: run
under Xvfb (xvfb-run) with --screenshot PNG to capture the frame area
after the last frame."""
import base64
import io
import os
import queue
import sys
import threading
import time

from .capture import Capture
from .protocol import KEY_BITS, input_packet

# Tk keysym -> key name (rast8.protocol.KEY_BITS, R8_KEY_* in C)
KEYMAP = {"Up": "up", "Down": "down", "Left": "left", "Right": "right",
          "z": "a", "x": "b", "Return": "start", "BackSpace": "select",
          "a": "x", "s": "y", "q": "l", "w": "r"}


class KeyPad:
    """Key state as a 16-bit mask; sends an INPUT packet through write()
    when it changes, and again every `period` seconds once a key has been
    used (a device that missed one packet catches up)."""

    def __init__(self, write, period=0.5, clock=time.monotonic):
        self.write = write
        self.period = period
        self.clock = clock
        self.mask = 0
        self.sent = 0               # INPUT packets written
        self._last = None           # time of the last send (None: never)

    def _send(self):
        self.write(input_packet(self.mask))
        self.sent += 1
        self._last = self.clock()

    def _set(self, keysym, down):
        name = KEYMAP.get(keysym, KEYMAP.get(keysym.lower()) if len(keysym) == 1 else None)
        if name is None:
            return False
        bit = KEY_BITS[name]
        mask = (self.mask | bit) if down else (self.mask & ~bit)
        if mask == self.mask:
            return False
        self.mask = mask
        self._send()
        return True

    def press(self, keysym):
        return self._set(keysym, True)

    def release(self, keysym):
        return self._set(keysym, False)

    def tick(self):
        """Call often: resends the state every `period` seconds."""
        if self._last is not None and self.clock() - self._last >= self.period:
            self._send()


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

    pad = KeyPad(src.write)
    root.bind("<KeyPress>", lambda e: pad.press(e.keysym))
    root.bind("<KeyRelease>", lambda e: pad.release(e.keysym))
    state["pad"] = pad

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
        bpf = ("%.0f B/frame" % (d.bytes / d.frames)) if d.frames else "- B/frame"
        ratio = ("%.2f:1" % (d.raw_bytes / d.bytes)) if d.frames and d.bytes else "-"
        keys = "  keys %04x" % pad.mask if pad.sent else ""
        return ("frame %s  %.1f fps  %.0f B/s  %s  compression %s  bad %d  dropped %d  "
                "incomplete %d%s%s" % (
                    fr.number if fr else "-", fps, bps, bpf, ratio, d.bad_packets, d.dropped,
                    d.incomplete, keys, "  [end]" if state["eof"] else ""))

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
        pad.tick()
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
