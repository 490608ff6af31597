"""pvbatch: creases of "SubdivKit Refine" from a cell array and from the feature angle
agree with `subdiv refine --features FILE.json` and `--feature-angle` on the same cube:
 - a cell array on line cells: each segment's value is its sharpness (semi-sharp 2.5 and
   infinitely sharp 10);
 - a cell array on faces (a part id): edges between different parts are infinitely sharp;
 - UseFeatureAngle: edges whose faces meet at more than the angle are infinitely sharp."""

from paraview.simple import PVTrivialProducer
from vtkmodules.vtkCommonCore import vtkDoubleArray, vtkPoints
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData

import pv_support as pv

pv.load_plugin(globals())

CORNERS = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)]
FACES = [(0, 3, 2, 1), (4, 5, 6, 7), (0, 1, 5, 4), (1, 2, 6, 5), (2, 3, 7, 6), (3, 0, 4, 7)]  # face 1: the top
LINES = [((4, 5, 6), 2.5), ((0, 1), 10.0)]  # a semi-sharp polyline over the top, an infinitely sharp edge


def cell_array(name, values):
    a = vtkDoubleArray()
    a.SetName(name)
    for v in values:
        a.InsertNextValue(v)
    return a


def creased_cube():
    """A unit cube of 6 quads with 2 line cells; cell arrays "crease" (the lines' sharpness,
    0 on faces) and "part" (1 on the top face, 0 elsewhere). VTK numbers lines before polygons."""
    poly = vtkPolyData()
    points = vtkPoints()
    for p in CORNERS:
        points.InsertNextPoint(p)
    poly.SetPoints(points)
    lines, faces = vtkCellArray(), vtkCellArray()
    for ids, _ in LINES:
        lines.InsertNextCell(len(ids), ids)
    for f in FACES:
        faces.InsertNextCell(4, f)
    poly.SetLines(lines)
    poly.SetPolys(faces)
    poly.GetCellData().AddArray(cell_array("crease", [s for _, s in LINES] + [0.0] * len(FACES)))
    poly.GetCellData().AddArray(cell_array("part", [0.0] * len(LINES) + [1.0 if f == 1 else 0.0 for f in range(6)]))
    return poly


cube = PVTrivialProducer()
cube.GetClientSideObject().SetOutput(creased_cube())
cube.UpdatePipeline()
path = pv.write_input(cube, "creased-cube.vtp")

line_creases = {"creases": [{"edge": [a, b], "sharpness": s} for ids, s in LINES for a, b in zip(ids, ids[1:])]}
top_edges = list(zip(FACES[1], FACES[1][1:] + FACES[1][:1]))
part_creases = {"creases": [{"edge": list(e), "sharpness": "infinite"} for e in top_edges]}
cases = [("crease array on lines", {"CreaseArray": "crease"}, ["--features", pv.json_file("lines.json", line_creases)]),
         ("part array on faces", {"CreaseArray": "part"}, ["--features", pv.json_file("parts.json", part_creases)]),
         ("feature angle 40", {"UseFeatureAngle": 1, "FeatureAngle": 40}, ["--feature-angle", 40])]
smooth = None
for what, properties, options in cases:
    refine = SubdivKitRefine(Input=cube, Scheme="catmull-clark", Levels=3, **properties)  # noqa: F821
    refine.UpdatePipeline()
    got = pv.fetch(refine)
    want = pv.cli_refine(path, what.replace(" ", "-"), "-s", "catmull-clark", "-l", 3, *options)
    pv.assert_same_polydata(got, want, what)
    creased = got.GetNumberOfCells() - got.GetNumberOfPolys()  # crease edges are line cells
    assert creased > 0, what
    print(f"{what}: as subdiv refine {' '.join(map(str, options[:1]))} ({creased} crease edges at level 3)")

# Without a crease array the same cube is smooth: the arrays made the difference.
plain = SubdivKitRefine(Input=cube, Scheme="catmull-clark", Levels=3)  # noqa: F821
plain.UpdatePipeline()
assert pv.fetch(plain).GetNumberOfCells() == pv.fetch(plain).GetNumberOfPolys()
print("creases_test: ok")
