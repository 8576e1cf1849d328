#!/usr/bin/env bash
# Builds the HAL component (sw/hal/hwinterp.comp with the servo's C sources
# and the board's C header it includes) with LinuxCNC's halcompile, in a
# temporary directory.
#
# Usage: scripts/linuxcnc/build_comp.sh [--install | --out DIR]
#   (none)      compile only: the module's size is printed, nothing is kept
#   --install   halcompile --install: into LinuxCNC's module directory, where
#               `loadrt hwinterp` finds it (as root, or through sudo)
#   --out DIR   compile and copy hwinterp.so to DIR
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
mode=compile dest=""
case "${1:-}" in
  "") ;;
  --install) mode=install ;;
  --out) [ $# -ge 2 ] || { echo "build_comp: --out needs a directory" >&2; exit 2; }; dest=$2 ;;
  *) echo "build_comp: unknown option '$1'" >&2; exit 2 ;;
esac
command -v halcompile >/dev/null || { echo "build_comp: no halcompile: run scripts/linuxcnc/setup.sh" >&2; exit 1; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cp "$root"/sw/hal/hwinterp.comp "$root"/sw/hal/hwinterp_servo.[ch] "$root"/sw/hal/hwinterp_link.[ch] \
   "$root"/sw/board_regs.h "$work/"
cd "$work"
if [ "$mode" = install ]; then
  sudo_cmd=()
  if [ "$(id -u)" -ne 0 ]; then sudo_cmd=(sudo); fi
  "${sudo_cmd[@]}" halcompile --install hwinterp.comp
else
  halcompile --compile hwinterp.comp
  test -s hwinterp.so
  echo "build_comp: hwinterp.so, $(stat -c %s hwinterp.so) bytes"
  [ -z "$dest" ] || cp hwinterp.so "$dest/"
fi
