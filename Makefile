# rast8 - top-level Makefile.  `make` builds the library and host tools
# into build/, `make test` runs every test, `make demo` runs the main job.
# Each part of the project adds its rules in mk/<part>.mk and appends
# its test steps to TEST_STEPS (see mk/core.mk for the pattern).

BUILD   := build
CC      ?= gcc
ifeq ($(origin CC),default)
CC      := gcc
endif
STRICT  := -std=c89 -pedantic -Wall -Wextra -Werror
CFLAGS  ?= -O2 -g
INC     := -Iinclude -Iscenes
VENV    := .venv
PY      := $(VENV)/bin/python
SETUP   := $(VENV)/.rast8-setup

LIB_SRC := $(sort $(wildcard src/*.c))
LIB_OBJ := $(LIB_SRC:src/%.c=$(BUILD)/obj/%.o)
LIB     := $(BUILD)/librast8.a
# The built-in demo scenes (scenes/*.c, generated): not library code;
# programs that use them link this archive before the library.
SCENE_SRC := $(sort $(wildcard scenes/*.c))
SCENE_OBJ := $(SCENE_SRC:scenes/%.c=$(BUILD)/obj/scenes/%.o)
SCENELIB  := $(BUILD)/librast8scenes.a
LIBS      := $(SCENELIB) $(LIB)

TEST_STEPS :=
ALL_TARGETS := $(LIB) $(SCENELIB)

.PHONY: all test setup clean demo bench golden lint chart fuzz
all: all-targets

$(BUILD)/obj/%.o: src/%.c $(wildcard include/*.h src/*.h) | $(BUILD)/obj
	$(CC) $(STRICT) $(CFLAGS) $(INC) -c $< -o $@

$(LIB): $(LIB_OBJ)
	rm -f $@
	ar rcs $@ $^

$(BUILD)/obj/scenes/%.o: scenes/%.c scenes/demo.h $(wildcard include/*.h)
	@mkdir -p $(dir $@)
	$(CC) $(STRICT) $(CFLAGS) $(INC) -c $< -o $@

# the scene loader runs this tree's scene converter (host/rast8/scene.py)
$(BUILD)/obj/scenes/blob.o: scenes/blob.c scenes/blob.h scenes/demo.h $(wildcard include/*.h)
	@mkdir -p $(dir $@)
	$(CC) $(STRICT) $(CFLAGS) $(INC) -DR8_HOST_DIR='"$(abspath host)"' -c $< -o $@

$(SCENELIB): $(SCENE_OBJ)
	rm -f $@
	ar rcs $@ $^

$(BUILD)/obj $(BUILD)/tests $(BUILD)/logs:
	mkdir -p $@

# Installs the cross toolchains (apt, when missing and root) and the
# Python venv with the host package.  Runs once; `make setup` forces it.
$(SETUP): scripts/setup.sh host/pyproject.toml
	bash scripts/setup.sh
	touch $@

setup:
	bash scripts/setup.sh && touch $(SETUP)

include $(sort $(wildcard mk/*.mk))

all-targets: $(ALL_TARGETS)

# Every step logs to build/logs/<step>.log; the summary adds up the
# "N passed, N failed" lines (and pytest's) and fails if any failed.
test: $(SETUP)
	@$(PY) -c "import os, sys, rast8; sys.exit(os.path.realpath(rast8.__file__).startswith(os.path.realpath('host')) == 0)" \
	  2>/dev/null || bash scripts/setup.sh   # the venv's rast8 must be this checkout's
	@rm -rf $(BUILD)/logs && mkdir -p $(BUILD)/logs
	@$(MAKE) --no-print-directory -k $(TEST_STEPS); rc=$$?; \
	  bash scripts/summarize.sh $(BUILD)/logs; src=$$?; \
	  if [ $$rc -ne 0 ] || [ $$src -ne 0 ]; then exit 1; fi

clean:
	rm -rf $(BUILD)
