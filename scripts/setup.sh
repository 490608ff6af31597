#!/usr/bin/env bash
# Fresh Debian 12, as root: install dependencies, build in Release, and refine the bundled
# cube with Catmull-Clark into out/cube.pvd (open it in ParaView). Works beside Debian's
# ParaView too: install-deps.sh then builds against ParaView's VTK.
set -euo pipefail
cd "$(dirname "$0")/.."
export CCACHE_BASEDIR="$PWD"  # clones of the checkout share ccache's objects
bash scripts/install-deps.sh
bash scripts/configure.sh
cmake --build build -j"$(nproc)"
mkdir -p out
build/tools/subdiv/subdiv refine examples/meshes/cube.obj --scheme catmull-clark --levels 3 -o out/cube.pvd
