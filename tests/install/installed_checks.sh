#!/bin/sh
# The checks of an installed SubdivKit (install_test.sh: a cmake --install prefix;
# deb_test.sh: the Debian packages in /usr), run where the source and build trees cannot be
# seen: only the installed PREFIX and copies in WORK (cube.obj, template/).
# Environment: WORK, PREFIX, CMAKE_COMMAND, CMAKE_GENERATOR, PYTHON (may be empty: no
# Python check), PVBATCH (may be empty: no ParaView check), PV_AUTOLOAD (1: the plugin must
# load when ParaView starts, as the Debian package sets up).
set -eu
fail() { echo "installed_checks.sh: FAILED: $*" >&2; exit 1; }
prefix="$PREFIX"
subdiv="$prefix/bin/subdiv"

echo "-- subdiv schemes: the built-in schemes from the prefix, the example plugins from its plugin folder"
"$subdiv" schemes > "$WORK/schemes.txt" 2>&1 || { cat "$WORK/schemes.txt"; fail "subdiv schemes"; }
for scheme in catmull-clark loop butterfly doo-sabin chaikin; do
  grep -q "^  $scheme  *\[built-in\]" "$WORK/schemes.txt" || { cat "$WORK/schemes.txt"; fail "no built-in $scheme"; }
done
grep -q "^  sqrt2  *\[plugin sqrt2\]" "$WORK/schemes.txt" || { cat "$WORK/schemes.txt"; fail "the installed sqrt2 plugin"; }

echo "-- subdiv refine cube.obj -o x.vtp (and an OBJ with the sqrt2 plugin's scheme)"
"$subdiv" refine "$WORK/cube.obj" -o "$WORK/x.vtp" || fail "subdiv refine cube.obj -o x.vtp"
grep -q "<VTKFile" "$WORK/x.vtp" || fail "x.vtp is not a VTK XML file"
"$subdiv" refine "$WORK/cube.obj" --scheme catmull-clark --levels 2 -o "$WORK/cc.obj" || fail "refine with catmull-clark"
# Catmull-Clark, cube, 2 levels: V = 8 + 12 + 6 -> 26, then 26 + 48 + 24 = 98 vertices, 6 * 16 = 96 quads.
test "$(grep -c '^v ' "$WORK/cc.obj")" -eq 98 || fail "catmull-clark level 2 of the cube: expected 98 vertices"
test "$(grep -c '^f ' "$WORK/cc.obj")" -eq 96 || fail "catmull-clark level 2 of the cube: expected 96 faces"
"$subdiv" refine "$WORK/cube.obj" --scheme sqrt2 --levels 1 -o "$WORK/sqrt2.obj" || fail "refine with the installed sqrt2 plugin"

if [ -n "$PYTHON" ]; then
  package=$(find "$prefix/lib" -maxdepth 5 -path '*/subdivkit/__init__.py' | head -1)
  test -n "$package" || fail "no subdivkit package under $prefix"
  site=$(dirname "$(dirname "$package")")
  echo "-- python: import subdivkit from $site"
  PYTHONPATH="$site" "$PYTHON" - "$WORK/cube.obj" "$prefix" <<'PY' || fail "the installed Python package"
import os, sys
import subdivkit as sk
cube_path, prefix = sys.argv[1], os.path.realpath(sys.argv[2])
assert os.path.realpath(sk.__file__).startswith(prefix), sk.__file__
builtin = {s["name"]: s for s in sk.schemes() if s["origin"] == "built-in"}
assert "catmull-clark" in builtin and "loop" in builtin, sorted(builtin)
assert os.path.realpath(builtin["loop"]["path"]).startswith(prefix), builtin["loop"]["path"]
fine = sk.refine(sk.read_mesh(cube_path), "catmull-clark", 2)
assert fine.points.shape == (98, 3) and len(fine.faces) == 96, (fine.points.shape, len(fine.faces))
print("subdivkit", sk.__version__, "from", os.path.dirname(sk.__file__), ": cube at level 2 has", len(fine.points), "points")
PY
fi

echo "-- plugins/template built against the installed package"
"$CMAKE_COMMAND" -S "$WORK/template" -B "$WORK/template-build" -G "$CMAKE_GENERATOR" -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_PREFIX_PATH="$prefix" > "$WORK/template.log" 2>&1 || { cat "$WORK/template.log"; fail "configure plugins/template"; }
"$CMAKE_COMMAND" --build "$WORK/template-build" >> "$WORK/template.log" 2>&1 || { cat "$WORK/template.log"; fail "build plugins/template"; }
"$subdiv" refine "$WORK/cube.obj" --plugin "$WORK/template-build/my_plugin.so" --scheme my-scheme --levels 1 \
  -o "$WORK/mine.obj" || fail "refine with the template plugin's scheme"

plugin=$(find "$prefix/lib" -maxdepth 5 -path '*/plugins/SubdivKit/SubdivKit.so' | head -1)
if [ -n "${PVBATCH:-}" ] && [ -n "$plugin" ]; then
  echo "-- pvbatch: SubdivKit Refine through PV_PLUGIN_PATH=$(dirname "$plugin")"
  cat > "$WORK/pv_check.py" <<'PY'
from paraview import simple
refine = simple.SubdivKitRefine(Input=simple.Sphere(), Scheme="loop", Levels=1)
refine.UpdatePipeline()
assert refine.GetDataInformation().GetNumberOfCells() == 4 * 96, refine.GetDataInformation().GetNumberOfCells()
PY
  PV_PLUGIN_PATH="$(dirname "$plugin")" "$PVBATCH" "$WORK/pv_check.py" || fail "the installed ParaView plugin"
fi
if [ -n "${PVBATCH:-}" ] && [ -n "$plugin" ] && [ "${PV_AUTOLOAD:-0}" = 1 ]; then
  # The package's paraview.conf beside ParaView's programs: loaded at start, no LoadPlugin
  # and no PV_PLUGIN_PATH; ParaView's own plugins are still offered.
  echo "-- pvbatch: the plugin loaded at start (paraview.conf), ParaView's own plugins still listed"
  cat > "$WORK/pv_autoload.py" <<'PY'
from paraview import simple
from paraview.modules.vtkRemotingCore import vtkPVPluginTracker
tracker = vtkPVPluginTracker.GetInstance()
names = [tracker.GetPluginName(i) for i in range(tracker.GetNumberOfPlugins())]
assert "SubdivKit" in names, names
assert "GMVReader" in names, names
refine = simple.SubdivKitRefine(Input=simple.Sphere(), Scheme="loop", Levels=1)
refine.UpdatePipeline()
assert refine.GetDataInformation().GetNumberOfCells() == 4 * 96, refine.GetDataInformation().GetNumberOfCells()
print("pvbatch: SubdivKit loaded at start among", len(names), "plugins")
PY
  env -u PV_PLUGIN_PATH -u PV_PLUGIN_CONFIG_FILE "$PVBATCH" "$WORK/pv_autoload.py" || fail "the plugin is not loaded when ParaView starts"
fi
echo "-- installed_checks.sh: ok"
