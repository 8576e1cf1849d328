#!/usr/bin/env bash
# Installs the Debian packages named that are missing (apt, as root or
# through sudo); prints nothing when all are there. Used by scripts/setup.sh
# and scripts/linuxcnc/setup.sh.
# Usage: scripts/apt_install.sh WHY PACKAGE...
set -euo pipefail
why=$1
shift
missing=()
for p in "$@"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done
[ ${#missing[@]} -gt 0 ] || exit 0
echo "$why: installing ${missing[*]}" >&2
sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then sudo_cmd=(sudo); fi
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
