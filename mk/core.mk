# mk/core.mk - library strictness gates and the C unit tests.
# C unit tests: every tests/c/test_*.c is one binary, linked with the
# library and tests/unity; add a file and it is built and run.

# tests/host/test_*.c: host-only C tests (whole scenes, too big to run
# inside the simulators); built and run the same way.
TEST_C    := $(sort $(wildcard tests/c/test_*.c))
TEST_HC   := $(sort $(wildcard tests/host/test_*.c))
TEST_BIN  := $(TEST_C:tests/c/%.c=$(BUILD)/tests/%) $(TEST_HC:tests/host/%.c=$(BUILD)/tests/%)
ASAN_BIN  := $(TEST_C:tests/c/%.c=$(BUILD)/asan/%) $(TEST_HC:tests/host/%.c=$(BUILD)/asan/%)
SANFLAGS  := -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer
TEST_INC  := $(INC) -Itests/unity -Itests/c
TEST_DEPS := tests/unity/unity.c tests/unity/unity.h $(wildcard tests/c/*.h)

ALL_TARGETS += $(TEST_BIN)

$(BUILD)/tests/%: tests/c/%.c $(LIBS) $(TEST_DEPS) $(wildcard src/*.h) | $(BUILD)/tests
	$(CC) $(STRICT) $(CFLAGS) $(TEST_INC) $< tests/unity/unity.c $(LIBS) -o $@

$(BUILD)/tests/%: tests/host/%.c $(LIBS) $(TEST_DEPS) | $(BUILD)/tests
	$(CC) -std=c99 -pedantic -Wall -Wextra -Werror $(CFLAGS) $(TEST_INC) $< tests/unity/unity.c $(LIBS) -o $@

# Sanitizer build: library sources compiled in, not the release archive.
$(BUILD)/asan/%: tests/c/%.c $(LIB_SRC) $(TEST_DEPS) $(wildcard include/*.h src/*.h)
	@mkdir -p $(dir $@)
	clang $(STRICT) -O1 -g $(SANFLAGS) $(TEST_INC) $< tests/unity/unity.c $(LIB_SRC) -o $@

$(BUILD)/asan/%: tests/host/%.c $(LIB_SRC) $(SCENE_SRC) $(TEST_DEPS) $(wildcard include/*.h src/*.h scenes/*.h)
	@mkdir -p $(dir $@)
	clang -std=c99 -pedantic -Wall -Wextra -Werror -O1 -g $(SANFLAGS) $(TEST_INC) $< tests/unity/unity.c $(LIB_SRC) $(SCENE_SRC) -o $@

.PHONY: test-unit test-asan lint test-lint test-strict test-cross
test-unit: $(TEST_BIN)
	@fail=0; for t in $(TEST_BIN); do \
	  bash scripts/run-step.sh unit-$$(basename $$t) $$t || fail=1; done; exit $$fail

test-asan: $(ASAN_BIN)
	@fail=0; for t in $(ASAN_BIN); do \
	  bash scripts/run-step.sh asan-$$(basename $$t) $$t || fail=1; done; exit $$fail

lint:
	bash scripts/lint.sh

test-lint:
	@bash scripts/run-step.sh lint bash scripts/lint.sh

# gcc and clang, each library file, strict C89.
test-strict:
	@bash scripts/run-step.sh strict bash scripts/strict.sh

# avr-gcc, cc65 and sdcc compile every library file.
test-cross:
	@bash scripts/run-step.sh cross bash scripts/cross-compile.sh

TEST_STEPS += test-lint test-strict test-cross test-unit test-asan

# r8dump: render built-in scenes on the host to raw bytes or PGM.
R8DUMP := $(BUILD)/r8dump
ALL_TARGETS += $(R8DUMP)
$(R8DUMP): tools/r8dump.c $(LIBS) $(wildcard include/*.h)
	$(CC) -std=c99 -O2 -Wall -Wextra -Werror $(INC) $< $(LIBS) -o $@

# Golden frames: compared byte for byte; only `make golden` rewrites them.
.PHONY: test-golden
golden: $(R8DUMP)
	bash scripts/golden.sh update

test-golden: $(R8DUMP)
	@bash scripts/run-step.sh golden bash scripts/golden.sh check

TEST_STEPS += test-golden

# Regenerate scenes/*.c from host/rast8/scene.py and its .r8s files.
.PHONY: scenes
scenes: $(SETUP)
	$(PY) -m rast8.scene c scenes
