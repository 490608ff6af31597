#!/usr/bin/env bash
# CI stage after scripts/test.sh: the ways users install SubdivKit, all from the same build
# tree (nothing is rebuilt; ctest's install_* and python_typing tests already ran there):
#   1. Debian packages: scripts/package.sh (CPack from build/), then tests/install/deb_test.sh
#      installs them with apt-get, runs the smoke test with the source and build trees
#      hidden, and checks that apt-get remove leaves nothing;
#   2. the Python package: tests/install/wheel_test.sh builds the wheel from build/
#      (SUBDIVKIT_BUILD_DIR), installs it into a fresh venv and runs pytest there.
# Run as root on Debian 12, after scripts/setup.sh.
set -euo pipefail
cd "$(dirname "$0")/.."
export CCACHE_BASEDIR="$PWD"
pvbatch=""
if [ -n "$(find build/lib* -path '*/plugins/SubdivKit/SubdivKit.so' 2> /dev/null | head -1)" ]; then
  pvbatch=$(command -v pvbatch || true)
fi
echo "== Debian packages (scripts/package.sh)"
bash scripts/package.sh
echo "== the packages installed, smoke-tested and removed (tests/install/deb_test.sh)"
CMAKE_GENERATOR=Ninja PVBATCH="$pvbatch" sh tests/install/deb_test.sh . build
echo "== the wheel in a venv (tests/install/wheel_test.sh)"
sh tests/install/wheel_test.sh . build
