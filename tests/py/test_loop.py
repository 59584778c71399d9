"""pyserial loop:// round trip: the emulator's stream written into loop://
and read back through rast8's source layer decodes to the framebuffers."""
from rast8.protocol import StreamDecoder
from rast8.source import open_source


def test_loop_round_trip(emu_stream):
    stream, frames = emu_stream("--frames", "10")
    src = open_source("loop://", idle=0.3)
    dec = StreamDecoder()
    got = []
    for i in range(0, len(stream), 1000):
        src.write(stream[i:i + 1000])
        while True:
            data = src.read(4096)
            got += dec.feed(data)
            if not data or dec.bytes >= i + len(stream[i:i + 1000]):
                break
    while True:
        data = src.read(4096)
        if not data:
            break
        got += dec.feed(data)
    src.close()
    assert dec.bytes == len(stream)
    assert [f.pixels for f in got] == [f.pixels for f in frames]
