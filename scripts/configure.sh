#!/usr/bin/env bash
# Configures build/ (Release, Ninja) unless it is configured already; compiles through
# ccache when it is installed (scripts/install-deps.sh installs it), with paths relative
# to the checkout so that clones share the cache.
set -euo pipefail
cd "$(dirname "$0")/.."
[ -f build/build.ninja ] && exit 0
launcher=()
if command -v ccache > /dev/null; then
  launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
fi
# SUBDIV_WERROR=ON (CI): warnings in framework/ fail the build.
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DSUBDIV_WERROR="${SUBDIV_WERROR:-OFF}" "${launcher[@]}"
