"""The ParaView plugin (python/subdivkit/paraview_plugin.py) in pvpython: run by
scripts/ci-paraview.sh on a machine with ParaView, with PYTHONPATH pointing at the build's
subdivkit module. Checks face counts against the splits' arithmetic, that point data is
refined like the points (an affine function of the position stays one), and that an
error leaves an empty output instead of stopping ParaView."""

from paraview.simple import Box, Clean, PythonCalculator, Sphere, TextureMaptoPlane
from paraview import servermanager as sm

import subdivkit

subdivkit.load_paraview_plugin(globals())

# A cube (ParaView's Box has a separate copy of each corner per face: Clean merges them).
cube = Clean(Input=Box())
refined = SubdivKitRefine(Input=cube, Scheme="catmull-clark", Levels=2)  # noqa: F821 (made by LoadPlugin)
refined.UpdatePipeline()
cells = refined.GetDataInformation().GetNumberOfCells()
assert cells == 6 * 16, cells  # a quad split makes 4 quads of each quad, twice
points = refined.GetDataInformation().GetNumberOfPoints()
assert points == 98, points  # a closed quad mesh: V - E + F = 2 at every level

# Point data: height = 2 x + 3 y - z + 1 is refined exactly as positions are.
sphere = Sphere(ThetaResolution=16, PhiResolution=9)
height = PythonCalculator(Input=sphere, Expression="2 * inputs[0].Points[:, 0] + 3 * inputs[0].Points[:, 1] - "
                                                   "inputs[0].Points[:, 2] + 1", ArrayName="height")
loop = SubdivKitRefine(Input=height, Scheme="loop", Levels=2)  # noqa: F821
loop.UpdatePipeline()
data = sm.Fetch(loop)
assert data.GetNumberOfPolys() == 16 * sphere.GetDataInformation().GetNumberOfCells()
h = data.GetPointData().GetArray("height")
for i in range(data.GetNumberOfPoints()):
    x, y, z = data.GetPoint(i)
    # ParaView's sphere and calculator work in float32: agreement to float32's precision.
    assert abs(h.GetValue(i) - (2 * x + 3 * y - z + 1)) < 1e-5, (i, h.GetValue(i))
assert data.GetPointData().GetArray("Normals") is None  # normals are left out

# Integer arrays are labels (taken, never averaged) and the active texture coordinates stay
# active: ParaView's Texture property works on the refined mesh.
textured = TextureMaptoPlane(Input=sphere)
labelled = PythonCalculator(Input=textured, Expression="(inputs[0].Points[:, 2] > 0) + 3", ArrayName="label")
tri = SubdivKitRefine(Input=labelled, Scheme="loop", Levels=1)  # noqa: F821
tri.UpdatePipeline()
data = sm.Fetch(tri)
label = data.GetPointData().GetArray("label")
assert label.GetDataTypeAsString() == "int", label.GetDataTypeAsString()  # int32, as the library's integer arrays
assert {label.GetValue(i) for i in range(data.GetNumberOfPoints())} == {3, 4}
assert data.GetPointData().GetTCoords() is not None

# A triangle scheme on quads: SubdivKit's message, an empty output, ParaView goes on.
wrong = SubdivKitRefine(Input=cube, Scheme="loop", Levels=1)  # noqa: F821
wrong.UpdatePipeline()
assert wrong.GetDataInformation().GetNumberOfCells() == 0
print("ParaView plugin: SubdivKit Refine ok (cube 96 quads, sphere Loop with point data, labels and texture "
      "coordinates, error gives empty output)")
