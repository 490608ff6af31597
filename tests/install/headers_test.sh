#!/bin/sh
# The installed headers are the public API and each compiles on its own (issue 28, item 6):
# `cmake --install` into a temporary prefix, then the separate project tests/install/headers
# compiles every installed header alone against the package and links a program: the
# libsubdiv headers without vtkio, then (where it was built) vtkio's with SubdivKit::vtkio.
# Environment: SUBDIV_BUILD_DIR, SUBDIV_SOURCE_DIR, CMAKE_COMMAND, CMAKE_GENERATOR,
# CXX_COMPILER, CXX_LAUNCHER (may be empty), HAVE_VTKIO (ON or OFF).
set -eu
fail() { echo "headers_test.sh: FAILED: $*" >&2; exit 1; }
work=$(mktemp -d "${TMPDIR:-/tmp}/subdivkit-headers-test.XXXXXX")
trap 'rm -rf "$work"' EXIT
prefix="$work/prefix"
"$CMAKE_COMMAND" --install "$SUBDIV_BUILD_DIR" --prefix "$prefix" --component dev > "$work/install.log" &&
  "$CMAKE_COMMAND" --install "$SUBDIV_BUILD_DIR" --prefix "$prefix" --component lib >> "$work/install.log" ||
  { cat "$work/install.log"; fail "cmake --install of the lib and dev components"; }
count=$(find "$prefix/include/subdivkit/framework" -name '*.h' | wc -l)
echo "== $count installed headers"
mesh="$SUBDIV_SOURCE_DIR/examples/meshes/cube.obj"

check() {  # check PART (subdiv or vtkio)
  build="$work/build-$1"
  launcher=""
  # ccache (when the build uses it) with paths relative to the temporary folder: hits across runs.
  [ -n "${CXX_LAUNCHER:-}" ] && launcher="-DCMAKE_CXX_COMPILER_LAUNCHER=$CXX_LAUNCHER" && export CCACHE_BASEDIR="$work"
  "$CMAKE_COMMAND" -S "$SUBDIV_SOURCE_DIR/tests/install/headers" -B "$build" -G "$CMAKE_GENERATOR" \
    -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER="$CXX_COMPILER" $launcher -DCMAKE_PREFIX_PATH="$prefix" \
    -DSUBDIVKIT_HEADERS="$prefix/include/subdivkit" -DPART="$1" > "$work/$1.log" 2>&1 ||
    { cat "$work/$1.log"; fail "configure the user project ($1)"; }
  "$CMAKE_COMMAND" --build "$build" >> "$work/$1.log" 2>&1 || { cat "$work/$1.log"; fail "build the user project ($1)"; }
}

echo "== without vtkio: every header but framework/io/vtk's alone against SubdivKit::subdiv"
check subdiv
"$work/build-subdiv/uses_subdiv" "$mesh" || fail "uses_subdiv"
if [ "$HAVE_VTKIO" = ON ]; then
  echo "== with vtkio: framework/io/vtk's headers alone against SubdivKit::vtkio"
  check vtkio
  "$work/build-vtkio/uses_vtkio" "$mesh" "$work/cube.vtp" || fail "uses_vtkio"
fi
echo "headers_test.sh: ok"
