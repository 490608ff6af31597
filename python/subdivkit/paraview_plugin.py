"""SubdivKit inside ParaView: the "SubdivKit Refine" filter (a ParaView Python plugin).

With the ``subdivkit`` module on ParaView's Python path (``PYTHONPATH=build/python`` in a
build tree, or an installed SubdivKit; built against ParaView's VTK where ParaView is
installed, which scripts/install-deps.sh chooses, so that one VTK is in the process), run
in pvpython, pvbatch or the GUI's Python Shell:

    import subdivkit; subdivkit.load_paraview_plugin(globals())

(or load this file with Tools > Manage Plugins where ParaView's Python plugins work; on
Debian 12 they do not without the fix load_paraview_plugin applies, see its docstring).

The filter takes polygonal data (polygons; points, lines and strips are not refined),
refines it with any registered scheme or a .json scheme file, and outputs the finest level
with the input's point arrays refined like the points and its cell arrays following the
faces (docs/primvars.md); normals are left out. SubdivKit's errors (a scheme that does not
parse, a triangle scheme on quads) go to ParaView's output window and leave the output
empty; ParaView does not stop.
"""

import numpy as np
from paraview.util.vtkAlgorithm import VTKPythonAlgorithmBase, smdomain, smhint, smproperty, smproxy
from vtkmodules.numpy_interface import dataset_adapter as dsa
from vtkmodules.util import numpy_support
from vtkmodules.vtkCommonCore import vtkOutputWindow, vtkPoints
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData

import subdivkit as sk

BOUNDARIES = ("edges-and-corners", "edges", "none")
CREASE_METHODS = ("uniform", "chaikin")


def _surface_scheme_names():
    return [s["name"] for s in sk.schemes() if s["kind"] == "surface"]


def _string_list_xml(name, label, values, default):
    strings = "".join(f'<String value="{v}"/>' for v in values)
    return (f'<StringVectorProperty name="{name}" label="{label}" command="Set{name}" number_of_elements="1" '
            f'default_values="{default}"><StringListDomain name="list">{strings}</StringListDomain>'
            f'</StringVectorProperty>')


def _enumeration_xml(name, label, values):
    entries = "".join(f'<Entry value="{i}" text="{v}"/>' for i, v in enumerate(values))
    return (f'<IntVectorProperty name="{name}" label="{label}" command="Set{name}" number_of_elements="1" '
            f'default_values="0"><EnumerationDomain name="enum">{entries}</EnumerationDomain></IntVectorProperty>')


def _parse_params(text):
    """'beta=warren lambda=0.6' -> {'beta': 'warren', 'lambda': '0.6'}."""
    params = {}
    for word in text.split():
        name, sep, value = word.partition("=")
        if not sep or not name:
            raise sk.Error(f"Parameters: '{word}' must be written name=value")
        params[name] = value
    return params


def _as_data(values):
    """A VTK array's values as refine() reads them: integer arrays stay integers (labels)."""
    a = np.asarray(values)
    return a if a.dtype.kind in "iub" else a.astype(np.float64)


def _point_roles(attributes):
    """The roles of the active texture coordinates and byte colours (as the C++ reader, vtk_read.cpp)."""
    roles = {}
    tcoords, scalars = attributes.GetTCoords(), attributes.GetScalars()
    if tcoords is not None and tcoords.GetName():
        roles[tcoords.GetName()] = "texture_coordinates"
    if scalars is not None and scalars.GetName() and scalars.GetDataTypeAsString() == "unsigned_char":
        roles[scalars.GetName()] = "color"
    return roles


def _mesh_from_polydata(poly):
    """The polygons of a vtkPolyData, with its point and polygon-cell arrays."""
    points = numpy_support.vtk_to_numpy(poly.GetPoints().GetData()).astype(np.float64) if poly.GetPoints() else \
        np.zeros((0, 3))
    polys = poly.GetPolys()
    offsets = numpy_support.vtk_to_numpy(polys.GetOffsetsArray()).astype(np.int64)
    connectivity = numpy_support.vtk_to_numpy(polys.GetConnectivityArray()).astype(np.int64)
    wrapped = dsa.WrapDataObject(poly)
    normals = poly.GetPointData().GetNormals()
    point_data = {name: _as_data(wrapped.PointData[name])
                  for name in wrapped.PointData.keys()
                  if wrapped.PointData[name] is not None and not (normals and name == normals.GetName())}
    # Cells are numbered vertices, lines, polygons, strips: the polygons' tuples follow the first two.
    first = poly.GetNumberOfVerts() + poly.GetNumberOfLines()
    count = poly.GetNumberOfPolys()
    cell_data = {name: _as_data(wrapped.CellData[name])[first:first + count]
                 for name in wrapped.CellData.keys() if wrapped.CellData[name] is not None}
    return sk.Mesh(points, connectivity, face_offsets=offsets, point_data=point_data, cell_data=cell_data,
                   point_roles=_point_roles(poly.GetPointData()))


def _polydata_from_mesh(mesh, out):
    points = numpy_support.numpy_to_vtk(np.ascontiguousarray(mesh.points), deep=True)
    vtk_points = vtkPoints()
    vtk_points.SetData(points)
    out.SetPoints(vtk_points)
    cells = vtkCellArray()
    cells.SetData(numpy_support.numpy_to_vtkIdTypeArray(mesh.face_offsets.astype(np.int64), deep=True),
                  numpy_support.numpy_to_vtkIdTypeArray(mesh.face_indices.astype(np.int64), deep=True))
    out.SetPolys(cells)
    for kind, data, roles in ((out.GetPointData(), mesh.point_data, mesh.point_roles),
                              (out.GetCellData(), mesh.cell_data, mesh.cell_roles)):
        for name, values in data.items():
            role = roles.get(name)
            if role == "color" and values.dtype.kind in "iu" and values.min() >= 0 and values.max() <= 255:
                values = values.astype(np.uint8)  # byte colours, shown as they are
            array = numpy_support.numpy_to_vtk(np.ascontiguousarray(values), deep=True)
            array.SetName(name)
            kind.AddArray(array)
            # The first array of a role is the active one (setting another would drop the first).
            if role == "texture_coordinates" and kind.GetTCoords() is None:
                kind.SetTCoords(array)
            elif role == "color" and kind.GetScalars() is None:
                kind.SetScalars(array)


@smproxy.filter(name="SubdivKitRefine", label="SubdivKit Refine")
@smhint.xml('<ShowInMenu category="SubdivKit"/>')
@smproperty.input(name="Input", port_index=0)
@smdomain.datatype(dataTypes=["vtkPolyData"], composite_data_supported=False)
class SubdivKitRefine(VTKPythonAlgorithmBase):
    """Refine polygons with any SubdivKit scheme (a registered one or a .json file)."""

    def __init__(self):
        super().__init__(nInputPorts=1, nOutputPorts=1, outputType="vtkPolyData")
        self._scheme = "catmull-clark"
        self._scheme_file = ""
        self._levels = 2
        self._parameters = ""
        self._boundary = 0
        self._crease_method = 0
        self._threads = 0
        self._limit = False

    @smproperty.xml(_string_list_xml("Scheme", "Scheme", _surface_scheme_names(), "catmull-clark"))
    def SetScheme(self, name):
        self._scheme = name or "catmull-clark"
        self.Modified()

    @smproperty.stringvector(name="SchemeFile", label="Scheme file (.json)", default_values="")
    @smdomain.filelist()
    @smhint.filechooser(extensions="json", file_description="SubdivKit scheme")
    def SetSchemeFile(self, path):
        self._scheme_file = path or ""  # ParaView passes None for an empty string
        self.Modified()

    @smproperty.intvector(name="Levels", default_values=2)
    @smdomain.intrange(min=0, max=8)
    def SetLevels(self, levels):
        self._levels = int(levels)
        self.Modified()

    @smproperty.stringvector(name="Parameters", label="Parameters (name=value ...)", default_values="")
    def SetParameters(self, text):
        self._parameters = text or ""
        self.Modified()

    @smproperty.xml(_enumeration_xml("Boundary", "Boundary interpolation", BOUNDARIES))
    def SetBoundary(self, index):
        self._boundary = int(index)
        self.Modified()

    @smproperty.xml(_enumeration_xml("CreaseMethod", "Crease method", CREASE_METHODS))
    def SetCreaseMethod(self, index):
        self._crease_method = int(index)
        self.Modified()

    @smproperty.intvector(name="Threads", label="Threads (0: all cores)", default_values=0)
    @smdomain.intrange(min=0, max=256)
    def SetThreads(self, threads):
        self._threads = int(threads)
        self.Modified()

    @smproperty.intvector(name="LimitPositions", label="Limit positions", default_values=0)
    @smdomain.xml('<BooleanDomain name="bool"/>')
    def SetLimitPositions(self, on):
        self._limit = bool(on)
        self.Modified()

    def RequestData(self, request, in_info, out_info):
        source = vtkPolyData.GetData(in_info[0], 0)
        out = vtkPolyData.GetData(out_info, 0)
        out.Initialize()
        try:
            scheme = self._scheme_file or self._scheme
            mesh = _mesh_from_polydata(source)
            refined = sk.refine(mesh, scheme, self._levels, params=_parse_params(self._parameters),
                                boundary=BOUNDARIES[self._boundary], crease_method=CREASE_METHODS[self._crease_method],
                                threads=self._threads)
            if self._limit:
                refined.points = sk.limit_positions(refined, scheme, params=_parse_params(self._parameters),
                                                    boundary=BOUNDARIES[self._boundary],
                                                    crease_method=CREASE_METHODS[self._crease_method],
                                                    start_level=self._levels).points
            _polydata_from_mesh(refined, out)
        except sk.Error as e:
            # SubdivKit's message, as the command line prints it; the output stays empty.
            vtkOutputWindow.GetInstance().DisplayErrorText(f"SubdivKit Refine: {e}\n")
            out.Initialize()
        return 1
