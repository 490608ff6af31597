"""Shared by the pvbatch tests of the ParaView plugin (plugins/paraview): load the plugin,
run the `subdiv` command line on the same input, read its output, compare.

Environment (set by ctest, see plugins/paraview/CMakeLists.txt): SUBDIV_PARAVIEW_PLUGIN,
the plugin's SubdivKit.so; SUBDIV_CLI, the `subdiv` program; SUBDIV_SOURCE_DIR, the source tree.
"""

import atexit
import json
import math
import os
import shutil
import subprocess
import tempfile

from paraview import servermanager as sm
from paraview.simple import LoadPlugin, SaveData
from vtkmodules.vtkCommonCore import vtkOutputWindow, vtkStringOutputWindow
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader

PLUGIN = os.environ["SUBDIV_PARAVIEW_PLUGIN"]
CLI = os.environ["SUBDIV_CLI"]
SOURCE_DIR = os.environ.get("SUBDIV_SOURCE_DIR", os.getcwd())
WORK = tempfile.mkdtemp(prefix="subdivkit-paraview-")
atexit.register(shutil.rmtree, WORK, ignore_errors=True)


def load_plugin(ns):
    """The plugin's proxies (SubdivKitRefine, SubdivKitAnalyze) into the caller's namespace."""
    LoadPlugin(PLUGIN, remote=False, ns=ns)


def cli(*args):
    """Runs `subdiv ARGS...`; returns its standard output, fails the test on an error."""
    done = subprocess.run([CLI, *map(str, args)], capture_output=True, text=True)
    assert done.returncode == 0, f"subdiv {' '.join(map(str, args))}: {done.stderr}"
    return done.stdout


def write_input(proxy, name):
    """The proxy's output as a .vtp file, the very data the filter gets."""
    path = os.path.join(WORK, name)
    SaveData(path, proxy=proxy)
    return path


def read_vtp(path):
    reader = vtkXMLPolyDataReader()
    reader.SetFileName(path)
    reader.Update()
    return reader.GetOutput()


def cli_refine(input_path, name, *options):
    """`subdiv refine INPUT OPTIONS -o NAME.vtp` with every array the plugin shows, read back."""
    out = os.path.join(WORK, name + ".vtp")
    cli("refine", input_path, "-q", "--arrays", "all", "-o", out, *options)
    return read_vtp(out)


def arrays(attributes):
    return {attributes.GetArrayName(i): attributes.GetArray(i) for i in range(attributes.GetNumberOfArrays())}


def assert_same_polydata(got, want, what, tolerance=1e-12):
    """Counts, every point and cell array (names, sizes, values) and positions agree."""
    assert got.GetNumberOfPoints() == want.GetNumberOfPoints(), (what, got.GetNumberOfPoints(), want.GetNumberOfPoints())
    assert got.GetNumberOfPolys() == want.GetNumberOfPolys(), (what, got.GetNumberOfPolys(), want.GetNumberOfPolys())
    assert got.GetNumberOfCells() == want.GetNumberOfCells(), (what, got.GetNumberOfCells(), want.GetNumberOfCells())
    for i in range(got.GetNumberOfPoints()):
        p, q = got.GetPoint(i), want.GetPoint(i)
        assert max(abs(a - b) for a, b in zip(p, q)) <= tolerance, (what, "point", i, p, q)
    for kind, a, b in (("point", got.GetPointData(), want.GetPointData()),
                       ("cell", got.GetCellData(), want.GetCellData())):
        mine, theirs = arrays(a), arrays(b)
        assert set(mine) == set(theirs), (what, kind, sorted(mine), sorted(theirs))
        for name, x in mine.items():
            y = theirs[name]
            assert (x.GetNumberOfTuples(), x.GetNumberOfComponents()) == \
                (y.GetNumberOfTuples(), y.GetNumberOfComponents()), (what, kind, name)
            for t in range(x.GetNumberOfTuples()):
                for c in range(x.GetNumberOfComponents()):
                    u, v = x.GetComponent(t, c), y.GetComponent(t, c)
                    assert u == v or abs(u - v) <= tolerance * max(1.0, abs(v)) or (math.isnan(u) and math.isnan(v)), \
                        (what, kind, name, t, c, u, v)


def fetch(proxy, port=0):
    return sm.Fetch(proxy, idx=port)


class CapturedMessages:
    """ParaView's output window replaced by a string while the block runs: what a filter
    reports there (errors, warnings) can then be read back."""

    def __enter__(self):
        self.previous = vtkOutputWindow.GetInstance()
        self.window = vtkStringOutputWindow()
        vtkOutputWindow.SetInstance(self.window)
        return self

    def __exit__(self, *exc):
        self.text = self.window.GetOutput()
        vtkOutputWindow.SetInstance(self.previous)
        return False


def json_file(name, data):
    path = os.path.join(WORK, name)
    with open(path, "w") as f:
        f.write(data if isinstance(data, str) else json.dumps(data))
    return path
