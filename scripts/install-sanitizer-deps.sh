#!/usr/bin/env bash
# Installs what the sanitizer and fuzzing builds need beyond scripts/install-deps.sh:
# clang 14 with its sanitizer and libFuzzer runtimes, and llvm-symbolizer for readable
# stack traces. Run as root on Debian 12; safe to run again.
set -euo pipefail
packages=(clang-14 libclang-rt-14-dev llvm-14)
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
