# mk/usb.mk - USB transport (issue 7): rast8-usbcat, built against
# libusb-1.0, and its tests, which run without hardware under umockdev.
#   build/rast8-usbcat        copies a bulk IN endpoint to stdout/file/pty
#   build/usb/faultshim.so    test-only LD_PRELOAD fault injector
#   test-usb                  pytest tests/usb (fixtures generated from a
#                             real build/rast8-emu stream at test time)
# libusb.h is not C89, so this host tool builds with -std=gnu99.

USBCAT       := $(BUILD)/rast8-usbcat
USB_SHIM     := $(BUILD)/usb/faultshim.so
LIBUSB_CFLAGS := $(shell pkg-config --cflags libusb-1.0 2>/dev/null || echo -I/usr/include/libusb-1.0)
LIBUSB_LIBS   := $(shell pkg-config --libs libusb-1.0 2>/dev/null || echo -lusb-1.0)

ALL_TARGETS += $(USBCAT)

$(USBCAT): tools/usbcat.c
	@mkdir -p $(dir $@)
	$(CC) -std=gnu99 -Wall -Wextra -Werror $(CFLAGS) $(LIBUSB_CFLAGS) $< -o $@ $(LIBUSB_LIBS)

$(USB_SHIM): tests/usb/faultshim.c
	@mkdir -p $(dir $@)
	$(CC) -std=gnu99 -Wall -Wextra -Werror -O2 -shared -fPIC $< -o $@ -ldl

.PHONY: usbcat test-usb
usbcat: $(USBCAT)

# Needs the emulator (mk/wire.mk) for a real stream, and the venv.
test-usb: $(USBCAT) $(USB_SHIM) $(BUILD)/rast8-emu $(SETUP)
	@bash scripts/run-step.sh usb $(PY) -m pytest -p no:cacheprovider tests/usb

TEST_STEPS += test-usb
