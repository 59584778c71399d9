# mk/targets.mk - cross builds for AVR (ATmega328P, ATmega1284P), 6502
# (cc65 / sim65) and Z80 (sdcc / ucsim sz80), the simulator runners, the
# C unit tests inside each simulator, the firmware bit-identity tests and
# `make bench`.
#
#   make xtargets   runners, target libraries, per-target sizes, unit tests
#   make fw         every firmware build the identity tests use
#   make bench      build/bench/results.json + results.md (make docs copies it)
#
# Under build/x/<target>/ (target = avr328 avr1284 6502 z80):
#   obj/            library objects (src/*.c, examples/spin/app.c), plat, scene_S
#   librast8.a / rast8.lib   the library archive
#   sizes.txt       "scene method bytes": app_ram() measured on the target
#                   (tests/targets/fw_sizes.c, one program per scene)
#   fw/fw-S-M-F.*   firmware for scene S, method M, F frames, with a static
#                   arena of exactly app_ram() bytes (examples/spin/fw_app.c)
#   tests/test_x.*  tests/c/test_x.c + tests/unity + the library
# Programs are linked by ports/xbuild.sh; one that does not fit its target
# becomes a one-line "SKIP: reason" file, which the runners report.
# Every firmware links build/x/scenes/scene_S.c (ports/scene_strip.py): the
# scene table with only its own scene's meshes.
# AVR assembly kernels (include/r8kern.h): ports/avr/trap.S, xform.S,
# edge.S, project.S, fill.S, facecull.S, facelevel.S and facez.S go into both AVR archives, whose library
# objects are compiled with -DR8_ASM_TRAP -DR8_ASM_XFORM -DR8_ASM_EDGE
# -DR8_ASM_PROJECT -DR8_ASM_FILL -DR8_ASM_CULL -DR8_ASM_LEVEL -DR8_ASM_ZSUM (src/kern.c then leaves its C references out),
# and zfill.S with -DR8_ASM_ZFILL (src/r8zrows.h: src/zrows.c's reference),
# fwalk.S with -DR8_ASM_FWALK (its painter's part, fwpaint.S, is an object of
# its own, linked only by firmwares with painter's), vertex.S with
# -DR8_ASM_VERTEX -DR8_ASM_DEPTH (r8k_vertex, fwalk.S's vertex call, and
# r8k_depth, r8_tf_depth's arithmetic; needs project.S); the
# host, 6502 and Z80 keep the references.  AVR_ASM=0 builds the AVR
# libraries without them; AVR_ASM="trap edge" (any of trap xform edge
# project fill facecull facelevel facez zfill fwalk vertex) with those only, for before/after figures; as an environment
# variable it also reaches make bench (`AVR_ASM=0 make bench`).
# build/x/avr-kernels.txt records the choice and AVR_CFLAGS, so changing
# either rebuilds the AVR objects.
# Test: tests/targets/test_avr_kern.c (each kernel against its reference
# on random inputs, in libsimavr), step xkern-avr1284.

XB       := $(BUILD)/x
AVRSIM   := $(BUILD)/emu/avrsim
Z80SIM   := $(BUILD)/emu/z80sim
FWHOST   := $(BUILD)/emu/fw-host
XTARGETS := avr328 avr1284 6502 z80
XHDRS    := $(wildcard include/*.h src/*.h scenes/*.h) ports/plat.h $(wildcard examples/spin/app.h)
XSCENES  := 0 1 2 3 4 5 6 7 8 9 10

# The library as the targets see it: src/*.c plus examples/spin/app.c.
# The firmware main is examples/spin/fw_app.c (app_run over a static
# arena).  Port layers: ports/<cpu>/plat_*.c behind ports/plat.h.
XLIB_SRC   := $(LIB_SRC) $(wildcard examples/spin/app.c)
FW_SRC     := examples/spin/fw_app.c
XINC       := -Iports -Iexamples/spin
FW_DEFS    := -DFW_HAVE_APP
XOBJ_NAMES := $(notdir $(XLIB_SRC:.c=))

# The wire encoder's AVR kernels (ports/avr/wire_avr.S; C89 references
# chosen by R8_ASM_WIRE, see src/r8crc.h) are always in the AVR libraries;
# the renderer's (trap.S, xform.S, edge.S, project.S) as AVR_ASM chooses.
AVR_WIRE_S := ports/avr/wire_avr.S
# Flash (the cube firmware): -mcall-prologues, register saves through
# libgcc's shared sequences (-1.4 KB, ~1% more cycles); -mstrict-X (-0.6
# KB); -mrelax, with ports/xbuild.sh linking with it: calls in reach
# become RCALL (-0.3 KB).
AVR_CFLAGS := -std=c89 -pedantic -Wall -Wextra -Werror -Os -mcall-prologues -mstrict-X -mrelax -DF_CPU=16000000UL \
              -ffunction-sections -fdata-sections $(INC) $(XINC) -DR8_ASM_WIRE
# 6502 assembly (ports/6502/*.s, ca65), in the 6502 library: each
# R8_ASM_* names the kernels that replace their C89 reference (the two go
# together: bench/kern6502.py builds without each) - R8_ASM_MUL16
# mul16_6502.s, R8_ASM_TRAP trap_6502.s, R8_ASM_XFORM xform_6502.s,
# R8_ASM_PROJECT proj_6502.s, R8_ASM_EDGE edge_6502.s, R8_ASM_WIRE
# wire_6502.s and wirec_6502.s (its C entries), R8_ASM_TXBAND
# txband_6502.s (r8_tx_band, r8_tx_pkt; needs wire_6502.s; its offsets
# for the test in txoffs_6502.s), R8_ASM_SCANX scanx_6502.s (r8_scanx_fill), R8_ASM_FILL
# fill_6502.s (r8k_fill); mul_6502.s is their
# quarter-square multiply, rtmul_6502.s replaces cc65's runtime int and
# long multiplies.  tests/c/test_mul.c, test_kern.c, test_wirek.c,
# test_txband.c and test_scanx.c compare them with the C in sim65.  Programs link with ports/6502/
# rast8.cfg (R8PAGE: the tables' page-aligned RAM) and ports/6502/gc65.py
# (function-level dead code removal; C65_GC=0: off); one that does not fit
# is linked again with ports/6502/ckern.s65 (the C versions of txband,
# scanx and fill: ports/xbuild.sh; txband stays the kernel in a firmware
# built with R8_TXBAND_ALL, FWK_6502 below).
C65_ASM    := $(wildcard ports/6502/*.s)
C65_ASMDEF := -DR8_ASM_MUL16 -DR8_ASM_TRAP -DR8_ASM_WIRE -DR8_ASM_TXBAND -DR8_ASM_SCANX -DR8_ASM_FILL -DR8_ASM_XFORM -DR8_ASM_PROJECT -DR8_ASM_EDGE
C65_CFLAGS := -t sim6502 --standard c89 -W +error,-const-comparison -Or -Cl -g $(C65_ASMDEF) $(INC) $(XINC)
# Z80 assembly kernels (ports/z80/NAME_z80.s, sdas): Z80_ASM=1 (default)
# links them all, Z80_ASM=0 none (the C89 references), or a list of NAMEs:
#   mul16    r8_mul16 (-DR8_ASM_MUL16); the multiply helpers the others
#            use (mulz_z80.s) are in with any kernel
#   mullong  sdcc's __mullong (long * long), ahead of z80.lib's
#   mulint   sdcc's __mulint and __mul16 (int * int), the same way
#   wire     the wire encoder's kernels (-DR8_ASM_WIRE, src/r8crc.h)
#   trap xform project edge fill   the kernels of include/r8kern.h
#            (-DR8_ASM_TRAP ...: src/kern.c leaves its references out)
#   (with wire, plat_z80.c's plat_write is its assembly loop too)
#   txband   r8_tx_band, one band onto the wire (-DR8_ASM_TXBAND; only
#            with wire; tests/c/test_txband.c in step xunit-z80)
#   scanx    r8_scanx_fill, a polygon's trapezoids in a band
#            (-DR8_ASM_SCANX; tests/c/test_scanx.c in step xunit-z80)
#   cull     r8k_cull, a face's 16-bit back-face test (-DR8_ASM_CULL, in
#            Z80_CFLAGS: the spin firmware's render.c calls it in place of
#            r8_cull_front, ports/fw_trim.c R8_CULL16; reference src/kern.c)
#   tframe   r8_tf_frame's arithmetic: r8k_rotoff (its rot_offset) and
#            r8_mat_apply_t14 (-DR8_ASM_TFRAME, in Z80_CFLAGS: the
#            firmware compiles transform.c itself; references src/r8tfref.h)
#   scanband r8k_scanband, a face's page-1 band (-DR8_ASM_SCANFILL, in
#            Z80_CFLAGS: render.c's draw_face calls it, R8_BANDK;
#            reference src/scanband.c)
#   band     r8_render_band in the cull firmware's configuration
#            (-DR8_ASM_BAND, in Z80_CFLAGS; reference: render.c's
#            r8_render_band_c)
# build/x/z80-kernels.txt records the choice (a change rebuilds the Z80
# library); tests/targets/test_z80_kern.c (step xkern-z80) checks trap,
# fill, xform, project, edge, tframe and the multiplies against their references
# whatever Z80_ASM says, and
# tests/c/test_wirek.c (step xunit-z80) the wire kernels when linked.
# bench/kernz80.py: the cube's T-states per frame with and without each.
# Z80 programs link through ports/z80/gcz80.py (ports/xbuild.sh): only the
# functions and data _main reaches, from the .asm sdcc -c leaves beside
# each object (sdld links whole modules); Z80_GC=0 (environment or make
# command line) links the objects and rast8.lib whole, as before.
Z80_ASM    ?= 1
Z80_KALL   := mul16 mullong mulint wire trap fill xform project edge txband scanx tframe scanband band cull
Z80_KERN0  := $(if $(filter 1,$(Z80_ASM)),$(Z80_KALL),$(filter $(Z80_KALL),$(Z80_ASM)))
# txband (txband_z80.s, R8_ASM_TXBAND: r8_tx_band) calls wire's kernels
Z80_KERN   := $(if $(filter wire,$(Z80_KERN0)),$(Z80_KERN0),$(filter-out txband,$(Z80_KERN0)))
Z80_KOBJS  := $(if $(Z80_KERN),$(XB)/z80/obj/mulz_z80.rel) $(Z80_KERN:%=$(XB)/z80/obj/%_z80.rel)
Z80_KDEFS  := $(if $(filter mul16,$(Z80_KERN)),-DR8_ASM_MUL16) $(if $(filter trap,$(Z80_KERN)),-DR8_ASM_TRAP) \
              $(if $(filter xform,$(Z80_KERN)),-DR8_ASM_XFORM) $(if $(filter project,$(Z80_KERN)),-DR8_ASM_PROJECT) \
              $(if $(filter edge,$(Z80_KERN)),-DR8_ASM_EDGE) $(if $(filter fill,$(Z80_KERN)),-DR8_ASM_FILL)
Z80_KSTAMP := $(XB)/z80-kernels.txt
Z80_CFLAGS := -mz80 --std-c89 --opt-code-speed $(INC) $(XINC) $(if $(filter wire,$(Z80_KERN)),-DR8_ASM_WIRE) \
              $(if $(filter txband,$(Z80_KERN)),-DR8_ASM_TXBAND) $(if $(filter scanx,$(Z80_KERN)),-DR8_ASM_SCANX) \
              $(if $(filter tframe,$(Z80_KERN)),-DR8_ASM_TFRAME) $(if $(filter scanband,$(Z80_KERN)),-DR8_ASM_SCANFILL) \
              $(if $(filter band,$(Z80_KERN)),-DR8_ASM_BAND) $(if $(filter cull,$(Z80_KERN)),-DR8_ASM_CULL)
XENV := AVR_CFLAGS="$(AVR_CFLAGS)" C65_CFLAGS="$(C65_CFLAGS)" Z80_CFLAGS="$(Z80_CFLAGS)" $(if $(Z80_GC),Z80_GC="$(Z80_GC)")
AVR_ASM    ?= 1
AVR_KALL   := trap xform edge project fill facecull facelevel facez zfill fwalk vertex
AVR_KERN0  := $(if $(filter 1,$(AVR_ASM)),$(AVR_KALL),$(filter $(AVR_KALL),$(AVR_ASM)))
# vertex (vertex.S, R8_ASM_VERTEX: r8k_vertex) reads project.S's reciprocal table
AVR_KERN   := $(if $(filter project,$(AVR_KERN0)),$(AVR_KERN0),$(filter-out vertex,$(AVR_KERN0)))
AVR_KDEFS  := $(if $(filter trap,$(AVR_KERN)),-DR8_ASM_TRAP -DR8_ASM_SCANFILL) $(if $(filter xform,$(AVR_KERN)),-DR8_ASM_XFORM) \
              $(if $(filter edge,$(AVR_KERN)),-DR8_ASM_EDGE -DR8_ASM_ESTART) $(if $(filter project,$(AVR_KERN)),-DR8_ASM_PROJECT) \
              $(if $(filter fill,$(AVR_KERN)),-DR8_ASM_FILL) $(if $(filter facecull,$(AVR_KERN)),-DR8_ASM_CULL) \
              $(if $(filter facelevel,$(AVR_KERN)),-DR8_ASM_LEVEL) $(if $(filter facez,$(AVR_KERN)),-DR8_ASM_ZSUM) \
              $(if $(filter zfill,$(AVR_KERN)),-DR8_ASM_ZFILL) $(if $(filter fwalk,$(AVR_KERN)),-DR8_ASM_FWALK) \
              $(if $(filter vertex,$(AVR_KERN)),-DR8_ASM_VERTEX -DR8_ASM_DEPTH)
AVR_KSTAMP := $(XB)/avr-kernels.txt
MCU_avr328  := atmega328p
MCU_avr1284 := atmega1284p
EXT_avr328  := elf
EXT_avr1284 := elf
EXT_6502    := prg
EXT_z80     := ihx
OBJ_avr328  := o
OBJ_avr1284 := o
OBJ_6502    := o
OBJ_z80     := rel
LIBA_avr328  := librast8.a
LIBA_avr1284 := librast8.a
LIBA_6502    := rast8.lib
LIBA_z80     := rast8.lib
PLAT_avr328  := plat_avr
PLAT_avr1284 := plat_avr
PLAT_6502    := plat_sim65
PLAT_z80     := plat_z80

# ---- the libsimavr runner and the host reference firmware
$(AVRSIM): emu/avrsim.c
	@mkdir -p $(dir $@)
	$(CC) -O2 -Wall $$(pkg-config --cflags simavr) -o $@ $< $$(pkg-config --libs --static simavr) -lutil

# the 6502 profiler: sim65's CPU and paravirtual I/O, cycles per function
$(BUILD)/emu/prof65: emu/prof65.c
	@mkdir -p $(dir $@)
	$(CC) -O2 -Wall -Wextra -std=gnu99 -o $@ $<

# the Z80 profiler (emu/z80sim.c: Zilog T-states per function; -u: ucsim's)
$(Z80SIM): emu/z80sim.c
	@mkdir -p $(dir $@)
	$(CC) -O2 -Wall -Wextra -std=c99 -o $@ $<

$(FWHOST): $(FW_SRC) emu/fw_plat_host.c $(XLIB_SRC) $(SCENE_SRC) $(XHDRS)
	@mkdir -p $(dir $@)
	$(CC) $(STRICT) -O2 -g $(INC) $(XINC) -DFW_HOST $(FW_DEFS) -o $@ $(FW_SRC) emu/fw_plat_host.c $(XLIB_SRC) $(SCENE_SRC)

# ---- one scene's meshes (target independent)
$(XB)/scenes/scene_%.c: $(wildcard scenes/*.c scenes/*.h) ports/scene_strip.py
	@mkdir -p $(dir $@)
	python3 ports/scene_strip.py $* > $@
# keep chained intermediates (scene tables, plat/unity/scene objects)
.SECONDARY: $(XSCENES:%=$(XB)/scenes/scene_%.c) \
  $(foreach t,avr328 avr1284 6502,$(XB)/$(t)/obj/unity_target.o $(XSCENES:%=$(XB)/$(t)/obj/scene_%.o)) \
  $(XB)/z80/obj/unity_target.rel $(XSCENES:%=$(XB)/z80/obj/scene_%.rel)

# The targets' wire encoder is built without Huffman, LZW and the
# per-band choice (issue 13: src/huff.c and src/lzw.c stay in the
# archive for the unit tests, but no firmware links them): the
# firmwares' flash does not grow.
$(XB)/%/obj/wire.o $(XB)/z80/obj/wire.rel: XNO := -DR8_NO_HUFF -DR8_NO_LZW

# ---- compile rules per target (library, plat, unity, scene tables)
# (the kernel stamp: rewritten only when AVR_ASM chooses other kernels)
$(AVR_KSTAMP): avr-kstamp-force
	@mkdir -p $(dir $@) && echo "$(AVR_KERN) $(AVR_CFLAGS)" | cmp -s - $@ || echo "$(AVR_KERN) $(AVR_CFLAGS)" > $@
avr-kstamp-force:
define AVR_OBJ
$(XB)/$(1)/obj/%.o: src/%.c $(XHDRS) $(AVR_KSTAMP)
	@mkdir -p $$(dir $$@)
	avr-gcc -mmcu=$(MCU_$(1)) $(AVR_CFLAGS) $(AVR_KDEFS) $$(XNO) -c $$< -o $$@
$(XB)/$(1)/obj/%.o: ports/avr/%.c $(XHDRS) $(AVR_KSTAMP)
	@mkdir -p $$(dir $$@)
	avr-gcc -mmcu=$(MCU_$(1)) $(AVR_CFLAGS) -c $$< -o $$@
$(XB)/$(1)/obj/%.o: ports/avr/%.S $(AVR_KSTAMP)
	@mkdir -p $$(dir $$@)
	avr-gcc -mmcu=$(MCU_$(1)) $(AVR_CFLAGS) -c $$< -o $$@
$(XB)/$(1)/obj/%.o: examples/spin/%.c $(XHDRS) $(AVR_KSTAMP)
	@mkdir -p $$(dir $$@)
	avr-gcc -mmcu=$(MCU_$(1)) $(AVR_CFLAGS) -c $$< -o $$@
$(XB)/$(1)/obj/%.o: $(XB)/scenes/%.c $(XHDRS) $(AVR_KSTAMP)
	@mkdir -p $$(dir $$@)
	avr-gcc -mmcu=$(MCU_$(1)) $(AVR_CFLAGS) -c $$< -o $$@
$(XB)/$(1)/obj/%.o: tests/targets/%.c $(XHDRS) $(AVR_KSTAMP) tests/unity/unity.c tests/unity/unity.h
	@mkdir -p $$(dir $$@)
	avr-gcc -mmcu=$(MCU_$(1)) $(AVR_CFLAGS) -Itests/unity -c $$< -o $$@
$(XB)/$(1)/librast8.a: $(XOBJ_NAMES:%=$(XB)/$(1)/obj/%.o) $(AVR_KERN:%=$(XB)/$(1)/obj/%.o) $(if $(filter fwalk,$(AVR_KERN)),$(XB)/$(1)/obj/fwpaint.o) $(AVR_WIRE_S:ports/avr/%.S=$(XB)/$(1)/obj/%.o) $(AVR_KSTAMP)
	rm -f $$@ && avr-ar rcs $$@ $$(filter %.o,$$^)
endef
$(eval $(call AVR_OBJ,avr328))
$(eval $(call AVR_OBJ,avr1284))

$(XB)/6502/obj/%.o: src/%.c $(XHDRS)
	@mkdir -p $(dir $@)
	bash ports/6502/cc65c.sh $@ $< $(C65_CFLAGS) $(XNO)
$(XB)/6502/obj/%.o: ports/6502/%.c $(XHDRS)
	@mkdir -p $(dir $@)
	bash ports/6502/cc65c.sh $@ $< $(C65_CFLAGS)
$(XB)/6502/obj/%.o: examples/spin/%.c $(XHDRS)
	@mkdir -p $(dir $@)
	bash ports/6502/cc65c.sh $@ $< $(C65_CFLAGS)
$(XB)/6502/obj/%.o: $(XB)/scenes/%.c $(XHDRS)
	@mkdir -p $(dir $@)
	bash ports/6502/cc65c.sh $@ $< $(C65_CFLAGS)
$(XB)/6502/obj/%.o: tests/targets/%.c $(XHDRS) tests/unity/unity.c tests/unity/unity.h
	@mkdir -p $(dir $@)
	bash ports/6502/cc65c.sh $@ $< $(C65_CFLAGS) -Itests/unity
$(XB)/6502/obj/%.o: ports/6502/%.s
	@mkdir -p $(dir $@)
	ca65 -g -t sim6502 -o $@ $<
$(XB)/6502/rast8.lib: $(XOBJ_NAMES:%=$(XB)/6502/obj/%.o) $(C65_ASM:ports/6502/%.s=$(XB)/6502/obj/%.o)
	rm -f $@ && ar65 a $@ $^

$(Z80_KSTAMP): z80-kstamp-force
	@mkdir -p $(dir $@) && echo "$(Z80_KERN)" | cmp -s - $@ || echo "$(Z80_KERN)" > $@
z80-kstamp-force:
# the library files a frame spends its time in get sdcc's deeper register
# allocation (~20 s each to compile; the cube's frame -1.7% for wire.c alone)
Z80_HOT := wire scan proj transform cull fixed scankern
# The same search for the firmware's own compile (fw_app.c with render.c,
# scan.c, transform.c, cull.c and app.c in it, ports/fw_trim.c: the
# per-face and per-band C): cube / cull 694,864 -> about 675 k T a frame,
# the image 1.9 KB smaller; ~40 s of sdcc a firmware instead of ~7, so
# only the cube's firmwares (scene 0, the real-time demo) get it: all 56
# Z80 firmwares would add half an hour to make test.
FWOPT_z80 := --max-allocs-per-node 25000
$(Z80_HOT:%=$(XB)/z80/obj/%.rel): Z80_OPT := --max-allocs-per-node 25000
$(XB)/z80/obj/%.rel: src/%.c $(XHDRS) $(Z80_KSTAMP)
	@mkdir -p $(dir $@)
	bash ports/z80/sdcc.sh $(Z80_CFLAGS) $(Z80_KDEFS) $(XNO) $(Z80_OPT) --Werror -c -o $@ $<
$(XB)/z80/obj/%.rel: ports/z80/%.s
	@mkdir -p $(dir $@)
	sdasz80 -o $@ $<
$(XB)/z80/obj/%.rel: ports/z80/%.c $(XHDRS) $(Z80_KSTAMP)
	@mkdir -p $(dir $@)
	bash ports/z80/sdcc.sh $(Z80_CFLAGS) -c -o $@ $<
$(XB)/z80/obj/%.rel: examples/spin/%.c $(XHDRS)
	@mkdir -p $(dir $@)
	bash ports/z80/sdcc.sh $(Z80_CFLAGS) -c -o $@ $<
# (the scenes' set-up, r8_demo_setup, with the deeper search too: ~8 s
# each, the cube's image 277 B smaller)
$(XSCENES:%=$(XB)/z80/obj/scene_%.rel): Z80_OPT := --max-allocs-per-node 25000
$(XB)/z80/obj/%.rel: $(XB)/scenes/%.c $(XHDRS)
	@mkdir -p $(dir $@)
	bash ports/z80/sdcc.sh $(Z80_CFLAGS) $(Z80_OPT) -c -o $@ $<
$(XB)/z80/obj/%.rel: tests/targets/%.c $(XHDRS) tests/unity/unity.c tests/unity/unity.h
	@mkdir -p $(dir $@)
	bash ports/z80/sdcc.sh $(Z80_CFLAGS) -Itests/unity -c -o $@ $<
$(XB)/z80/rast8.lib: $(XOBJ_NAMES:%=$(XB)/z80/obj/%.rel) $(Z80_KOBJS) $(Z80_KSTAMP)
	rm -f $@ && sdar -rc $@ $(filter %.rel,$^)

# ---- programs per target: sizes, firmware, unit tests
# $(1) target.  Sizes come from the 1284P for both AVRs (same ABI; the
# 328P cannot hold every scene's sizer); the 328P's from sizers built
# with its firmware's RAM-saving flags (ports/fwdefs.sh --small328).
XSIZES_avr328  := $(XB)/avr328/sizes.txt
XSIZES_avr1284 := $(XB)/avr1284/sizes.txt
XSIZES_6502    := $(XB)/6502/sizes.txt
XSIZES_z80     := $(XB)/z80/sizes.txt
# the firmware unit (render.c, proj.c built in: ports/fw_trim.c) knows
# which AVR kernels the library links (FW_PROJ16: src/proj.c)
FWK_avr328     = $(AVR_KDEFS)
FWK_avr1284    = $(AVR_KDEFS)
# (the Z80's: whether project_z80.s hands r8_project_recip its rare points;
# R8_TXBAND_ALL: txband_z80.s takes every band of the stream, raw too, so
# src/wire.c leaves its C band path out; R8_ASM_TXPKT: its r8_tx_pkt
# sends FRAME_START / FRAME_END, so tx_send goes too)
FWK_z80        = $(if $(filter project,$(Z80_KERN)),-DR8_ASM_PROJECT) $(if $(filter txband,$(Z80_KERN)),-DR8_TXBAND_ALL -DR8_ASM_TXPKT)
# (the 6502's: txband_6502.s takes every band of the fixed stream, raw
# too, so src/wire.c leaves its C band path out: R8_TXBAND_ALL; and its
# r8_tx_pkt sends FRAME_START / FRAME_END, so tx_send goes too:
# R8_ASM_TXPKT)
FWK_6502       = -DR8_TXBAND_ALL -DR8_ASM_TXPKT
define XPROG
XDEPS_$(1) := $(XB)/$(1)/obj/$(PLAT_$(1)).$(OBJ_$(1)) $(XB)/$(1)/$(LIBA_$(1)) ports/xbuild.sh
XSCENE_OBJS_$(1) := $(XSCENES:%=$(XB)/$(1)/obj/scene_%.$(OBJ_$(1)))

$(XB)/$(1)/sizes/sizes-%.$(EXT_$(1)): tests/targets/fw_sizes.c ports/fw_trim.c $(XB)/$(1)/obj/scene_%.$(OBJ_$(1)) $$(XDEPS_$(1))
	@mkdir -p $$(dir $$@)
	$(XENV) bash ports/xbuild.sh $(1) $$@ $$< $(XB)/$(1)/obj/scene_$$*.$(OBJ_$(1)) -- $(FW_DEFS) -DFW_SCENE=$$* -Isrc -DFW_TRIM_LZ77 -DFW_RENDER -DR8_PLAN_ONLY

$(XB)/$(1)/fw/fw-%.$(EXT_$(1)): $(FW_SRC) ports/fw_trim.c $$(XSCENE_OBJS_$(1)) $$(XDEPS_$(1)) $(XSIZES_$(1)) ports/fwdefs.sh
	@mkdir -p $$(dir $$@)
	$(XENV) bash ports/xbuild.sh $(1) $$@ $$< $(XB)/$(1)/obj/scene_$$$$(echo $$* | cut -d- -f1).$(OBJ_$(1)) \
	  -- $(FW_DEFS) $(FWK_$(1)) $$$$(case $$* in (0-*) echo '$(FWOPT_$(1))' ;; esac) $$$$(bash ports/fwdefs.sh $$* $(XSIZES_$(1)) $(1))

$(XB)/$(1)/micro.$(EXT_$(1)): bench/fw_micro.c $$(XDEPS_$(1))
	$(XENV) bash ports/xbuild.sh $(1) $$@ $$<

$(XB)/$(1)/codecs.$(EXT_$(1)): bench/fw_codecs.c bench/codec_frame.h src/wire.c $$(XDEPS_$(1))
	$(XENV) bash ports/xbuild.sh $(1) $$@ $$< -- -Ibench -Isrc

$(XB)/$(1)/tests/%.$(EXT_$(1)): tests/c/%.c $(XB)/$(1)/obj/unity_target.$(OBJ_$(1)) $$(XDEPS_$(1)) $(XHDRS) $(wildcard tests/c/*.h) tests/targets/wrap.sh ports/xbuild.sh
	@mkdir -p $$(dir $$@)
	@bash tests/targets/wrap.sh $$< > $$(basename $$@).wrap.c
	$(XENV) bash ports/xbuild.sh $(1) $$@ $$(basename $$@).wrap.c $(XB)/$(1)/obj/unity_target.$(OBJ_$(1)) \
	  -- -Itests/unity -Itests/c $(if $(findstring 6502,$(1)),-W -error)
endef
$(foreach t,$(XTARGETS),$(eval $(call XPROG,$(t))))

# sizes.txt: every scene's sizer run on the target; a scene whose sizer
# does not fit gets "S M 0" lines (the identity test skips it, with why).
XSZ = $(XSCENES:%=$(XB)/$(1)/sizes/sizes-%.$(EXT_$(1)))
$(XB)/avr1284/sizes.txt: $(call XSZ,avr1284) $(AVRSIM) tests/targets/sizes.sh
	bash tests/targets/sizes.sh avr1284 $@ $(call XSZ,avr1284)
# Gouraud's arenas (make bench measures every shading): sizers built so
XSZG = $(XSCENES:%=$(XB)/avr1284/sizesg/sizes-%.elf)
$(XB)/avr1284/sizesg/sizes-%.elf: tests/targets/fw_sizes.c ports/fw_trim.c $(XB)/avr1284/obj/scene_%.o $(XDEPS_avr1284)
	@mkdir -p $(dir $@)
	$(XENV) bash ports/xbuild.sh avr1284 $@ $< $(XB)/avr1284/obj/scene_$*.o -- $(FW_DEFS) -DFW_SCENE=$* -Isrc -DFW_TRIM_LZ77 -DFW_RENDER -DR8_PLAN_ONLY -DFW_SHADING=2
$(XB)/avr1284/sizes-sh2.txt: $(XSZG) $(AVRSIM) tests/targets/sizes.sh
	bash tests/targets/sizes.sh avr1284 $@ $(XSZG)
XSZ328 = $(XSCENES:%=$(XB)/avr1284/sizes328/sizes-%.elf)
$(XB)/avr1284/sizes328/sizes-%.elf: tests/targets/fw_sizes.c ports/fw_trim.c ports/fwdefs.sh $(XB)/avr1284/obj/scene_%.o $(XDEPS_avr1284)
	@mkdir -p $(dir $@)
	$(XENV) bash ports/xbuild.sh avr1284 $@ $< $(XB)/avr1284/obj/scene_$*.o -- $(FW_DEFS) -DFW_SCENE=$* -Isrc -DFW_TRIM_LZ77 -DFW_RENDER -DR8_PLAN_ONLY $$(bash ports/fwdefs.sh --small328)
$(XB)/avr328/sizes.txt: $(XSZ328) $(AVRSIM) tests/targets/sizes.sh
	@mkdir -p $(dir $@)
	bash tests/targets/sizes.sh avr1284 $@ $(XSZ328)
$(XB)/6502/sizes.txt: $(call XSZ,6502) tests/targets/sizes.sh
	bash tests/targets/sizes.sh 6502 $@ $(call XSZ,6502)
$(XB)/z80/sizes.txt: $(call XSZ,z80) tests/targets/sizes.sh
	bash tests/targets/sizes.sh z80 $@ $(call XSZ,z80)

# the AVR kernels against their references (src/kern.c, compiled into the
# test under other names, without R8_ASM_*), whatever AVR_ASM says
XKERN := $(XB)/avr1284/tests/avr_kern.elf
XKERN_OBJS := $(AVR_KALL:%=$(XB)/avr1284/obj/%.o) $(XB)/avr1284/obj/fwpaint.o $(XB)/avr1284/obj/unity_target.o
$(XKERN): tests/targets/test_avr_kern.c tests/targets/kern_trap.h tests/targets/kern_cases.h src/kern.c src/zrows.c $(XKERN_OBJS) $(XDEPS_avr1284) $(XHDRS) tests/targets/wrap.sh
	@mkdir -p $(dir $@)
	@bash tests/targets/wrap.sh $< > $(basename $@).wrap.c
	$(XENV) bash ports/xbuild.sh avr1284 $@ $(basename $@).wrap.c $(XKERN_OBJS) -- -Isrc -Itests/unity -Itests/targets

# the Z80 kernels against their references (src/kern.c, compiled into the
# test under other names), whatever Z80_ASM says: every kernel's object
# is linked in (r8_mul16 is the library's; band calls render.c's
# draw_face: tests/c/test_bandz80.c checks it)
XKERNZ := $(XB)/z80/tests/z80_kern1.ihx $(XB)/z80/tests/z80_kern2.ihx
XKERNZ_OBJS := $(XB)/z80/obj/mulz_z80.rel $(patsubst %,$(XB)/z80/obj/%_z80.rel,$(filter-out mul16 txband scanx band,$(Z80_KALL))) \
               $(XB)/z80/obj/unity_target.rel
# (two programs, the cases split by Z80K_PART: one no longer leaves the
# stack its 1 KB in 64 KB)
$(XKERNZ): $(XB)/z80/tests/z80_kern%.ihx: tests/targets/test_z80_kern.c tests/targets/kern_trap.h tests/targets/kern_cases.h src/kern.c $(XKERNZ_OBJS) $(XDEPS_z80) $(XHDRS) tests/targets/wrap.sh
	@mkdir -p $(dir $@)
	@bash tests/targets/wrap.sh $< > $(basename $@).wrap.c
	$(XENV) bash ports/xbuild.sh z80 $@ $(basename $@).wrap.c $(XKERNZ_OBJS) -- -Isrc -Itests/unity -Itests/targets -DZ80K_PART=$*

# ---- test steps
XT_NAMES   := $(TEST_C:tests/c/%.c=%)
XT_avr1284 := $(XT_NAMES:%=$(XB)/avr1284/tests/%.elf)
XT_6502    := $(XT_NAMES:%=$(XB)/6502/tests/%.prg)
XT_z80     := $(XT_NAMES:%=$(XB)/z80/tests/%.ihx)
XREADY := $(AVRSIM) $(FWHOST) $(XB)/avr328/sizes.txt $(XB)/avr1284/sizes.txt $(XB)/6502/sizes.txt $(XB)/z80/sizes.txt

.PHONY: xtargets fw xtest-avr xtest-6502 xtest-z80 xprof-6502
xtargets: $(XREADY) $(XT_avr1284) $(XKERN) $(XT_6502) $(XT_z80) $(XKERNZ)

# Unit tests in the simulators (AVR on the 1284P: 16 KB SRAM).  Every
# test program fits every target today, so one that stops fitting fails
# its step (UNIT_SKIP_FAILS) rather than vanishing from the count.
xtest-avr:
	@UNIT_SKIP_FAILS=1 bash scripts/run-step.sh xunit-avr1284 bash tests/targets/unit.sh avr1284 $(XT_avr1284)
xtest-6502:
	@UNIT_SKIP_FAILS=1 bash scripts/run-step.sh xunit-6502 bash tests/targets/unit.sh 6502 $(XT_6502)
xtest-z80:
	@UNIT_SKIP_FAILS=1 XTEST_TIMEOUT=$(XTEST_TIMEOUT) bash scripts/run-step.sh xunit-z80 bash tests/targets/unit.sh z80 $(XT_z80)
XTEST_TIMEOUT ?= 300

# emu/prof65 against sim65: same cycles, exit code and stream.
xprof-6502:
	@bash scripts/run-step.sh xprof-6502 $(PY) tests/targets/prof65_check.py

# Bit identity: every scene x method that fits, per target, vs the host.
xident-%:
	@bash scripts/run-step.sh xident-$* $(PY) tests/targets/identity.py $*

fw: $(XREADY)
	$(PY) tests/targets/identity.py --build-only $(XTARGETS)

# The AVR assembly kernels against their C references, in the simulator.
.PHONY: xtest-avr-kern xtest-z80-kern bench-codecs xident-codecs
xtest-avr-kern:
	@UNIT_SKIP_FAILS=1 bash scripts/run-step.sh xkern-avr1284 bash tests/targets/unit.sh avr1284 $(XKERN)
# The Z80 assembly kernels against their C references, in ucsim.
xtest-z80-kern:
	@UNIT_SKIP_FAILS=1 XTEST_TIMEOUT=$(XTEST_TIMEOUT) bash scripts/run-step.sh xkern-z80 bash tests/targets/unit.sh z80 $(XKERNZ)

TEST_STEPS += xtest-avr xtest-avr-kern xtest-6502 xtest-z80 xtest-z80-kern xident-avr328 xident-avr1284 xident-6502 xident-z80 xprof-6502

# ---- benchmark
# every target x scene x method, then the portal renderer's walk (mk/portal.mk)
bench: $(SETUP) $(BUILD)/portal_bench
	$(PY) bench/bench.py
	$(PY) bench/bench.py --portal
# only the band codecs' figures (encode/decode cycles per byte per CPU)
bench-codecs: $(SETUP)
	$(PY) bench/codec_bench.py
# the codecs and the wire with the per-band choice give the Python bytes
# on the 1284P, the 6502 and the Z80 (bench/fw_codecs.c)
xident-codecs: $(SETUP)
	@bash scripts/run-step.sh xident-codecs $(PY) bench/codec_bench.py --test
TEST_STEPS += xident-codecs
