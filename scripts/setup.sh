#!/usr/bin/env bash
# Installs every Debian package the project needs, when missing (Debian 12),
# and the pinned Python tools from PyPI (scripts/python/requirements.txt:
# FuseSoC, cocotb) into .venv/ at the top of the tree. Idempotent and quiet when
# everything is present.
set -euo pipefail
pkgs=(
  build-essential cmake python3
  verilator iverilog yosys z3
  libsystemc-dev
  libfmt-dev libcli11-dev nlohmann-json3-dev
  libgtest-dev googletest libbenchmark-dev
  zlib1g-dev
  python3-matplotlib
  tcl procps
  clang-14 libclang-rt-14-dev
  python3-venv
  gtkwave
  pybind11-dev python3-dev
  lcov
)
missing=()
for p in "${pkgs[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "setup: installing ${missing[*]}"
  SUDO=""
  [ "$(id -u)" -eq 0 ] || SUDO="sudo"
  export DEBIAN_FRONTEND=noninteractive
  $SUDO apt-get update -qq
  $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

# The Python tools: a virtual environment of Debian's python3, re-created
# when the requirements change (their hash is kept in the environment).
here=$(cd "$(dirname "$0")/.." && pwd)
req=$here/scripts/python/requirements.txt
venv=$here/.venv
want=$(sha256sum "$req" | cut -d' ' -f1)
if [ "$(cat "$venv/requirements.sha256" 2>/dev/null)" != "$want" ]; then
  echo "setup: installing the Python tools into $venv (scripts/python/requirements.txt)"
  rm -rf "$venv"
  /usr/bin/python3 -m venv "$venv"
  "$venv/bin/pip" install --quiet --disable-pip-version-check --no-deps -r "$req"
  echo "$want" > "$venv/requirements.sha256"
fi
