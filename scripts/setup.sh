#!/usr/bin/env bash
# Installs every Debian package the project needs, when missing (Debian 12).
# Idempotent and quiet when everything is present.
set -euo pipefail
pkgs=(
  build-essential cmake python3
  verilator iverilog yosys
  libsystemc-dev
  libfmt-dev libcli11-dev nlohmann-json3-dev
  libgtest-dev googletest libbenchmark-dev
  zlib1g-dev
  python3-matplotlib
  tcl procps
  clang-14 libclang-rt-14-dev
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
