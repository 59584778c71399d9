# The portal renderer (issue 14): its bench piece.  The host test
# (tests/host/test_portal.c) and the rooms identity tests run with the rest.
#   make bench-portal   build/bench/portal.json and portal.md: overdraw,
#                       polygons, vertices transformed, sectors (host, the
#                       whole rooms walk) and cycles, RAM, flash (the
#                       firmware on the ATmega1284P, 6502 and Z80) for
#                       portal, zbuf16 and painter's on the rooms
$(BUILD)/portal_bench: bench/portal_bench.c $(LIB_SRC) $(SCENE_SRC) $(wildcard include/*.h src/*.h scenes/*.h)
	@mkdir -p $(dir $@)
	$(CC) -std=c99 -pedantic -Wall -Wextra -Werror -O2 -DR8_COUNT_PX $(INC) -Isrc -o $@ bench/portal_bench.c $(LIB_SRC) $(SCENE_SRC)

.PHONY: bench-portal
bench-portal: $(SETUP) $(BUILD)/portal_bench
	$(PY) bench/bench.py --portal
