# mk/examples.mk - the example applications beside examples/spin
# (issue 11), their host builds, target firmware and checks:
#   build/examples/flythrough    the flythrough on the host (--pty: fly it
#                                from `rast8 view`)
#   build/x/T/fly/fly-F.*        the flythrough firmware for target T
#                                (F frames, the test key script compiled in)
# Targets T: avr328 avr1284 6502 z80 (mk/targets.mk builds their libraries,
# plat objects and scene tables; ports/xbuild.sh links, or writes a
# one-line "SKIP: reason" when a program does not fit).

EXB := $(BUILD)/x
EXH := $(BUILD)/examples
EX_HOST_CFLAGS := -std=gnu99 -Wall -Wextra -Werror -O2 -g
EX_HDRS := ports/plat.h $(wildcard include/*.h src/*.h scenes/*.h)

# compile one C file for a target: $(call ex_cc,TARGET,OUT,SRC,FLAGS)
# (AVR_CFLAGS, C65_CFLAGS and Z80_CFLAGS come from mk/targets.mk)
ex_cc = $(if $(filter avr%,$(1)),avr-gcc -mmcu=$(if $(filter avr328,$(1)),atmega328p,atmega1284p) \
  $(AVR_CFLAGS) $(4) -c $(3) -o $(2),$(if $(filter 6502,$(1)),bash ports/6502/cc65c.sh $(2) $(3) \
  $(C65_CFLAGS) $(4),bash ports/z80/sdcc.sh $(Z80_CFLAGS) $(4) -c -o $(2) $(3)))

# ---- flythrough
FLY_DIR    := examples/flythrough
FLY_HDR    := $(FLY_DIR)/fly.h examples/common/walk_loop.c $(EX_HDRS)
FLY_KEYS   := tests/examples/fly.keys
FLY_FRAMES := 24
FLY_TARGETS := avr328 avr1284 6502 z80
# what the firmware leaves out (fw_fly.c compiles render.c and scan.c in
# with these): the flythrough is painter's, Lambert, SSD1306 pages, RLE,
# meshes with their normals; it keeps the clipper
# the parts no mesh example firmware uses (each costs flash when linked)
EX_NEW_OFF := -DR8_NO_BSP -DR8_NO_WIRE -DR8_NO_PORTAL -DR8_NO_RAY
FLY_XDEFS  := -Isrc -I$(FLY_DIR) -Iexamples/common -I$(EXB)/fly -DFLY_TRIM -DFW_TRIM_LZ77 -DR8_NO_GOURAUD \
  -DR8_NO_RT_NORMALS -DR8_PAGE1_ONLY -DR8_NO_ZBUF -DR8_NO_BLOCK -DR8_NO_SBUF -DR8_NO_TEXTURE \
  $(EX_NEW_OFF)
FLY_FW     := $(EXB)/avr328/fly/fly-$(FLY_FRAMES).elf $(EXB)/avr1284/fly/fly-$(FLY_FRAMES).elf \
  $(EXB)/6502/fly/fly-$(FLY_FRAMES).prg $(EXB)/z80/fly/fly-$(FLY_FRAMES).ihx

ALL_TARGETS += $(EXH)/flythrough

# the keyed walks' host program (flythrough, maze): examples/common
WALK_HOST := examples/common/walk_host.c
WALK_DEPS := $(WALK_HOST) examples/common/walk_host.h
$(EXH)/flythrough: $(FLY_DIR)/fly_host.c $(FLY_DIR)/fly.c emu/plat_host.c emu/plat_host.h $(FLY_HDR) $(LIBS) $(WALK_DEPS)
	@mkdir -p $(dir $@)
	$(CC) $(EX_HOST_CFLAGS) $(INC) -Iemu -Iports -I$(FLY_DIR) -Iexamples/common $(FLY_DIR)/fly_host.c $(FLY_DIR)/fly.c \
	  $(WALK_HOST) emu/plat_host.c $(LIBS) -o $@

# the key script as the INPUT packets a display sends (fw_fly.c FLY_KEYS)
# (and as bytes for the UART: emu/avrsim -i, the FLY_UART firmware)
$(EXB)/fly/fly_keys.h: $(FLY_KEYS) $(FLY_DIR)/keys2c.py $(SETUP)
	@mkdir -p $(dir $@)
	$(PY) $(FLY_DIR)/keys2c.py $(FLY_KEYS) -o $@ --bin $(EXB)/fly/fly_keys.bin

$(EXB)/%/fly/fly.o: $(FLY_DIR)/fly.c $(FLY_HDR)
	@mkdir -p $(dir $@)
	$(call ex_cc,$*,$@,$<,$(FLY_XDEFS))
$(EXB)/z80/fly/fly.rel: $(FLY_DIR)/fly.c $(FLY_HDR)
	@mkdir -p $(dir $@)
	$(call ex_cc,z80,$@,$<,$(FLY_XDEFS))

# link: $(call fly_link,TARGET,OUT,OBJ-EXT,EXTRA-FLAGS)
fly_link = $(XENV) bash ports/xbuild.sh $(1) $(2) $(FLY_DIR)/fw_fly.c $(EXB)/$(1)/fly/fly.$(3) \
  $(EXB)/$(1)/obj/scene_3.$(3) -- $(FLY_XDEFS) $(4)
# the firmware: the arena is fly_ram() as the sizer measured it on the target
fly_fw = if head -c 5 $(EXB)/$(1)/fly/ram.txt | grep -q '^SKIP:'; then cp $(EXB)/$(1)/fly/ram.txt $(2); \
  else $(call fly_link,$(1),$(2),$(3),-DFLY_KEYS -DFLY_FRAMES=$(FLY_FRAMES) -DFLY_RAM=$$(cat $(EXB)/$(1)/fly/ram.txt)); fi

FLY_DEPS = $(FLY_DIR)/fw_fly.c examples/common/fw_walk.c ports/fw_trim.c ports/xbuild.sh src/render.c src/scan.c
$(EXB)/%/fly/size.elf: $(FLY_DEPS) $(EXB)/%/fly/fly.o $(EXB)/%/obj/scene_3.o $(EXB)/%/obj/plat_avr.o $(EXB)/%/librast8.a
	$(call fly_link,$*,$@,o,-DFLY_SIZE_ONLY)
$(EXB)/6502/fly/size.prg: $(FLY_DEPS) $(EXB)/6502/fly/fly.o $(EXB)/6502/obj/scene_3.o $(EXB)/6502/obj/plat_sim65.o $(EXB)/6502/rast8.lib
	$(call fly_link,6502,$@,o,-DFLY_SIZE_ONLY)
$(EXB)/z80/fly/size.ihx: $(FLY_DEPS) $(EXB)/z80/fly/fly.rel $(EXB)/z80/obj/scene_3.rel $(EXB)/z80/obj/plat_z80.rel $(EXB)/z80/rast8.lib
	$(call fly_link,z80,$@,rel,-DFLY_SIZE_ONLY)

$(EXB)/%/fly/ram.txt: tests/examples/size_run.sh $(BUILD)/emu/avrsim
	bash tests/examples/size_run.sh $* $(filter %/size.elf %/size.prg %/size.ihx,$^) $@
$(EXB)/avr328/fly/ram.txt: $(EXB)/avr328/fly/size.elf
$(EXB)/avr1284/fly/ram.txt: $(EXB)/avr1284/fly/size.elf
$(EXB)/6502/fly/ram.txt: $(EXB)/6502/fly/size.prg
$(EXB)/z80/fly/ram.txt: $(EXB)/z80/fly/size.ihx

$(EXB)/%/fly/fly-$(FLY_FRAMES).elf: $(EXB)/%/fly/ram.txt $(EXB)/fly/fly_keys.h $(EXB)/%/fly/size.elf
	$(call fly_fw,$*,$@,o)
# the ATmega1284P with the keys over its UART (plat_getc) instead
$(EXB)/avr1284/fly/fly-uart-$(FLY_FRAMES).elf: $(EXB)/avr1284/fly/ram.txt $(EXB)/fly/fly_keys.h $(EXB)/avr1284/fly/size.elf
	$(call fly_link,avr1284,$@,o,-DFLY_KEYS -DFLY_UART -DFLY_FRAMES=$(FLY_FRAMES) -DFLY_RAM=$$(cat $(EXB)/avr1284/fly/ram.txt))
$(EXB)/6502/fly/fly-$(FLY_FRAMES).prg: $(EXB)/6502/fly/ram.txt $(EXB)/fly/fly_keys.h $(EXB)/6502/fly/size.prg
	$(call fly_fw,6502,$@,o)
$(EXB)/z80/fly/fly-$(FLY_FRAMES).ihx: $(EXB)/z80/fly/ram.txt $(EXB)/fly/fly_keys.h $(EXB)/z80/fly/size.ihx
	$(call fly_fw,z80,$@,rel)

.SECONDARY: $(foreach t,avr328 avr1284 6502,$(EXB)/$(t)/fly/fly.o $(EXB)/$(t)/obj/scene_3.o) \
  $(EXB)/z80/fly/fly.rel $(EXB)/z80/obj/scene_3.rel

.PHONY: fly-fw test-flythrough
fly-fw: $(EXH)/flythrough $(FLY_FW)

# the host build against a fixed key script, then every target's stream
# byte for byte against it (tests/examples/fly_check.py)
test-flythrough: $(SETUP)
	@bash scripts/run-step.sh flythrough $(PY) tests/examples/fly_check.py --frames $(FLY_FRAMES)

TEST_STEPS += test-flythrough

# ---- ssd1306: an ATmega328P drawing on an SSD1306 over SPI
#   build/emu/ssd1306sim          libsimavr + simavr's SSD1306 part on SPI
#   build/examples/ssd1306        the same application on the host
#   build/x/avr328/oled/oled-F.elf  the firmware (F frames; -small: its
#                                 arena one byte under oled_cube_ram())
OLED_DIR    := examples/ssd1306
OLED_HDR    := $(OLED_DIR)/oled_cube.h $(OLED_DIR)/ssd1306_spi.h $(EX_HDRS)
OLED_FRAMES := 16
OLED_STEP   := 5
OLED_X      := $(EXB)/avr328/oled
OLED_XDEFS  := -Isrc -I$(OLED_DIR) -DOLED_TRIM -DR8_NO_PAINTER -DR8_NO_ZBUF -DR8_NO_BLOCK \
  -DR8_NO_SBUF -DR8_NO_GOURAUD -DR8_NO_RT_NORMALS -DR8_NO_CLIP -DR8_PAGE1_ONLY -DR8_NO_TEXTURE \
  $(EX_NEW_OFF)
OLED_OBJS   := $(OLED_X)/oled_cube.o $(OLED_X)/ssd1306_spi.o
SSDSIM      := $(BUILD)/emu/ssd1306sim

ALL_TARGETS += $(EXH)/ssd1306

$(SSDSIM): emu/ssd1306sim.c
	@mkdir -p $(dir $@)
	$(CC) -O2 -Wall -Wextra $$(pkg-config --cflags simavr simavrparts) -o $@ $< \
	  -l:libsimavrparts.a $$(pkg-config --libs simavr) -lelf

$(EXH)/ssd1306: $(OLED_DIR)/ssd1306_host.c $(OLED_DIR)/oled_cube.c $(OLED_HDR) $(LIBS)
	@mkdir -p $(dir $@)
	$(CC) $(STRICT) -O2 $(INC) -I$(OLED_DIR) $(OLED_DIR)/ssd1306_host.c $(OLED_DIR)/oled_cube.c $(LIBS) -o $@

$(OLED_X)/%.o: $(OLED_DIR)/%.c $(OLED_HDR)
	@mkdir -p $(dir $@)
	$(call ex_cc,avr328,$@,$<,$(OLED_XDEFS))

oled_link = $(XENV) bash ports/xbuild.sh avr328 $(1) $(OLED_DIR)/fw_ssd1306.c $(OLED_OBJS) -- $(OLED_XDEFS) $(2)
OLED_DEPS = $(OLED_DIR)/fw_ssd1306.c $(OLED_OBJS) $(EXB)/avr328/obj/plat_avr.o $(EXB)/avr328/librast8.a \
  ports/xbuild.sh src/render.c src/scan.c
$(OLED_X)/size.elf: $(OLED_DEPS)
	$(call oled_link,$@,-DOLED_SIZE_ONLY)
$(OLED_X)/ram.txt: $(OLED_X)/size.elf tests/examples/size_run.sh $(BUILD)/emu/avrsim
	bash tests/examples/size_run.sh avr328 $< $@
$(OLED_X)/oled-$(OLED_FRAMES).elf: $(OLED_DEPS) $(OLED_X)/ram.txt
	$(call oled_link,$@,-DOLED_FRAMES=$(OLED_FRAMES) -DOLED_STEP=$(OLED_STEP) -DOLED_RAM=$$(cat $(OLED_X)/ram.txt))
$(OLED_X)/oled-small.elf: $(OLED_DEPS) $(OLED_X)/ram.txt
	$(call oled_link,$@,-DOLED_FRAMES=$(OLED_FRAMES) -DOLED_STEP=$(OLED_STEP) -DOLED_RAM=$$(($$(cat $(OLED_X)/ram.txt) - 1)))

# the Arduino sketch (make arduino): examples/ssd1306/ssd1306.ino and these
ARDUINO_FILES_ssd1306 := $(OLED_DIR)/oled_cube.c $(OLED_DIR)/oled_cube.h $(OLED_DIR)/ssd1306_spi.c \
  $(OLED_DIR)/ssd1306_spi.h

.PHONY: test-ssd1306
# simavr's SSD1306 display RAM after every frame against the host build
# and r8dump (tests/examples/ssd1306_check.py)
# (the zip through the phony `arduino`: mk/package.mk, where ARDUINO_ZIP
# is set, is read after this file)
test-ssd1306: $(SETUP) arduino
	@bash scripts/run-step.sh ssd1306 $(PY) tests/examples/ssd1306_check.py --frames $(OLED_FRAMES) --step $(OLED_STEP)

TEST_STEPS += test-ssd1306

# ---- two-objects: the analyser's choice for two separate convex objects
TWO_DIR := examples/two-objects
ALL_TARGETS += $(EXH)/two-objects

$(EXH)/two-objects: $(TWO_DIR)/two_host.c $(TWO_DIR)/two.c $(TWO_DIR)/two.h $(EX_HDRS) $(LIB)
	@mkdir -p $(dir $@)
	$(CC) $(EX_HOST_CFLAGS) $(INC) -I$(TWO_DIR) $(TWO_DIR)/two_host.c $(TWO_DIR)/two.c $(LIB) -o $@

.PHONY: test-two-objects test-examples-c89
test-two-objects: $(EXH)/two-objects $(SETUP)
	@bash scripts/run-step.sh two-objects $(PY) tests/examples/two_check.py

# the examples' application files run on the targets: the library's C89
# gate (gcc, clang) and the three cross compilers
test-examples-c89:
	@bash scripts/run-step.sh examples-c89 bash tests/examples/c89.sh

TEST_STEPS += test-two-objects test-examples-c89

# ---- maze: a first-person walk drawn by the ray caster (issue 14)
#   build/examples/maze           the walk on the host (--pty: walk it from
#                                 `rast8 view`)
#   build/x/T/maze/maze-F.*       its firmware for target T (F frames, the
#                                 test key script compiled in)
MAZE_DIR    := examples/maze
MAZE_HDR    := $(MAZE_DIR)/maze.h examples/common/walk_loop.c $(EX_HDRS)
MAZE_KEYS   := tests/examples/maze.keys
MAZE_FRAMES := 56
MAZE_TARGETS := avr328 avr1284 6502 z80
# the walk is the ray caster only: every mesh method, Gouraud, the
# clipper and run-time normals left out (render.c and scan.c compiled in)
MAZE_XDEFS  := -Isrc -I$(MAZE_DIR) -Iexamples/common -I$(EXB)/maze -DMAZE_TRIM -DFW_TRIM_LZ77 -DR8_NO_GOURAUD \
  -DR8_NO_RT_NORMALS -DR8_PAGE1_ONLY -DR8_NO_PAINTER -DR8_NO_ZBUF -DR8_NO_BLOCK -DR8_NO_SBUF -DR8_NO_CLIP \
  -DR8_NO_TEXTURE -DR8_NO_BSP -DR8_NO_WIRE -DR8_NO_PORTAL -DR8_NO_FWALK
MAZE_FW     := $(EXB)/avr328/maze/maze-$(MAZE_FRAMES).elf $(EXB)/avr1284/maze/maze-$(MAZE_FRAMES).elf \
  $(EXB)/6502/maze/maze-$(MAZE_FRAMES).prg $(EXB)/z80/maze/maze-$(MAZE_FRAMES).ihx

ALL_TARGETS += $(EXH)/maze

$(EXH)/maze: $(MAZE_DIR)/maze_host.c $(MAZE_DIR)/maze.c emu/plat_host.c emu/plat_host.h $(MAZE_HDR) $(LIBS) $(WALK_DEPS)
	@mkdir -p $(dir $@)
	$(CC) $(EX_HOST_CFLAGS) $(INC) -Iemu -Iports -I$(MAZE_DIR) -Iexamples/common $(MAZE_DIR)/maze_host.c $(MAZE_DIR)/maze.c \
	  $(WALK_HOST) emu/plat_host.c $(LIBS) -o $@

$(EXB)/maze/maze_keys.h: $(MAZE_KEYS) $(FLY_DIR)/keys2c.py $(SETUP)
	@mkdir -p $(dir $@)
	$(PY) $(FLY_DIR)/keys2c.py $(MAZE_KEYS) -o $@ --bin $(EXB)/maze/maze_keys.bin

$(EXB)/%/maze/maze.o: $(MAZE_DIR)/maze.c $(MAZE_HDR)
	@mkdir -p $(dir $@)
	$(call ex_cc,$*,$@,$<,$(MAZE_XDEFS))
$(EXB)/z80/maze/maze.rel: $(MAZE_DIR)/maze.c $(MAZE_HDR)
	@mkdir -p $(dir $@)
	$(call ex_cc,z80,$@,$<,$(MAZE_XDEFS))

maze_link = $(XENV) bash ports/xbuild.sh $(1) $(2) $(MAZE_DIR)/fw_maze.c $(EXB)/$(1)/maze/maze.$(3) \
  $(EXB)/$(1)/obj/scene_8.$(3) -- $(MAZE_XDEFS) $(4)
maze_fw = if head -c 5 $(EXB)/$(1)/maze/ram.txt | grep -q '^SKIP:'; then cp $(EXB)/$(1)/maze/ram.txt $(2); \
  else $(call maze_link,$(1),$(2),$(3),-DMAZE_KEYS -DMAZE_FRAMES=$(MAZE_FRAMES) -DMAZE_RAM=$$(cat $(EXB)/$(1)/maze/ram.txt)); fi

MAZE_DEPS = $(MAZE_DIR)/fw_maze.c examples/common/fw_walk.c ports/fw_trim.c ports/xbuild.sh src/render.c src/scan.c src/raycast.c
$(EXB)/%/maze/size.elf: $(MAZE_DEPS) $(EXB)/%/maze/maze.o $(EXB)/%/obj/scene_8.o $(EXB)/%/obj/plat_avr.o $(EXB)/%/librast8.a
	$(call maze_link,$*,$@,o,-DMAZE_SIZE_ONLY)
$(EXB)/6502/maze/size.prg: $(MAZE_DEPS) $(EXB)/6502/maze/maze.o $(EXB)/6502/obj/scene_8.o $(EXB)/6502/obj/plat_sim65.o $(EXB)/6502/rast8.lib
	$(call maze_link,6502,$@,o,-DMAZE_SIZE_ONLY)
$(EXB)/z80/maze/size.ihx: $(MAZE_DEPS) $(EXB)/z80/maze/maze.rel $(EXB)/z80/obj/scene_8.rel $(EXB)/z80/obj/plat_z80.rel $(EXB)/z80/rast8.lib
	$(call maze_link,z80,$@,rel,-DMAZE_SIZE_ONLY)

$(EXB)/%/maze/ram.txt: tests/examples/size_run.sh $(BUILD)/emu/avrsim
	bash tests/examples/size_run.sh $* $(filter %/size.elf %/size.prg %/size.ihx,$^) $@
$(EXB)/avr328/maze/ram.txt: $(EXB)/avr328/maze/size.elf
$(EXB)/avr1284/maze/ram.txt: $(EXB)/avr1284/maze/size.elf
$(EXB)/6502/maze/ram.txt: $(EXB)/6502/maze/size.prg
$(EXB)/z80/maze/ram.txt: $(EXB)/z80/maze/size.ihx

$(EXB)/%/maze/maze-$(MAZE_FRAMES).elf: $(EXB)/%/maze/ram.txt $(EXB)/maze/maze_keys.h $(EXB)/%/maze/size.elf
	$(call maze_fw,$*,$@,o)
$(EXB)/6502/maze/maze-$(MAZE_FRAMES).prg: $(EXB)/6502/maze/ram.txt $(EXB)/maze/maze_keys.h $(EXB)/6502/maze/size.prg
	$(call maze_fw,6502,$@,o)
$(EXB)/z80/maze/maze-$(MAZE_FRAMES).ihx: $(EXB)/z80/maze/ram.txt $(EXB)/maze/maze_keys.h $(EXB)/z80/maze/size.ihx
	$(call maze_fw,z80,$@,rel)

.SECONDARY: $(foreach t,avr328 avr1284 6502,$(EXB)/$(t)/maze/maze.o $(EXB)/$(t)/obj/scene_8.o) \
  $(EXB)/z80/maze/maze.rel $(EXB)/z80/obj/scene_8.rel

# the textured maze's walk (MAZE_TEXTURED, scenes/maze.c tmaze = scene 10):
# the same rules under build/x/T/tmaze/, the ray caster's textures only
TMAZE_XDEFS := $(MAZE_XDEFS) -DMAZE_TEXTURED -DR8_RAY_TEXTURE
TMAZE_FW    := $(EXB)/avr328/tmaze/tmaze-$(MAZE_FRAMES).elf $(EXB)/avr1284/tmaze/tmaze-$(MAZE_FRAMES).elf \
  $(EXB)/6502/tmaze/tmaze-$(MAZE_FRAMES).prg $(EXB)/z80/tmaze/tmaze-$(MAZE_FRAMES).ihx
$(EXB)/%/tmaze/maze.o: $(MAZE_DIR)/maze.c $(MAZE_HDR)
	@mkdir -p $(dir $@)
	$(call ex_cc,$*,$@,$<,$(TMAZE_XDEFS))
$(EXB)/z80/tmaze/maze.rel: $(MAZE_DIR)/maze.c $(MAZE_HDR)
	@mkdir -p $(dir $@)
	$(call ex_cc,z80,$@,$<,$(TMAZE_XDEFS))
tmaze_link = $(XENV) bash ports/xbuild.sh $(1) $(2) $(MAZE_DIR)/fw_maze.c $(EXB)/$(1)/tmaze/maze.$(3) \
  $(EXB)/$(1)/obj/scene_10.$(3) -- $(TMAZE_XDEFS) $(4)
tmaze_fw = if head -c 5 $(EXB)/$(1)/tmaze/ram.txt | grep -q '^SKIP:'; then cp $(EXB)/$(1)/tmaze/ram.txt $(2); \
  else $(call tmaze_link,$(1),$(2),$(3),-DMAZE_KEYS -DMAZE_FRAMES=$(MAZE_FRAMES) -DMAZE_RAM=$$(cat $(EXB)/$(1)/tmaze/ram.txt)); fi
$(EXB)/%/tmaze/size.elf: $(MAZE_DEPS) $(EXB)/%/tmaze/maze.o $(EXB)/%/obj/scene_10.o $(EXB)/%/obj/plat_avr.o $(EXB)/%/librast8.a
	$(call tmaze_link,$*,$@,o,-DMAZE_SIZE_ONLY)
$(EXB)/6502/tmaze/size.prg: $(MAZE_DEPS) $(EXB)/6502/tmaze/maze.o $(EXB)/6502/obj/scene_10.o $(EXB)/6502/obj/plat_sim65.o $(EXB)/6502/rast8.lib
	$(call tmaze_link,6502,$@,o,-DMAZE_SIZE_ONLY)
$(EXB)/z80/tmaze/size.ihx: $(MAZE_DEPS) $(EXB)/z80/tmaze/maze.rel $(EXB)/z80/obj/scene_10.rel $(EXB)/z80/obj/plat_z80.rel $(EXB)/z80/rast8.lib
	$(call tmaze_link,z80,$@,rel,-DMAZE_SIZE_ONLY)
$(EXB)/%/tmaze/ram.txt: tests/examples/size_run.sh $(BUILD)/emu/avrsim
	bash tests/examples/size_run.sh $* $(filter %/size.elf %/size.prg %/size.ihx,$^) $@
$(EXB)/avr328/tmaze/ram.txt: $(EXB)/avr328/tmaze/size.elf
$(EXB)/avr1284/tmaze/ram.txt: $(EXB)/avr1284/tmaze/size.elf
$(EXB)/6502/tmaze/ram.txt: $(EXB)/6502/tmaze/size.prg
$(EXB)/z80/tmaze/ram.txt: $(EXB)/z80/tmaze/size.ihx
$(EXB)/%/tmaze/tmaze-$(MAZE_FRAMES).elf: $(EXB)/%/tmaze/ram.txt $(EXB)/maze/maze_keys.h $(EXB)/%/tmaze/size.elf
	$(call tmaze_fw,$*,$@,o)
$(EXB)/6502/tmaze/tmaze-$(MAZE_FRAMES).prg: $(EXB)/6502/tmaze/ram.txt $(EXB)/maze/maze_keys.h $(EXB)/6502/tmaze/size.prg
	$(call tmaze_fw,6502,$@,o)
$(EXB)/z80/tmaze/tmaze-$(MAZE_FRAMES).ihx: $(EXB)/z80/tmaze/ram.txt $(EXB)/maze/maze_keys.h $(EXB)/z80/tmaze/size.ihx
	$(call tmaze_fw,z80,$@,rel)
.SECONDARY: $(foreach t,avr328 avr1284 6502,$(EXB)/$(t)/tmaze/maze.o $(EXB)/$(t)/obj/scene_10.o) \
  $(EXB)/z80/tmaze/maze.rel $(EXB)/z80/obj/scene_10.rel

.PHONY: maze-fw test-maze
maze-fw: $(EXH)/maze $(MAZE_FW) $(TMAZE_FW)

# the host build against a fixed key script, then every target's stream
# byte for byte against it (tests/examples/maze_check.py)
test-maze: $(SETUP)
	@bash scripts/run-step.sh maze $(PY) tests/examples/maze_check.py --frames $(MAZE_FRAMES)

TEST_STEPS += test-maze
