#!/bin/sh
# An installed SubdivKit stands on its own (issue 28, item 5):
#   1. `cmake --install` the build tree into a temporary prefix, then move the prefix
#      elsewhere (nothing may point to where it was installed);
#   2. hide the source and build trees (hide_trees.sh: empty folders over them in a private
#      mount namespace, else strace, which fails the test if anything under them is looked at);
#   3. there, from another working directory: `subdiv schemes` lists the built-in schemes
#      and the installed plugins, `subdiv refine` writes a .vtp, the Python package imports
#      and refines (PYTHONPATH into the prefix), the out-of-tree plugin template builds
#      against the installed package and loads, and (built beside ParaView) pvbatch finds
#      the filter through PV_PLUGIN_PATH.
# Environment: SUBDIV_BUILD_DIR, SUBDIV_SOURCE_DIR, CMAKE_COMMAND, CMAKE_GENERATOR; PYTHON
# (the interpreter the module was built for, empty when it was not built); PVBATCH (optional).
set -eu
fail() { echo "install_test.sh: FAILED: $*" >&2; exit 1; }
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d "${TMPDIR:-/tmp}/subdivkit-install-test.XXXXXX")
trap 'rm -rf "$work"' EXIT
case "$work" in "$SUBDIV_SOURCE_DIR"/* | "$SUBDIV_BUILD_DIR"/*) fail "TMPDIR is inside the source or build tree" ;; esac

echo "== cmake --install into a prefix, then move the prefix"
"$CMAKE_COMMAND" --install "$SUBDIV_BUILD_DIR" --prefix "$work/installed-here" > "$work/install.log" ||
  { cat "$work/install.log"; fail "cmake --install"; }
mv "$work/installed-here" "$work/prefix"
cp "$SUBDIV_SOURCE_DIR/examples/meshes/cube.obj" "$work/"
cp -R "$SUBDIV_SOURCE_DIR/plugins/template" "$work/template"
cp "$here/installed_checks.sh" "$here/hide_trees.sh" "$work/"
mkdir "$work/cwd"

env -u SUBDIV_SCHEME_PATH -u SUBDIV_PLUGIN_PATH -u SUBDIV_NO_INSTALLED_PLUGINS -u PYTHONPATH \
  WORK="$work" PREFIX="$work/prefix" CMAKE_COMMAND="$CMAKE_COMMAND" CMAKE_GENERATOR="$CMAKE_GENERATOR" \
  PYTHON="${PYTHON:-}" PVBATCH="${PVBATCH:-}" \
  sh "$work/hide_trees.sh" "$SUBDIV_SOURCE_DIR" "$SUBDIV_BUILD_DIR" "$work/cwd" sh "$work/installed_checks.sh" ||
  fail "the installed tree needs the source or build tree, or does not work (above)"
echo "install_test.sh: ok"
