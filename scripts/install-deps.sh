#!/usr/bin/env bash
# Installs every Debian package SubdivKit needs to build, test and benchmark.
# Run as root on Debian 12. Safe to run again: apt skips what is installed.
set -euo pipefail
packages=(
  build-essential cmake ninja-build pkg-config
  libopenmesh-dev nlohmann-json3-dev libfmt-dev doctest-dev
  libvtk9-dev libeigen3-dev libmuparser-dev libcli11-dev libtbb-dev
  libosd-dev
  pybind11-dev python3-dev python3-numpy python3-scipy python3-pytest python3-matplotlib
)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "installing: ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq
  apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
