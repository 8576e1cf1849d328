#!/usr/bin/env bash
# Installs LinuxCNC 2.9 from Debian's archive, on demand: the uspace realtime
# (rtapi_app, HAL, the motion controller and its trajectory planner), the
# development files (halcompile, to build sw/hal/hwinterp.comp) and the
# interpreter's standalone driver (rs274). About 380 packages: never run by
# README's test command or CI; the LinuxCNC tests (ctest label linuxcnc) and
# scripts/linuxcnc/sil.sh call it. Idempotent: prints nothing when installed.
set -euo pipefail

packages=(linuxcnc-uspace linuxcnc-uspace-dev)
missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "linuxcnc setup: installing ${missing[*]} from Debian (about 380 packages, a few minutes)" >&2
  sudo_cmd=()
  if [ "$(id -u)" -ne 0 ]; then sudo_cmd=(sudo); fi
  export DEBIAN_FRONTEND=noninteractive
  "${sudo_cmd[@]}" apt-get update -qq
  "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi
for tool in halcompile halcmd linuxcnc; do
  command -v "$tool" >/dev/null || { echo "linuxcnc setup: $tool is not on PATH after the install" >&2; exit 1; }
done
