# Sourced by scripts/sanitize.sh and scripts/fuzz.sh: the one build directory both use and
# the sanitizer options that make any report fatal.
#
# One directory for both: the library is built once with ASan + UBSan + libFuzzer's
# coverage instrumentation (cmake/Sanitizers.cmake), which serves the sanitized test suite
# and the fuzzers alike and halves what CI compiles.
SUBDIV_ASAN_DIR=${SUBDIV_ASAN_DIR:-build-asan}
# Clones of the checkout share ccache's objects (paths relative to the checkout; the debug
# info's compile directory is not hashed, so a clone elsewhere hits the same objects).
export CCACHE_BASEDIR="$PWD" CCACHE_NOHASHDIR=1
SUBDIV_JOBS=${JOBS:-$(nproc)}

configure_sanitized_build() {
  local launcher=()
  if command -v ccache >/dev/null; then launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache); fi
  # Without MPI: OpenMPI keeps its allocations for the life of the process (LeakSanitizer
  # would report them); --pieces is sanitized on its serial path, which is the same code.
  if [ ! -f "$SUBDIV_ASAN_DIR/build.ninja" ]; then
    CXX=clang++-14 CC=clang-14 cmake -S . -B "$SUBDIV_ASAN_DIR" -G Ninja \
      -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSUBDIV_BUILD_FUZZERS=ON -DSUBDIV_BUILD_BENCH=OFF -DSUBDIV_BUILD_PYTHON=OFF \
      -DSUBDIV_WITH_MPI=OFF "${launcher[@]}"
  elif grep -q "^SUBDIV_WITH_MPI:BOOL=ON" "$SUBDIV_ASAN_DIR/CMakeCache.txt" 2>/dev/null; then
    # A directory configured before MPI was left out of sanitized builds.
    cmake -S . -B "$SUBDIV_ASAN_DIR" -DSUBDIV_WITH_MPI=OFF > /dev/null
  fi
}

# Any ASan or UBSan report stops the program with a non-zero exit and a symbolized stack.
export ASAN_OPTIONS=${ASAN_OPTIONS:-halt_on_error=1:abort_on_error=1:detect_leaks=1:check_initialization_order=1:strict_init_order=1:detect_stack_use_after_return=0}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-halt_on_error=1:print_stacktrace=1:report_error_type=1}
export LSAN_OPTIONS=${LSAN_OPTIONS:-suppressions=$PWD/tests/sanitizers/lsan.supp:print_suppressions=0}
export ASAN_SYMBOLIZER_PATH=${ASAN_SYMBOLIZER_PATH:-/usr/bin/llvm-symbolizer-14}
