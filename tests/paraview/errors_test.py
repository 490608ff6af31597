"""pvbatch: SubdivKit's errors reach ParaView's output window with SubdivKit's message,
the filter's output is empty, and pvbatch goes on (the script keeps running and a good
filter after a failed one still works): a scheme JSON that does not parse, a triangle
scheme on quads, a parameter the scheme does not have, a crease array the input lacks, an
analysis of a curve scheme or of valence 1."""

from paraview.simple import Box, Clean, PVTrivialProducer
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData

import pv_support as pv

pv.load_plugin(globals())
cube = Clean(Input=Box())


def expect_error(proxy, *fragments):
    """The proxy's update reports an error naming every fragment; its output is empty."""
    with pv.CapturedMessages() as messages:
        proxy.UpdatePipeline()
    assert "ERROR" in messages.text.upper(), messages.text
    for fragment in fragments:
        assert fragment in messages.text, (fragment, messages.text)
    assert proxy.GetDataInformation().GetNumberOfPoints() == 0
    assert proxy.GetDataInformation().GetNumberOfCells() == 0
    return messages.text


broken = pv.json_file("broken.json", '{"name": "broken", "split": "quad",\n "rules": {')
text = expect_error(SubdivKitRefine(Input=cube, SchemeFile=broken, Levels=1), "broken.json")  # noqa: F821
print("scheme JSON that does not parse:", text.strip().splitlines()[-1][:160])

text = expect_error(SubdivKitRefine(Input=cube, Scheme="loop", Levels=1), "triangle")  # noqa: F821
print("loop on quads:", text.strip().splitlines()[-1][:160])

expect_error(SubdivKitRefine(Input=cube, Scheme="loop", Levels=1, Parameters="nosuch=1"), "nosuch")  # noqa: F821
expect_error(SubdivKitRefine(Input=cube, Scheme="catmull-clark", Parameters="w"), "name=value")  # noqa: F821
expect_error(SubdivKitRefine(Input=cube, CreaseArray="NoSuchArray"), "NoSuchArray")  # noqa: F821
expect_error(SubdivKitAnalyze(Scheme="catmull-clark", SchemeFile=broken), "broken.json")  # noqa: F821
expect_error(SubdivKitAnalyze(Scheme="chaikin"), "curve scheme")  # noqa: F821
# Valences start at 2 (inside and on boundaries): the message gives the range.
expect_error(SubdivKitAnalyze(Scheme="loop", Valences=[1, 4]), "Valences 1..4", "from 2 to 512")  # noqa: F821


def fin():
    """Three triangles on one edge (0, 1): a non-manifold edge no scheme refines."""
    poly, points, faces = vtkPolyData(), vtkPoints(), vtkCellArray()
    for p in [(0, 0, 0), (1, 0, 0), (0.5, 1, 0), (0.5, -1, 0), (0.5, 0, 1)]:
        points.InsertNextPoint(p)
    for f in [(0, 1, 2), (1, 0, 3), (0, 1, 4)]:
        faces.InsertNextCell(3, f)
    poly.SetPoints(points)
    poly.SetPolys(faces)
    source = PVTrivialProducer()
    source.GetClientSideObject().SetOutput(poly)
    return source


# Non-manifold input: the primal splits refine it as OpenSubdiv does; Doo-Sabin takes the
# non-manifold edge as a crease its three sheets share (its ends corners: three faces, joined,
# no gap); the mid-edge split cannot make a face at a non-manifold vertex and says so in the
# output window (a warning: the rest of the surface is refined, as `subdiv refine` does).
fin_loop = SubdivKitRefine(Input=fin(), Scheme="loop", Levels=1)  # noqa: F821
fin_loop.UpdatePipeline()
assert pv.fetch(fin_loop).GetNumberOfPolys() == 12, pv.fetch(fin_loop).GetNumberOfPolys()
fin_doo_sabin = SubdivKitRefine(Input=fin(), Scheme="doo-sabin", Levels=1)  # noqa: F821
fin_doo_sabin.UpdatePipeline()
assert pv.fetch(fin_doo_sabin).GetNumberOfPolys() == 3, pv.fetch(fin_doo_sabin).GetNumberOfPolys()
assert pv.fetch(fin_doo_sabin).GetNumberOfPoints() == 5, pv.fetch(fin_doo_sabin).GetNumberOfPoints()
with pv.CapturedMessages() as messages:
    fin_mid_edge = SubdivKitRefine(Input=fin(), Scheme="mid-edge", Levels=1)  # noqa: F821
    fin_mid_edge.UpdatePipeline()
assert "WARN" in messages.text.upper() and "non-manifold" in messages.text, messages.text
print("non-manifold input, mid-edge:", messages.text.strip().splitlines()[-1][:200])

# ParaView went on: the same pipeline refines once the input is right.
good = SubdivKitRefine(Input=cube, Scheme="catmull-clark", Levels=1)  # noqa: F821
good.UpdatePipeline()
assert good.GetDataInformation().GetNumberOfCells() == 24
print("errors_test: ok (7 errors reported with SubdivKit's message, outputs empty, pvbatch went on)")
