# mk/package.mk - packages (issue 11): install with pkg-config, the
# Arduino library zip, and their checks in make test.
#
#   make install [PREFIX=/usr/local] [DESTDIR=]
#       PREFIX/include/rast8/*.h   the public headers (include/)
#       PREFIX/lib/librast8.a      the host library
#       PREFIX/lib/pkgconfig/rast8.pc
#   make uninstall [PREFIX=...]    removes exactly those files
#   make arduino   build/arduino/rast8-VERSION.zip: library.properties,
#                  LICENSE, src/ (src/*.c, src/*.h and include/*.h, flat,
#                  as the Arduino IDE expects) and examples/NAME/NAME.ino
#                  with the files each sketch needs (ARDUINO_FILES_NAME).
# VERSION comes from library.properties; tests/package/check.py checks
# that library.json and host/pyproject.toml agree with it.

VERSION := $(shell sed -n 's/^version=//p' library.properties)
PREFIX  ?= /usr/local
DESTDIR ?=
PUB_HDR := $(sort $(wildcard include/*.h))
PC_PREFIX = $(abspath $(PREFIX))
INST_INC = $(DESTDIR)$(PC_PREFIX)/include/rast8
INST_LIB = $(DESTDIR)$(PC_PREFIX)/lib
INST_PC  = $(DESTDIR)$(PC_PREFIX)/lib/pkgconfig

.PHONY: install uninstall arduino test-package test-arduino

install: $(LIB)
	@[ -n "$(PREFIX)" ] || { echo "install: PREFIX is empty" >&2; exit 2; }
	install -d $(INST_INC) $(INST_LIB) $(INST_PC)
	install -m 644 $(PUB_HDR) $(INST_INC)/
	install -m 644 $(LIB) $(INST_LIB)/
	@printf '%s\n' 'prefix=$(PC_PREFIX)' 'exec_prefix=$${prefix}' \
	  'libdir=$${exec_prefix}/lib' 'includedir=$${prefix}/include' '' \
	  'Name: rast8' \
	  'Description: fixed-point 3D renderer in ISO C89 for 8-bit microcontrollers' \
	  'Version: $(VERSION)' 'Libs: -L$${libdir} -lrast8' 'Cflags: -I$${includedir}/rast8' \
	  > $(INST_PC)/rast8.pc
	@echo "installed rast8 $(VERSION) into $(DESTDIR)$(PC_PREFIX)"

uninstall:
	rm -f $(addprefix $(INST_INC)/,$(notdir $(PUB_HDR))) $(INST_LIB)/librast8.a $(INST_PC)/rast8.pc
	-rmdir $(INST_INC) 2>/dev/null

# ---- Arduino library zip
# Sketches: every examples/NAME/ with a .ino.  A sketch's folder in the
# zip gets its .ino files, ARDUINO_FILES_NAME, and scene.c (built-in
# scene S's meshes alone, ports/scene_strip.py) when ARDUINO_SCENE_NAME=S.
ARDUINO_DIR      := $(BUILD)/arduino
ARDUINO_ZIP      := $(ARDUINO_DIR)/rast8-$(VERSION).zip
ARDUINO_SKETCHES := $(sort $(notdir $(patsubst %/,%,$(dir $(wildcard examples/*/*.ino)))))
ARDUINO_FILES_spin := examples/spin/app.c examples/spin/app.h ports/plat.h scenes/demo.h
ARDUINO_SCENE_spin := 0
ARDUINO_DEPS := library.properties LICENSE README.md $(LIB_SRC) $(wildcard src/*.h) $(PUB_HDR) \
  ports/scene_strip.py mk/package.mk $(wildcard examples/*/*.ino) $(wildcard scenes/*.c) \
  $(foreach s,$(ARDUINO_SKETCHES),$(ARDUINO_FILES_$(s)))

arduino: $(ARDUINO_ZIP)

$(ARDUINO_ZIP): $(ARDUINO_DEPS)
	@[ -n "$(VERSION)" ] || { echo "arduino: no version= line in library.properties" >&2; exit 2; }
	@rm -rf $(ARDUINO_DIR)/rast8 $@ && mkdir -p $(ARDUINO_DIR)/rast8/src
	@cp library.properties LICENSE README.md $(ARDUINO_DIR)/rast8/
	@cp $(LIB_SRC) $(wildcard src/*.h) $(PUB_HDR) $(ARDUINO_DIR)/rast8/src/
	@sed -i 's/^#define R8CONFIG_H$$/&\n#define R8_ARDUINO_PRESET/' $(ARDUINO_DIR)/rast8/src/r8config.h
	@set -e; $(foreach s,$(ARDUINO_SKETCHES),d=$(ARDUINO_DIR)/rast8/examples/$(s); mkdir -p $$d; \
	  cp examples/$(s)/*.ino $(ARDUINO_FILES_$(s)) $$d/; \
	  $(if $(ARDUINO_SCENE_$(s)),python3 ports/scene_strip.py $(ARDUINO_SCENE_$(s)) --inline > $$d/scene.c;))
	@cd $(ARDUINO_DIR) && python3 -m zipfile -c $(notdir $@) rast8
	@echo "$@: $$(cd $(ARDUINO_DIR) && find rast8 -type f | wc -l) files; sketches: $(ARDUINO_SKETCHES)"

# ---- checks
# install into a temporary prefix, build and run a C89 program with
# pkg-config only; library.properties / library.json against their specs.
test-package: $(LIB) $(R8DUMP) $(SETUP)
	@bash scripts/run-step.sh package $(PY) tests/package/check.py

# the zip's layout, and every sketch compiled and linked for an
# ATmega328P against tests/arduino/core (and a real core if installed),
# then run in libsimavr against build/rast8-emu's stream.
test-arduino: $(ARDUINO_ZIP) $(BUILD)/emu/avrsim $(BUILD)/rast8-emu $(SETUP)
	@bash scripts/run-step.sh arduino $(PY) tests/arduino/check.py $(ARDUINO_ZIP)

TEST_STEPS += test-package test-arduino
