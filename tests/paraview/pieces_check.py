"""A refinement in pieces (`subdiv refine --pieces N -o OUT.pvtp`, docs/scale.md) opened by
ParaView as one dataset: its cells and bounds equal the serial run's .vtp, and with the
pieces' shared points merged, so do its points. Run it with pvbatch, serially or in
parallel (each rank then reads some of the pieces, and ParaView adds up their counts):

    subdiv refine MESH -l 3 -o serial.vtp
    subdiv refine MESH -l 3 --pieces 4 -o pieces.pvtp
    pvbatch tests/paraview/pieces_check.py pieces.pvtp serial.vtp
    mpirun -n 2 pvbatch tests/paraview/pieces_check.py pieces.pvtp serial.vtp

(as root, mpirun needs --allow-run-as-root, and --oversubscribe for more ranks than cores).
"""

import sys

from paraview.simple import Clean, OpenDataFile
from paraview import servermanager as sm

pvtp, vtp = sys.argv[1], sys.argv[2]
pieces = OpenDataFile(pvtp)
serial = OpenDataFile(vtp)
pieces.UpdatePipeline()
serial.UpdatePipeline()
got, want = pieces.GetDataInformation(), serial.GetDataInformation()

assert pieces.GetXMLName() == "XMLPPolyDataReader", pieces.GetXMLName()
assert got.GetNumberOfCells() == want.GetNumberOfCells(), (got.GetNumberOfCells(), want.GetNumberOfCells())
assert got.GetBounds() == want.GetBounds(), (got.GetBounds(), want.GetBounds())
# Pieces repeat the points they share; each piece holds at least one of its own.
assert got.GetNumberOfPoints() >= want.GetNumberOfPoints(), (got.GetNumberOfPoints(), want.GetNumberOfPoints())

ranks = sm.vtkProcessModule.GetProcessModule().GetNumberOfLocalPartitions()
if ranks == 1:
    # One process holds every piece: merging equal points gives the serial run's points.
    merged = Clean(Input=pieces, Tolerance=0.0, PointMerging=1, ConvertLinesToPoints=0, ConvertPolysToLines=0,
                   ConvertStripsToPolys=0)
    merged.UpdatePipeline()
    points = merged.GetDataInformation().GetNumberOfPoints()
    assert points == want.GetNumberOfPoints(), (points, want.GetNumberOfPoints())
print(f"pvbatch on {ranks} rank(s): {pvtp} has {got.GetNumberOfCells()} cells and the bounds of {vtp}; "
      f"{got.GetNumberOfPoints()} points before merging shared ones")
