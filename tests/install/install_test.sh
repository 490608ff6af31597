#!/bin/sh
# An installed SubdivKit stands on its own (issue 28, item 5):
#   1. `cmake --install` the build tree into a temporary prefix, then move the prefix
#      elsewhere (nothing may point to where it was installed);
#   2. hide the source and build trees: a private mount namespace with empty folders over
#      both (unshare, as root or with user namespaces), else strace, which fails the test if
#      anything under them is even looked at;
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
cp "$here/installed_checks.sh" "$work/"
mkdir "$work/cwd"

run_checks() {
  env -u SUBDIV_SCHEME_PATH -u SUBDIV_PLUGIN_PATH -u SUBDIV_NO_INSTALLED_PLUGINS -u PYTHONPATH \
    WORK="$work" CMAKE_COMMAND="$CMAKE_COMMAND" CMAKE_GENERATOR="$CMAKE_GENERATOR" \
    PYTHON="${PYTHON:-}" PVBATCH="${PVBATCH:-}" "$@" sh "$work/installed_checks.sh"
}

# Empty folders over the trees: as root, or as a user where user namespaces are allowed.
if unshare -m true 2> /dev/null; then how="unshare -m"
elif unshare -rm true 2> /dev/null; then how="unshare -rm"
else how=""
fi
if [ -n "$how" ]; then
  echo "== the checks with the source and build trees hidden ($how, empty folders over them)"
  # The build tree first: it may lie inside the source tree.
  cat > "$work/hidden.sh" <<SH
for d in "$SUBDIV_BUILD_DIR" "$SUBDIV_SOURCE_DIR"; do mount -t tmpfs -o size=1m hidden "\$d" || exit 1; done
test -z "\$(ls -A "$SUBDIV_SOURCE_DIR")" || { echo "the source tree is not hidden" >&2; exit 1; }
cd "$work/cwd"
exec "\$@"
SH
  run_checks $how sh "$work/hidden.sh" || fail "the installed tree needs the source or build tree (above)"
elif command -v strace > /dev/null; then
  echo "== the checks under strace (no mount namespace here): nothing under the source or build tree may be looked at"
  (cd "$work/cwd" && run_checks strace -f -qq -e trace=%file -o "$work/files.log") || fail "the checks (above)"
  if grep -F -e "\"$SUBDIV_SOURCE_DIR/" -e "\"$SUBDIV_SOURCE_DIR\"" -e "\"$SUBDIV_BUILD_DIR/" "$work/files.log" > "$work/touched.log"; then
    head -20 "$work/touched.log" >&2
    fail "the installed tree looked into the source or build tree (above)"
  fi
else
  fail "neither unshare nor strace is available to hide the source and build trees"
fi
echo "install_test.sh: ok"
