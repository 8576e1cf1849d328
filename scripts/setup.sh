#!/usr/bin/env bash
# Installs what hwinterp builds and runs with: the Debian packages (apt, as
# root or through sudo) and the pinned Python tool chain
# (scripts/requirements.txt) in a virtual environment inside the project,
# .venv/ (git-ignored; HWINTERP_VENV moves it). Idempotent: it prints nothing
# and touches nothing when everything is there. Scripts, tests and hwinterp
# call .venv/bin/python3, never the python3 on PATH (which may be pyenv's).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)

packages=(
  g++ make cmake ninja-build pkg-config
  libsystemc-dev verilator libeigen3-dev libgtest-dev libgmock-dev libbenchmark-dev
  yosys nextpnr-ice40 fpga-icestorm fpga-icestorm-chipdb iverilog gtkwave
  python3 python3-venv libpython3.11 z3 nlohmann-json3-dev
  clang libclang-rt-14-dev parallel
)

"$root/scripts/apt_install.sh" setup "${packages[@]}"

# The Python environment: (re)made when the requirements file or the host
# package's definition (sw/host/pyproject.toml: its command and dependencies;
# requirements.txt installs the package editable, so its code needs no
# reinstall) changed since it was installed (a stamp holds their hash; so do the board
# package's, boards/pyproject.toml).
# pip runs from the project's root: the requirements name the package by a
# path relative to it.
venv=${HWINTERP_VENV:-$root/.venv}
requirements=$root/scripts/requirements.txt
stamp=$venv/.requirements.sha256
want=$(cat "$requirements" "$root/sw/host/pyproject.toml" "$root/boards/pyproject.toml" | sha256sum | cut -d' ' -f1)
if [ ! -x "$venv/bin/python3" ] || [ "$(cat "$stamp" 2>/dev/null)" != "$want" ]; then
  echo "setup: installing the Python tool chain (scripts/requirements.txt) into $venv" >&2
  /usr/bin/python3 -m venv "$venv"
  (cd "$root" && "$venv/bin/python3" -m pip install -q --disable-pip-version-check --no-input \
    -r "$requirements" >&2)
  echo "$want" >"$stamp"
fi
