# mk/chart.mk - accuracy and stability (issue 6): the floating-point
# reference's tests, the stability suite (tests/host/test_stability*.c,
# built and run by mk/core.mk), short libFuzzer runs, `make fuzz` for long
# ones and `make chart` (build/chart/speed-accuracy.{png,md}; `make docs`
# copies them to docs/).
#
#   build/r8probe            renders built-in scenes or scene blobs: frames,
#                            per-pixel face ids, C-projected vertices
#   build/r8fill             r8_fill_poly on polygons read from stdin
#   build/fuzz/fuzz_<name>   libFuzzer targets (tests/fuzz/fuzz_<name>.c)

R8PROBE := $(BUILD)/r8probe
R8FILL  := $(BUILD)/r8fill
ALL_TARGETS += $(R8PROBE) $(R8FILL)

$(R8PROBE): tests/tools/r8probe.c $(LIBS) $(wildcard include/*.h src/*.h)
	$(CC) -std=c99 -O2 -g -Wall -Wextra -Werror $(INC) $< $(LIBS) -o $@

$(R8FILL): tests/tools/r8fill.c $(LIB) $(wildcard include/*.h)
	$(CC) -std=c99 -O2 -g -Wall -Wextra -Werror $(INC) $< $(LIBS) -o $@

# tests/py/test_reference.py runs in mk/wire.mk's py-wire step (pytest on
# tests/py) and needs the two tools.
test-py: $(R8PROBE) $(R8FILL)

# ---- fuzzing: libFuzzer (clang), the library sources compiled in
FUZZ_SRC  := $(sort $(wildcard tests/fuzz/fuzz_*.c))
FUZZ_BIN  := $(FUZZ_SRC:tests/fuzz/%.c=$(BUILD)/fuzz/%)
FUZZ_SECS ?= 4
FUZZ_LONG ?= 3600

$(BUILD)/fuzz/fuzz_%: tests/fuzz/fuzz_%.c $(LIB_SRC) $(wildcard include/*.h src/*.h)
	@mkdir -p $(dir $@)
	clang -g -O1 -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=all $(INC) $< $(LIB_SRC) -o $@

.PHONY: test-fuzz
# short runs inside make test
test-fuzz: $(FUZZ_BIN)
	@bash scripts/run-step.sh fuzz bash tests/fuzz/run.sh $(FUZZ_SECS) $(FUZZ_BIN)

# long runs: make fuzz [FUZZ_RUNS=executions per target] [FUZZ_LONG=cap in s]
FUZZ_RUNS ?= 10000000
fuzz: $(FUZZ_BIN)
	FUZZ_RUNS=$(FUZZ_RUNS) bash tests/fuzz/run.sh $(FUZZ_LONG) $(FUZZ_BIN)

TEST_STEPS += test-fuzz

# ---- make chart: build/chart/speed-accuracy.{png,md}
# Uses AVR cycles from build/bench/results.json (make bench, issue 5) when
# present, adding the accuracy fields to its records first; otherwise (or
# for variants the bench does not cover) host instructions by callgrind.
# CHART_BENCH=0 skips running make bench when results.json is missing.
CHART_BENCH ?= 1
chart: $(R8PROBE) $(SETUP)
	@if [ "$(CHART_BENCH)" != 0 ] && [ -f bench/bench.py ] && [ ! -f $(BUILD)/bench/results.json ]; then \
	  $(MAKE) --no-print-directory bench || echo "chart: make bench failed; charting host instruction counts"; fi
	@if [ -f $(BUILD)/bench/results.json ]; then $(PY) bench/accuracy.py $(BUILD)/bench/results.json; fi
	$(PY) bench/chart.py $(CHART_ARGS)
	$(PY) bench/chart.py --texture   # affine, subdivided, bilinear on the crate

# ---- make docs: the generated tables and chart into the tracked docs
# (the only target that writes docs/: make bench and make chart write to
# build/)
.PHONY: docs
docs:
	@test -f $(BUILD)/bench/results.md || { echo "docs: build/bench/results.md missing: run make bench"; exit 1; }
	cp $(BUILD)/bench/results.md docs/bench-results.md
	@if [ -f $(BUILD)/chart/speed-accuracy.md ]; then cp $(BUILD)/chart/speed-accuracy.md $(BUILD)/chart/speed-accuracy.png docs/; \
	  else echo "docs: no build/chart (make chart): docs/speed-accuracy.* unchanged"; fi

# the ray caster's columns for the float reference (host/rast8/raycast_ref.py,
# tests/py/test_raycast.py, bench/bench.py's ray figures)
R8RAYCOLS := $(BUILD)/r8raycols
ALL_TARGETS += $(R8RAYCOLS)
$(R8RAYCOLS): tests/tools/r8raycols.c $(LIBS) $(wildcard include/*.h src/*.h scenes/*.h)
	$(CC) -std=c99 -O2 -g -Wall -Wextra -Werror $(INC) $< $(LIBS) -o $@
test-py: $(R8RAYCOLS)
