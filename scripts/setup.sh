#!/usr/bin/env bash
# Installs the Debian packages hwinterp builds and runs with. Idempotent: it
# prints nothing and touches nothing when every package is already there.
set -euo pipefail

packages=(
  g++ cmake ninja-build pkg-config
  libsystemc-dev verilator libeigen3-dev libgtest-dev libgmock-dev libbenchmark-dev
  yosys nextpnr-ice40 fpga-icestorm fpga-icestorm-chipdb iverilog gtkwave
  python3 python3-matplotlib z3 nlohmann-json3-dev
  clang libclang-rt-14-dev parallel
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done
[ ${#missing[@]} -eq 0 ] && exit 0

echo "setup: installing ${missing[*]}" >&2
sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then sudo_cmd=(sudo); fi
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
