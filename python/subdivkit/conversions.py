"""Meshes to and from the Python libraries users hold their meshes in: VTK's vtkPolyData
(and so PyVista, whose PolyData is one), Open3D's TriangleMesh and trimesh's Trimesh.

Each import is optional: the library is imported when its function is first called, and
a missing one raises ImportError naming the Debian package. Conversions copy as little as
the other library allows; points become float64 and indices int32, as everywhere in
subdivkit. Triangle-only libraries (Open3D, trimesh) get n-gons split into fans
(triangles (v0, vi, vi+1)), and a face's cell data goes to each of its triangles.

    import subdivkit as sk
    fine = sk.refine(sk.from_vtk(polydata), "loop", 2)
    pyvista.wrap(sk.to_vtk(fine)).plot()
    open3d.visualization.draw_geometries([sk.to_open3d(fine)])
"""
import numpy as np

from . import _subdivkit
from ._subdivkit import Error
from .mesh import Mesh, _data_arrays, _escaped, _type_name


def _require(module, debian_package):
    try:
        return __import__(module, fromlist=["_"])
    except ImportError as e:
        raise ImportError(f"{module} is not installed: on Debian, apt-get install {debian_package}") from e


def _fan_triangles(mesh):
    """Triangles (v0, vi, vi+1) of every face, and the face each comes from."""
    offsets, indices = mesh.face_offsets, mesh.face_indices
    sizes = np.diff(offsets)
    if np.any(sizes < 3):
        raise Error(f"{_escaped(mesh.name)}: face {int(np.argmax(sizes < 3))} has fewer than 3 vertices; it makes no triangle")
    per_face = sizes - 2
    face_of = np.repeat(np.arange(mesh.n_faces), per_face)
    # Triangle t of face f is (first of f, its (k+1)-th, its (k+2)-th), k = t - first triangle of f.
    first_triangle = np.concatenate([[0], np.cumsum(per_face)[:-1]]).astype(np.int64)
    k = np.arange(len(face_of)) - np.repeat(first_triangle, per_face)
    start = offsets[:-1].astype(np.int64)[face_of]
    triangles = np.column_stack([indices[start], indices[start + k + 1], indices[start + k + 2]])
    return triangles.astype(np.int32), face_of


def _role_array(mesh, role, columns):
    """The point array with `role` (point_roles), if it has `columns` columns."""
    for name, value in mesh.point_data.items():
        if mesh.point_roles.get(name) == role:
            array = np.asarray(value, dtype=float)
            if array.ndim == 2 and array.shape[1] == columns:
                return array
    return None


# ---- VTK and PyVista ---------------------------------------------------------------------------

def _vtk_cells(cell_array):
    from vtkmodules.util.numpy_support import vtk_to_numpy
    offsets = vtk_to_numpy(cell_array.GetOffsetsArray()).astype(np.int64)
    connectivity = vtk_to_numpy(cell_array.GetConnectivityArray()).astype(np.int64)
    return connectivity, offsets


def _vtk_arrays(attributes, rows, first=0):
    """The named numeric arrays' tuples first .. first + rows - 1, with their roles."""
    from vtkmodules.util.numpy_support import vtk_to_numpy
    data, roles = {}, {}
    special = {"normals": attributes.GetNormals(), "texture_coordinates": attributes.GetTCoords()}
    for i in range(attributes.GetNumberOfArrays()):
        array = attributes.GetArray(i)  # numeric arrays only; string arrays are None
        if array is None or not array.GetName() or array.GetNumberOfTuples() < first + rows:
            continue
        values = vtk_to_numpy(array)[first:first + rows]
        if array.GetNumberOfComponents() == 1:
            values = values.reshape(-1)
        data[array.GetName()] = values.copy()
        for role, active in special.items():
            if active is not None and active.GetName() == array.GetName():
                roles[array.GetName()] = role
    return data, roles


def from_vtk(polydata, name="vtkPolyData"):
    """A Mesh from a vtkPolyData (or a pyvista.PolyData): its points, polygons and lines,
    and its numeric point and cell arrays (the active normals and texture coordinates keep
    their roles). Triangle strips and vertex cells are refused: run vtkTriangleFilter first.
    VTK's cell data runs over the lines, then the polygons: the polygons' rows become the
    Mesh's cell data (which is per face)."""
    _require("vtkmodules.vtkCommonDataModel", "python3-vtk9")
    from vtkmodules.util.numpy_support import vtk_to_numpy
    if not hasattr(polydata, "GetPolys"):
        raise Error(f"from_vtk: expected a vtkPolyData, got {_type_name(polydata)}")
    if polydata.GetNumberOfStrips():
        raise Error(f"{_escaped(name)}: {polydata.GetNumberOfStrips()} triangle strip(s): run vtkTriangleFilter first")
    if polydata.GetNumberOfVerts():
        raise Error(f"{_escaped(name)}: {polydata.GetNumberOfVerts()} vertex cell(s) are not polygons or lines: remove them "
                    "(vtkExtractCells) or keep the polygons only")
    points = polydata.GetPoints()
    xyz = np.zeros((0, 3)) if points is None else vtk_to_numpy(points.GetData()).astype(float)
    faces, face_offsets = _vtk_cells(polydata.GetPolys())
    lines, line_offsets = _vtk_cells(polydata.GetLines())
    point_data, point_roles = _vtk_arrays(polydata.GetPointData(), len(xyz))
    cell_data, cell_roles = _vtk_arrays(polydata.GetCellData(), len(face_offsets) - 1,
                                        first=len(line_offsets) - 1)
    mesh = Mesh(xyz, faces, face_offsets=face_offsets, lines=lines, line_offsets=line_offsets,
                point_data=point_data, cell_data=cell_data, point_roles=point_roles, cell_roles=cell_roles, name=name)
    _check(mesh, "from_vtk")  # as every reader checks its result: indices in range, finite points
    return mesh


def _numpy_to_vtk(name, values):
    from vtkmodules.util.numpy_support import numpy_to_vtk
    array = np.ascontiguousarray(values)
    if array.dtype.kind in "iu":
        array = array.astype(np.int32 if array.dtype.itemsize <= 4 else np.int64)
    else:
        array = array.astype(float)
    out = numpy_to_vtk(array, deep=True)
    out.SetName(name)
    return out


def _cell_array(indices, offsets):
    from vtkmodules.util.numpy_support import numpy_to_vtkIdTypeArray
    from vtkmodules.vtkCommonDataModel import vtkCellArray
    cells = vtkCellArray()
    cells.SetData(numpy_to_vtkIdTypeArray(np.asarray(offsets, dtype=np.int64), deep=True),
                  numpy_to_vtkIdTypeArray(np.asarray(indices, dtype=np.int64), deep=True))
    return cells


def to_vtk(mesh):
    """A vtkPolyData of the Mesh: points, polygons, lines, point and cell arrays (arrays
    with the normals or texture_coordinates role become the active ones). For PyVista:
    ``pyvista.wrap(to_vtk(mesh))``. Creases and corners have no place in a vtkPolyData;
    `subdiv refine` writes them as the cell arrays of a .vtp."""
    _require("vtkmodules.vtkCommonDataModel", "python3-vtk9")
    from vtkmodules.util.numpy_support import numpy_to_vtk
    from vtkmodules.vtkCommonCore import vtkPoints
    from vtkmodules.vtkCommonDataModel import vtkPolyData
    _check(mesh, "to_vtk")
    poly = vtkPolyData()
    points = vtkPoints()
    points.SetData(numpy_to_vtk(np.ascontiguousarray(mesh.points), deep=True))
    poly.SetPoints(points)
    if mesh.n_faces:
        poly.SetPolys(_cell_array(mesh.face_indices, mesh.face_offsets))
    if mesh.n_lines:
        poly.SetLines(_cell_array(mesh.line_indices, mesh.line_offsets))
    for name, values in mesh.point_data.items():
        array = _numpy_to_vtk(name, values)
        role = mesh.point_roles.get(name)
        if role == "normals":
            poly.GetPointData().SetNormals(array)
        elif role == "texture_coordinates":
            poly.GetPointData().SetTCoords(array)
        else:
            poly.GetPointData().AddArray(array)
    for name, values in mesh.cell_data.items():
        # VTK's cell data runs over the lines first: they get no value (NaN, or 0 for labels).
        values = np.asarray(values)
        if mesh.n_lines:
            fill = np.zeros if values.dtype.kind in "iu" else lambda shape: np.full(shape, np.nan)
            values = np.concatenate([fill((mesh.n_lines,) + values.shape[1:]), values])
        poly.GetCellData().AddArray(_numpy_to_vtk(name, values))
    return poly


# ---- Open3D ------------------------------------------------------------------------------------

def from_open3d(triangle_mesh, name="open3d.TriangleMesh"):
    """A Mesh from an open3d.geometry.TriangleMesh: vertices, triangles, and its vertex
    normals and colours when it has them (point arrays "normal" and "color" with those roles)."""
    o3d = _require("open3d", "python3-open3d")
    if not isinstance(triangle_mesh, o3d.geometry.TriangleMesh):
        raise Error(f"from_open3d: expected an open3d.geometry.TriangleMesh, got {_type_name(triangle_mesh)}")
    point_data, point_roles = {}, {}
    if triangle_mesh.has_vertex_normals():
        point_data["normal"], point_roles["normal"] = np.asarray(triangle_mesh.vertex_normals).copy(), "normals"
    if triangle_mesh.has_vertex_colors():
        point_data["color"], point_roles["color"] = np.asarray(triangle_mesh.vertex_colors).copy(), "color"
    mesh = Mesh(np.asarray(triangle_mesh.vertices), np.asarray(triangle_mesh.triangles), point_data=point_data,
                point_roles=point_roles, name=name)
    _check(mesh, "from_open3d")
    return mesh


def to_open3d(mesh):
    """An open3d.geometry.TriangleMesh of the Mesh, n-gons split into fans; a point array
    with the normals role (3 columns) becomes its vertex normals, one with the color role
    its vertex colours (floats in 0..1, as Open3D keeps them)."""
    o3d = _require("open3d", "python3-open3d")
    _check(mesh, "to_open3d")
    triangles, _ = _fan_triangles(mesh)
    out = o3d.geometry.TriangleMesh(o3d.utility.Vector3dVector(np.ascontiguousarray(mesh.points)),
                                    o3d.utility.Vector3iVector(triangles))
    normals = _role_array(mesh, "normals", 3)
    if normals is not None:
        out.vertex_normals = o3d.utility.Vector3dVector(normals)
    colors = _role_array(mesh, "color", 3)
    if colors is not None:
        out.vertex_colors = o3d.utility.Vector3dVector(colors / 255.0 if colors.max(initial=0) > 1 else colors)
    return out


# ---- trimesh -----------------------------------------------------------------------------------

def from_trimesh(tm, name="trimesh.Trimesh"):
    """A Mesh from a trimesh.Trimesh: vertices and faces, with its vertex_attributes and
    face_attributes as point and cell data."""
    _require("trimesh", "python3-trimesh (not in Debian 12: pip install trimesh)")
    point_data = {k: np.asarray(v) for k, v in getattr(tm, "vertex_attributes", {}).items()}
    cell_data = {k: np.asarray(v) for k, v in getattr(tm, "face_attributes", {}).items()}
    mesh = Mesh(np.asarray(tm.vertices), np.asarray(tm.faces), point_data=point_data, cell_data=cell_data, name=name)
    _check(mesh, "from_trimesh")
    return mesh


def to_trimesh(mesh):
    """A trimesh.Trimesh of the Mesh (process=False: trimesh merges no vertices), n-gons
    split into fans; point and cell data as its vertex_attributes and face_attributes."""
    trimesh = _require("trimesh", "python3-trimesh (not in Debian 12: pip install trimesh)")
    _check(mesh, "to_trimesh")
    triangles, face_of = _fan_triangles(mesh)
    return trimesh.Trimesh(vertices=mesh.points, faces=triangles, process=False,
                           vertex_attributes={k: np.asarray(v) for k, v in mesh.point_data.items()},
                           face_attributes={k: np.asarray(v)[face_of] for k, v in mesh.cell_data.items()})


def _check(mesh, what):
    if not isinstance(mesh, Mesh):
        raise Error(f"{what}: expected a subdivkit.Mesh, got {_type_name(mesh)}")
    # What write_mesh refuses, the other library would take and break on later (or at once,
    # as numpy_to_vtk does on a 3-d array): offsets that do not fit the indices, indices out
    # of range, non-finite points, data arrays without one row per point or face.
    _subdivkit._check_mesh(mesh, _data_arrays(mesh.point_data, mesh.point_roles, mesh.n_points, "point data"),
                           _data_arrays(mesh.cell_data, mesh.cell_roles, mesh.n_faces, "cell data"),
                           f"{what}({mesh.name})")
