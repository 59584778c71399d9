#!/usr/bin/env bash
# setup.sh [demo] - install what rast8's build, demo and tests need on Debian.
#  `setup.sh demo` (make demo) installs only what the demo and the README's
#  commands need: the host compiler, libusb, Tk and the venv with the
#  package (and pyusb); without it, everything for make test / make bench.
#  * apt: cross toolchains and simulators (avr-gcc, cc65, sdcc/ucsim,
#    simavr), clang (sanitizers, libFuzzer), valgrind, socat, umockdev,
#    libusb, Xvfb.  Only packages that are missing are installed; apt runs
#    only as root (otherwise it prints what to install and goes on).
#  * .venv: a Python venv with the host package (rast8 CLI) and its test
#    dependencies, installed editable from host/.
set -e
cd "$(dirname "$0")/.."

APT_PKGS="build-essential gcc-avr avr-libc simavr libsimavr-dev libelf-dev cc65 sdcc sdcc-ucsim
 clang libclang-rt-14-dev valgrind socat umockdev libusb-1.0-0-dev pkg-config xvfb xauth
 python3-venv python3-dev python3-tk"
EXTRA="test"
if [ "${1:-}" = demo ]; then
  APT_PKGS="build-essential libusb-1.0-0-dev pkg-config python3-venv python3-dev python3-tk"
  EXTRA="usb"
fi

missing=""
for p in $APT_PKGS; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing="$missing $p"
done
if [ -n "$missing" ]; then
  if [ "$(id -u)" = 0 ]; then
    echo "setup: apt-get install$missing"
    export DEBIAN_FRONTEND=noninteractive
    apt-get update -q
    apt-get install -y -q --no-install-recommends $missing
  else
    echo "setup: not root; please install:$missing" >&2
  fi
fi

if [ ! -x .venv/bin/python ]; then
  echo "setup: creating .venv"
  python3 -m venv .venv
fi
.venv/bin/python -m pip install -q --upgrade pip >/dev/null 2>&1 || true
echo "setup: pip install -e host[$EXTRA]"
.venv/bin/python -m pip install -q -e "host[$EXTRA]"
echo "setup: done"
