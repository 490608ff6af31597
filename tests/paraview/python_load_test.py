"""pvbatch with the build's subdivkit module on PYTHONPATH: subdivkit.load_paraview_plugin()
finds the plugin beside the package (no SUBDIV_PARAVIEW_PLUGIN) and loads it; the module and
the plugin then work side by side in one process, on one libsubdiv: the filter's refined
points are subdivkit.refine's."""

import os

import numpy as np
from paraview import servermanager as sm
from paraview.simple import Box, Clean

os.environ.pop("SUBDIV_PARAVIEW_PLUGIN", None)
import subdivkit  # noqa: E402

print("plugin:", subdivkit.paraview_plugin_path())
subdivkit.load_paraview_plugin(globals())
cube = Clean(Input=Box())
refine = SubdivKitRefine(Input=cube, Scheme="catmull-clark", Levels=2)  # noqa: F821
refine.UpdatePipeline()
got = sm.Fetch(refine)
data = sm.Fetch(cube)
points = np.array([data.GetPoint(i) for i in range(data.GetNumberOfPoints())])
polys = data.GetPolys()
offsets = np.array([polys.GetOffsetsArray().GetValue(i) for i in range(polys.GetNumberOfCells() + 1)])
indices = np.array([polys.GetConnectivityArray().GetValue(i) for i in range(offsets[-1])])
want = subdivkit.refine(subdivkit.Mesh(points, indices, face_offsets=offsets), "catmull-clark", 2)
assert got.GetNumberOfPoints() == len(want.points), (got.GetNumberOfPoints(), len(want.points))
error = max(abs(np.array(got.GetPoint(i)) - want.points[i]).max() for i in range(len(want.points)))
assert error < 1e-12, error
print("python_load_test: ok (load_paraview_plugin; the filter's points are subdivkit.refine's)")
