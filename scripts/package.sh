#!/usr/bin/env bash
# Debian packages from the build tree, with CPack's DEB generator (cmake/SubdivPackaging.cmake):
# libsubdivkit, libsubdivkit-dev, subdivkit-tools (with the man page), python3-subdivkit,
# and paraview-subdivkit where the ParaView plugin is built. Builds what is not built yet
# (an incremental build of build/, as scripts/setup.sh made it), then writes the .deb
# files into build/packages/. Run as root on Debian 12 (it installs dpkg-dev, file and
# help2man if missing). Install them with: apt-get install ./build/packages/*.deb
set -euo pipefail
cd "$(dirname "$0")/.."
export CCACHE_BASEDIR="$PWD"
source scripts/apt-packages.sh
install_missing dpkg-dev file help2man  # dpkg-shlibdeps; CPack's ELF check; the man page
bash scripts/configure.sh
cmake build > /dev/null  # finds help2man if it came after the first configure
cmake --build build -j"$(nproc)"
rm -rf build/packages
(cd build && cpack -G DEB > packages.log 2>&1) || { cat build/packages.log; exit 1; }
for deb in build/packages/*.deb; do
  echo "$deb: $(dpkg-deb -f "$deb" Depends)"
done
