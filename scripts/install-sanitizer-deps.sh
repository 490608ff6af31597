#!/usr/bin/env bash
# Installs what the sanitizer and fuzzing builds need beyond scripts/install-deps.sh:
# clang 14 with its sanitizer and libFuzzer runtimes, and llvm-symbolizer for readable
# stack traces. Run as root on Debian 12; safe to run again.
set -euo pipefail
source "$(dirname "$0")/apt-packages.sh"
install_missing clang-14 libclang-rt-14-dev llvm-14
