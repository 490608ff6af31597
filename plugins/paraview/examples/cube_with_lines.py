"""A unit cube of 6 quads with line cells over some of its edges and cell arrays, as a
ParaView source: the input of the crease examples (screenshots.py) and of
tests/paraview/creases_test.py. VTK numbers line cells before polygons, so a cell array
holds one value per line, then one per face."""

from paraview.simple import PVTrivialProducer
from vtkmodules.vtkCommonCore import vtkDoubleArray, vtkPoints
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData

CORNERS = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)]
FACES = [(0, 3, 2, 1), (4, 5, 6, 7), (0, 1, 5, 4), (1, 2, 6, 5), (2, 3, 7, 6), (3, 0, 4, 7)]  # 0 bottom, 1 top


def cube_with_lines(lines, cell_arrays, offset=(0, 0, 0)):
    """lines: lists of corner indices; cell_arrays: name -> values (lines first, then FACES);
    offset: added to every corner (-0.5 each centres the cube)."""
    poly, points, line_cells, face_cells = vtkPolyData(), vtkPoints(), vtkCellArray(), vtkCellArray()
    for corner in CORNERS:
        points.InsertNextPoint([c + o for c, o in zip(corner, offset)])
    for ids in lines:
        line_cells.InsertNextCell(len(ids), ids)
    for face in FACES:
        face_cells.InsertNextCell(len(face), face)
    poly.SetPoints(points)
    poly.SetLines(line_cells)
    poly.SetPolys(face_cells)
    for name, values in cell_arrays.items():
        array = vtkDoubleArray()
        array.SetName(name)
        for v in values:
            array.InsertNextValue(v)
        poly.GetCellData().AddArray(array)
    source = PVTrivialProducer()
    source.GetClientSideObject().SetOutput(poly)
    return source
