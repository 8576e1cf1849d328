#!/usr/bin/env bash
# Installs LinuxCNC 2.9 from Debian's archive, on demand: the uspace realtime
# (rtapi_app, HAL, the motion controller and its trajectory planner), the
# development files (halcompile, to build sw/hal/hwinterp.comp) and the
# interpreter's standalone driver (rs274). About 380 packages: never run by
# README's test command or CI; the LinuxCNC tests (ctest label linuxcnc) and
# scripts/linuxcnc/sil.sh call it. Idempotent: prints nothing when installed.
set -euo pipefail

packages=(linuxcnc-uspace linuxcnc-uspace-dev)
root=$(cd "$(dirname "$0")/../.." && pwd)
"$root/scripts/apt_install.sh" "linuxcnc setup (about 380 packages, a few minutes)" "${packages[@]}"
for tool in halcompile halcmd linuxcnc; do
  command -v "$tool" >/dev/null || { echo "linuxcnc setup: $tool is not on PATH after the install" >&2; exit 1; }
done
