#!/bin/sh
# The out-of-tree plugin kit, end to end (ctest: plugin_out_of_tree):
#   1. install SubdivKit from the build tree into a temporary prefix;
#   2. copy plugins/template elsewhere and build it with find_package(SubdivKit) against
#      that prefix (subdivkit_add_plugin from the installed package config);
#   3. load it into the installed `subdiv` with --plugin and refine a mesh with its scheme;
#   4. install it into the prefix's plugin folder and find it there without --plugin.
# Needs SUBDIV_BUILD_DIR, SUBDIV_SOURCE_DIR, CMAKE_COMMAND, CMAKE_GENERATOR (set by ctest).
set -eu
work=$(mktemp -d "${TMPDIR:-/tmp}/subdivkit-out-of-tree.XXXXXX")
trap 'rm -rf "$work"' EXIT
prefix="$work/prefix"
fail() { echo "out_of_tree.sh: FAILED: $*" >&2; exit 1; }

echo "== install SubdivKit into $prefix"
"$CMAKE_COMMAND" --install "$SUBDIV_BUILD_DIR" --prefix "$prefix" > "$work/install.log" || { cat "$work/install.log"; fail "install"; }
test -f "$prefix/lib/cmake/SubdivKit/SubdivKitConfig.cmake" || fail "no package config installed"
test -f "$prefix/lib/cmake/SubdivKit/SubdivKitPlugin.cmake" || fail "no plugin helper installed"
test -f "$prefix/include/subdivkit/framework/plugin/plugin_api.h" || fail "plugin_api.h not installed"

echo "== build plugins/template out of tree"
cp -R "$SUBDIV_SOURCE_DIR/plugins/template" "$work/my_plugin"
"$CMAKE_COMMAND" -S "$work/my_plugin" -B "$work/build" -G "$CMAKE_GENERATOR" -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_INSTALL_PREFIX="$prefix" > "$work/configure.log" 2>&1 \
  || { cat "$work/configure.log"; fail "configure against the installed SubdivKit"; }
"$CMAKE_COMMAND" --build "$work/build" > "$work/build.log" 2>&1 || { cat "$work/build.log"; fail "build"; }
plugin="$work/build/my_plugin.so"
test -f "$plugin" || fail "no $plugin"

subdiv="$prefix/bin/subdiv"
echo "== load it with --plugin"
"$subdiv" plugins --plugin "$plugin" > "$work/plugins.txt" 2>&1 || { cat "$work/plugins.txt"; fail "subdiv plugins"; }
cat "$work/plugins.txt"
grep -q "^loaded   my-plugin 0.1.0  $plugin (--plugin)" "$work/plugins.txt" || fail "my-plugin not loaded"
grep -q "surface scheme my-scheme" "$work/plugins.txt" || fail "my-scheme not listed"

echo "== refine a cube with its scheme"
"$subdiv" refine "$SUBDIV_SOURCE_DIR/examples/meshes/cube.obj" --plugin "$plugin" --scheme my-scheme --levels 2 \
  --param s=0.5 -o "$work/cube.obj" || fail "refine"
vertices=$(grep -c '^v ' "$work/cube.obj")
faces=$(grep -c '^f ' "$work/cube.obj")
echo "cube, 2 levels of my-scheme: $vertices vertices, $faces faces"
test "$vertices" -eq 98 || fail "expected 98 vertices, got $vertices"
test "$faces" -eq 96 || fail "expected 96 faces, got $faces"

echo "== install it into the prefix's plugin folder: found without --plugin"
"$CMAKE_COMMAND" --install "$work/build" > "$work/install-plugin.log" || fail "install the plugin"
test -f "$prefix/lib/subdivkit/plugins/my_plugin.so" || fail "plugin not installed into lib/subdivkit/plugins"
"$subdiv" schemes > "$work/schemes.txt" 2>&1 || { cat "$work/schemes.txt"; fail "subdiv schemes"; }
grep -q "my-scheme.*\[plugin my-plugin\]" "$work/schemes.txt" || { cat "$work/schemes.txt"; fail "installed plugin not found"; }
grep -q "circle-four-point.*\[plugin circle-preserving\]" "$work/schemes.txt" || fail "installed example plugins not found"
echo "out_of_tree.sh: ok"
