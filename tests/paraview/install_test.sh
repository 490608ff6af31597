#!/bin/sh
# The installed plugin loads where ParaView looks for plugins: `cmake --install` into a
# temporary prefix, then pvbatch finds "SubdivKit Refine" without LoadPlugin, through
# PV_PLUGIN_PATH (the plugin's folder) and through PV_PLUGIN_CONFIG_FILE (the installed
# subdivkit.plugins.xml, which also lists it in the GUI's plugin manager), and the GUI
# under Xvfb where xvfb-run is installed. The installed
# plugin links the installed libsubdiv and ParaView's VTK only: one VTK in the process.
# Environment: SUBDIV_BUILD_DIR, SUBDIV_PARAVIEW_PLUGIN_SUBDIR (lib/paraview-X.Y/plugins
# under the prefix), PVBATCH, CMAKE_COMMAND.
set -eu
prefix=$(mktemp -d "${TMPDIR:-/tmp}/subdivkit-install.XXXXXX")
trap 'rm -rf "$prefix"' EXIT
"$CMAKE_COMMAND" --install "$SUBDIV_BUILD_DIR" --prefix "$prefix" > "$prefix/install.log"
plugins="$prefix/$SUBDIV_PARAVIEW_PLUGIN_SUBDIR"
test -f "$plugins/SubdivKit/SubdivKit.so" || { echo "no $plugins/SubdivKit/SubdivKit.so after cmake --install" >&2; exit 1; }

libraries=$(ldd "$plugins/SubdivKit/libSubdivKitParaViewFilters.so")
echo "$libraries" | grep -q "libsubdiv.so.* => $prefix/" ||
  { echo "the installed plugin does not use the installed libsubdiv:" >&2; echo "$libraries" >&2; exit 1; }
if echo "$libraries" | grep -E 'libvtk[A-Za-z]+-9\.[0-9]+\.so' >&2; then
  echo "the installed plugin links Debian's VTK (above) besides ParaView's" >&2; exit 1
fi

script="$prefix/find_filter.py"
cat > "$script" <<'PY'
from paraview import simple  # the plugin, loaded at start, added SubdivKitRefine to it
refine = simple.SubdivKitRefine(Input=simple.Sphere(), Scheme="loop", Levels=1)
refine.UpdatePipeline()
assert refine.GetDataInformation().GetNumberOfCells() == 4 * 96, refine.GetDataInformation().GetNumberOfCells()
PY
PV_PLUGIN_PATH="$plugins/SubdivKit" "$PVBATCH" "$script"
echo "PV_PLUGIN_PATH=$plugins/SubdivKit: SubdivKit Refine found without LoadPlugin"
PV_PLUGIN_CONFIG_FILE="$plugins/subdivkit.plugins.xml" "$PVBATCH" "$script"
echo "PV_PLUGIN_CONFIG_FILE=$plugins/subdivkit.plugins.xml: found too"
# The GUI the same way, under Xvfb (ParaView's --script runs the check after the plugins load).
if command -v xvfb-run > /dev/null && command -v paraview > /dev/null; then
  gui_script="$prefix/gui_check.py"
  sed "s|^assert .*|open('$gui_script.ok', 'w').write('ok')|" "$script" > "$gui_script"
  PV_PLUGIN_PATH="$plugins/SubdivKit" xvfb-run -a paraview --script="$gui_script" --exit > "$prefix/gui.log" 2>&1 || true
  test -f "$gui_script.ok" || { echo "the ParaView GUI did not run SubdivKit Refine:" >&2; cat "$prefix/gui.log" >&2; exit 1; }
  echo "the ParaView GUI (under Xvfb) found it through PV_PLUGIN_PATH too"
fi
echo "install_test: ok"
