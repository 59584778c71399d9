# mk/wire.mk - the serial display protocol's host side (issue 3):
# build/rast8-emu (the demo firmware run natively), build/rast8-codec
# (the C codecs/decoder as a filter for C-vs-Python tests), the Python
# tests and `make demo`.

EMU_CFLAGS := -std=gnu99 -Wall -Wextra -Werror -O2 -g
EMU        := $(BUILD)/rast8-emu
CODEC_TOOL := $(BUILD)/rast8-codec
EMU_SRC    := emu/main.c emu/plat_host.c examples/spin/app.c
EMU_HDR    := examples/spin/app.h ports/plat.h emu/plat_host.h $(wildcard include/*.h)
EMU_INC    := -Iemu -Iports -Iexamples/spin

ALL_TARGETS += $(EMU) $(CODEC_TOOL)

$(EMU): $(EMU_SRC) $(EMU_HDR) $(LIBS)
	$(CC) $(EMU_CFLAGS) $(INC) $(EMU_INC) $(EMU_SRC) $(LIBS) -o $@

$(CODEC_TOOL): tests/tools/codec_host.c $(wildcard include/*.h) $(LIB)
	$(CC) $(EMU_CFLAGS) $(INC) tests/tools/codec_host.c $(LIB) -o $@

# examples/spin/app.c runs on every target: hold it to the library's C89 gate and
# the three cross compilers too.
.PHONY: test-app-c89 test-py vectors demo stats
test-app-c89:
	@bash scripts/run-step.sh app-c89 bash -c 'p=0; f=0; t=$$(mktemp -d); \
	  for cc in gcc clang; do if $$cc $(STRICT) $(INC) $(EMU_INC) -c examples/spin/app.c -o /dev/null; \
	  then p=$$((p+1)); else f=$$((f+1)); echo "FAIL: $$cc examples/spin/app.c"; fi; done; \
	  if avr-gcc $(STRICT) -mmcu=atmega328p -Os $(INC) $(EMU_INC) -c examples/spin/app.c -o $$t/a.o; \
	  then p=$$((p+1)); else f=$$((f+1)); echo "FAIL: avr-gcc examples/spin/app.c"; fi; \
	  if cc65 -t sim6502 --standard c89 -W +error,-const-comparison -Oirs $(INC) $(EMU_INC) examples/spin/app.c -o $$t/a.s >/dev/null; \
	  then p=$$((p+1)); else f=$$((f+1)); echo "FAIL: cc65 examples/spin/app.c"; fi; \
	  if sdcc -mz80 --std-c89 --Werror $(INC) $(EMU_INC) -c examples/spin/app.c -o $$t/a.rel >/dev/null; \
	  then p=$$((p+1)); else f=$$((f+1)); echo "FAIL: sdcc examples/spin/app.c"; fi; \
	  rm -rf $$t; echo "$$p passed, $$f failed"; [ $$f = 0 ]'

# Python: codec/vector agreement with C, protocol, fault injection,
# emulator end to end over a pty, loop://, pacing, headless viewer.
test-py: $(SETUP) $(EMU) $(CODEC_TOOL)
	@bash scripts/run-step.sh py-wire $(PY) -m pytest -q -p no:cacheprovider tests/py

TEST_STEPS += test-app-c89 test-py

# The main job: the emulator streams the teapot (Gouraud, 8-bit grey)
# through a pty, the viewer reads it over pyserial and writes
# build/demo/*.png (1:1 and x4) + demo.gif.  It installs only what the
# demo and the README's "Using it" commands need (scripts/setup.sh demo:
# compiler, libusb, Tk, the venv); the cross toolchains come with
# `make test` / `make bench`.  It also builds every host tool.
DEMO_FRAMES ?= 64
DEMO_ARGS ?= -- --scene teapot --format idx8 --shading gouraud --method auto
DEMO_SETUP := $(VENV)/.rast8-demo-setup
$(DEMO_SETUP): scripts/setup.sh host/pyproject.toml
	bash scripts/setup.sh demo
	touch $@
demo: $(DEMO_SETUP)
	@$(MAKE) --no-print-directory $(EMU) $(CODEC_TOOL) $(BUILD)/r8dump $(BUILD)/rast8-usbcat
	@rm -rf $(BUILD)/demo && mkdir -p $(BUILD)/demo
	@$(PY) -m rast8.demo --emu $(EMU) --frames $(DEMO_FRAMES) --out $(BUILD)/demo $(DEMO_ARGS)

# Bytes per frame and compression ratio of the demo with each codec and
# dirty bands, then bytes/frame of every codec on every built-in scene
# (PAGE1 and IDX8) (make stats DEMO_FRAMES=64).
stats: $(SETUP) $(EMU)
	@$(PY) -m rast8.demo --emu $(EMU) --frames $(DEMO_FRAMES) --compare
	@$(PY) -m rast8.demo --emu $(EMU) --frames $(DEMO_FRAMES) --codecs
	@$(PY) -m rast8.demo --emu $(EMU) --frames $(DEMO_FRAMES) --codecs -- --format idx8

# Library objects also depend on the private headers in src/ (the
# pattern rule in the Makefile lists include/*.h only); without this a
# changed src/*.h leaves stale objects and rast8-emu crashes.
$(LIB_OBJ): $(wildcard src/*.h)

# The C tests that read the shared vectors; `make vectors` regenerates
# tests/vectors/vectors.h from tests/vectors/codec.txt (a pytest checks
# that it is up to date).
VEC_TESTS := test_rle test_lz77 test_wire
$(VEC_TESTS:%=$(BUILD)/tests/%) $(VEC_TESTS:%=$(BUILD)/asan/%): tests/vectors/vectors.h
vectors: $(SETUP)
	$(PY) -m rast8.vectors tests/vectors/codec.txt tests/vectors/vectors.h

# ---- soak (issue 12): fault injection into a real emulator stream, C
# decoder (build/r8soak, tests/soak/soak.c) and Python decoder
# (tests/soak/soak.py); one summary line each.  `make soak` is the long
# run; test-soak a short one inside make test.
SOAK        := $(BUILD)/r8soak
SOAK_STREAM := $(BUILD)/soak/small.bin
SOAK_FAULTS ?= 10000000
SOAK_PY_FAULTS ?= 1000000
SOAK_JOBS ?= 2
# the protocol version soaked: 2 (the emulator's version-1 stream rewritten
# by tests/soak/wire2.py: rast8-emu uses the default library, which writes
# version 1; -DR8_WIRE_CRC32 builds write version 2) or 1
SOAK_WIRE ?= 2
SOAK_V2     := $(BUILD)/soak/small-v2.bin
SOAK_IN     := $(if $(filter 1,$(SOAK_WIRE)),$(SOAK_STREAM),$(SOAK_V2))
ALL_TARGETS += $(SOAK)

$(SOAK): tests/soak/soak.c $(LIB) $(wildcard include/*.h)
	$(CC) -std=gnu99 -O2 -g -Wall -Wextra -Werror $(INC) $< $(LIB) -o $@

# 4096 frames of the cube at 64x32, full frame every 8 (P = 8)
$(SOAK_STREAM): $(EMU)
	@mkdir -p $(dir $@)
	$(EMU) -q --frames 4096 --width 64 --height 32 --full-period 8 --out $@ --dump $(@:.bin=.r8fb)

.PHONY: soak test-soak
$(SOAK_V2): $(SOAK_STREAM) tests/soak/wire2.py host/rast8/protocol.py $(SETUP)
	$(PY) tests/soak/wire2.py $(SOAK_STREAM) $(SOAK_STREAM:.bin=.r8fb) $@

soak: $(SOAK) $(SOAK_IN) $(SETUP)
	$(SOAK) $(SOAK_IN) $(SOAK_STREAM:.bin=.r8fb) --faults $(SOAK_FAULTS) --quiet
	$(PY) tests/soak/soak.py $(SOAK_IN) $(SOAK_STREAM:.bin=.r8fb) --faults $(SOAK_PY_FAULTS) --jobs $(SOAK_JOBS) --quiet

test-soak: $(SOAK) $(SOAK_V2) $(SETUP)
	@bash scripts/run-step.sh soak bash -c '$(SOAK) $(SOAK_V2) $(SOAK_STREAM:.bin=.r8fb) --faults 30000 --quiet \
	  && $(PY) tests/soak/soak.py $(SOAK_V2) $(SOAK_STREAM:.bin=.r8fb) --faults 5000 --quiet \
	  && echo "2 passed, 0 failed" || { echo "0 passed, 1 failed"; exit 1; }'

TEST_STEPS += test-soak
