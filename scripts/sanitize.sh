#!/usr/bin/env bash
# The whole test suite under AddressSanitizer + UndefinedBehaviorSanitizer: builds the
# library, the tool, the plugins, the tests (and the fuzzers, which share the build) in
# build-asan with clang, then runs ctest with every sanitizer report fatal.
# Usage: scripts/sanitize.sh [extra ctest arguments]; JOBS=N limits parallelism.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/install-sanitizer-deps.sh
source scripts/sanitize-env.sh
configure_sanitized_build
cmake --build "$SUBDIV_ASAN_DIR" -j"$SUBDIV_JOBS"
ctest --test-dir "$SUBDIV_ASAN_DIR" --output-on-failure -j"$SUBDIV_JOBS" "$@"
