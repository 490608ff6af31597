#!/usr/bin/env bash
# CI stage: the README's two commands on a machine where a user already has Debian's
# ParaView and its Python (paraview, python3-paraview). python3-paraview conflicts with
# python3-vtk9, which Debian's libvtk9-dev needs, so installing them removes Debian's VTK;
# setup.sh must then build against ParaView's VTK (paraview-dev) instead. Runs on a clean
# clone of this checkout, as a user would. Run as root, after the default stage.
set -euo pipefail
cd "$(dirname "$0")/.."
export DEBIAN_FRONTEND=noninteractive
source scripts/apt-packages.sh
checkout=$PWD
# The machine is left as the stage found it: where ParaView was not installed before, it is
# removed at the end and Debian's VTK comes back, so that the next run's first stage builds
# as on a fresh Debian 12 machine again.
restore_debian_vtk() {
  echo "== ParaView stage: removing ParaView again, reinstalling Debian's VTK (scripts/install-deps.sh)"
  apt-get remove -y -qq paraview python3-paraview paraview-dev > /dev/null
  apt-get autoremove -y -qq > /dev/null
  SUBDIV_VTK=debian bash "$checkout/scripts/install-deps.sh" > /dev/null
}
had_paraview=0
installed python3-paraview && had_paraview=1
echo "== ParaView stage: installing paraview and python3-paraview (removes Debian's VTK)"
apt-get update -qq
apt-get install -y -qq --no-install-recommends paraview python3-paraview > /dev/null  # setup.sh adds paraview-dev, xvfb
if installed libvtk9-dev; then
  echo "ci-paraview.sh: libvtk9-dev is still installed; this stage would not test ParaView's VTK" >&2
  exit 1
fi
work=$(mktemp -d "${TMPDIR:-/tmp}/subdivkit-paraview.XXXXXX")
cleanup() {
  rm -rf "$work"
  [ "$had_paraview" = 1 ] || restore_debian_vtk
}
trap cleanup EXIT
git clone -q . "$work/subdivkit"
cd "$work/subdivkit"
# With -Werror as the first stage: the same compile commands, so the objects that do not
# see VTK's headers come from ccache instead of being compiled again against ParaView's VTK.
SUBDIV_WERROR=ON bash scripts/setup.sh
grep -q "SUBDIV_VTK_PROVIDER_FOUND:INTERNAL=paraview" build/CMakeCache.txt ||
  { echo "ci-paraview.sh: the build did not use ParaView's VTK" >&2; exit 1; }
bash scripts/test.sh
# The packages of this configuration, paraview-subdivkit included: installed, the plugin
# loaded by pvbatch at start without LoadPlugin or PV_PLUGIN_PATH, removed (issue 34).
bash scripts/ci-install.sh
# ParaView itself opens what `subdiv` wrote (its reader, its Expat).
pvpython -c "
from paraview.simple import OpenDataFile
r = OpenDataFile('out/cube_levels/level_3.vtp'); r.UpdatePipeline()
n = r.GetDataInformation().GetNumberOfCells()
assert n == 384, n
print('pvpython reads out/cube_levels/level_3.vtp:', n, 'cells')
"
# The ParaView plugin (plugins/paraview) was built, and test.sh ran its pvbatch tests
# (ctest -R paraview: tests/paraview/*_test.py against the subdiv command line, and the
# installed plugin found through PV_PLUGIN_PATH).
ls build/lib*/paraview-*/plugins/SubdivKit/SubdivKit.so ||
  { echo "ci-paraview.sh: the ParaView plugin was not built (see the configure output of plugins/paraview)" >&2; exit 1; }
grep -q "paraview_refine" build/plugins/paraview/CTestTestfile.cmake ||
  { echo "ci-paraview.sh: the plugin's pvbatch tests are not registered with ctest" >&2; exit 1; }
# A refinement in pieces opened by ParaView as one dataset, by one pvbatch and by two under
# MPI (tests/paraview/pieces_check.py); mpirun runs as root in CI.
build/tools/subdiv/subdiv refine examples/meshes/torus-quads.obj -l 3 -q -o out/torus.vtp
build/tools/subdiv/subdiv refine examples/meshes/torus-quads.obj -l 3 --pieces 4 -q -o out/torus.pvtp
pvbatch tests/paraview/pieces_check.py out/torus.pvtp out/torus.vtp
mpirun --allow-run-as-root --oversubscribe -n 2 pvbatch tests/paraview/pieces_check.py out/torus.pvtp out/torus.vtp
