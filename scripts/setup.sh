#!/usr/bin/env bash
# Fresh Debian 12, as root: install dependencies, build in Release, and refine the bundled
# cube with Catmull-Clark into out/cube.pvd (open it in ParaView).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release
cmake --build build -j"$(nproc)"
mkdir -p out
build/tools/subdiv/subdiv refine examples/meshes/cube.obj --scheme catmull-clark --levels 3 -o out/cube.pvd
