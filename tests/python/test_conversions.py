"""Meshes to and from VTK (and so PyVista), Open3D and trimesh (subdivkit.conversions).
Each round trip keeps what the other library can hold; the other library's own view of
the result is checked with its own functions (VTK's cell counts and its area filter,
Open3D's watertightness and Euler characteristic), and a fan split keeps the area."""
import importlib.util

import numpy as np
import pytest

import subdivkit as sk
from conftest import MESHES

HAS_VTK = importlib.util.find_spec("vtkmodules") is not None
HAS_OPEN3D = importlib.util.find_spec("open3d") is not None
HAS_TRIMESH = importlib.util.find_spec("trimesh") is not None


def polygon_area(mesh):
    """Sum of the faces' vector areas' lengths (planar faces)."""
    total = 0.0
    for face in mesh.face_list():
        p = mesh.points[face]
        total += 0.5 * np.linalg.norm(np.cross(p - p[0], np.roll(p, -1, axis=0) - p[0]).sum(axis=0))
    return total


def mixed_mesh():
    """Quads, a triangle and a pentagon, with point and cell data of both kinds."""
    points = np.array([[0, 0, 0], [1, 0, 0], [2, 0, 0], [0, 1, 0], [1, 1, 0], [2, 1, 0], [3, 0.5, 0], [1, 2, 0],
                       [0.5, 2.5, 0]], dtype=float)
    faces = [[0, 1, 4, 3], [1, 2, 5, 4], [2, 6, 5], [3, 4, 5, 7, 8]]
    return sk.Mesh(points, faces, point_data={"height": points[:, 0] * 2.0, "uv": points[:, :2].copy(),
                                              "label": np.arange(9, dtype=np.int32)},
                   cell_data={"face_id": np.arange(4, dtype=np.int32), "weight": np.array([0.5, 1.5, 2.5, 3.5])},
                   point_roles={"uv": "texture_coordinates"})


@pytest.mark.skipif(not HAS_VTK, reason="python3-vtk9 is not installed")
def test_vtk_round_trip_keeps_points_polygons_lines_and_arrays():
    from vtkmodules.vtkFiltersVerdict import vtkCellSizeFilter
    mesh = mixed_mesh()
    mesh.line_indices, mesh.line_offsets = np.array([0, 3, 8], dtype=np.int32), np.array([0, 3], dtype=np.int32)
    poly = sk.to_vtk(mesh)
    assert (poly.GetNumberOfPoints(), poly.GetNumberOfPolys(), poly.GetNumberOfLines()) == (9, 4, 1)
    assert poly.GetPointData().GetTCoords().GetName() == "uv"
    # VTK's own measure of the polygons agrees with ours.
    sizes = vtkCellSizeFilter()
    sizes.SetInputData(poly)
    sizes.Update()
    from vtkmodules.util.numpy_support import vtk_to_numpy
    vtk_area = vtk_to_numpy(sizes.GetOutput().GetCellData().GetArray("Area"))[1:].sum()  # the line comes first
    assert vtk_area == pytest.approx(polygon_area(mesh), rel=1e-12)

    back = sk.from_vtk(poly)
    assert np.array_equal(back.points, mesh.points)
    assert [list(f) for f in back.face_list()] == [list(f) for f in mesh.face_list()]
    assert [list(line) for line in back.line_list()] == [[0, 3, 8]]
    assert np.array_equal(back.point_data["height"], mesh.point_data["height"])
    assert np.array_equal(back.point_data["label"], mesh.point_data["label"])
    assert back.point_roles["uv"] == "texture_coordinates"
    # The line's cell-data row is VTK's first; the faces' rows come back in order.
    assert np.array_equal(back.cell_data["face_id"], mesh.cell_data["face_id"])
    assert np.array_equal(back.cell_data["weight"], mesh.cell_data["weight"])


@pytest.mark.skipif(not HAS_VTK, reason="python3-vtk9 is not installed")
def test_a_vtk_source_refines_and_strips_are_refused():
    from vtkmodules.vtkFiltersSources import vtkCubeSource
    from vtkmodules.vtkFiltersCore import vtkCleanPolyData, vtkStripper, vtkTriangleFilter
    cube = vtkCubeSource()
    clean = vtkCleanPolyData()  # vtkCubeSource repeats corners per face (its normals differ)
    clean.SetInputConnection(cube.GetOutputPort())
    clean.Update()
    mesh = sk.from_vtk(clean.GetOutput())
    assert (mesh.n_points, mesh.n_faces) == (8, 6)
    with pytest.warns(UserWarning, match="'Normals' hold"):  # VTK's normals keep their role
        fine = sk.refine(mesh, "catmull-clark", 2)
    assert (fine.n_points, fine.n_faces) == (98, 96)  # V - E + F = 2 at every level

    strips = vtkTriangleFilter()
    strips.SetInputConnection(cube.GetOutputPort())
    strips.Update()
    stripper = vtkStripper()
    stripper.SetInputData(strips.GetOutput())
    stripper.Update()
    with pytest.raises(sk.Error, match="triangle strip.*vtkTriangleFilter"):
        sk.from_vtk(stripper.GetOutput())
    with pytest.raises(sk.Error, match="expected a vtkPolyData"):
        sk.from_vtk(np.zeros(3))


@pytest.mark.skipif(not HAS_OPEN3D, reason="python3-open3d is not installed")
def test_open3d_round_trip_splits_ngons_into_fans_and_keeps_the_surface():
    import open3d as o3d
    mesh = mixed_mesh()
    tm = sk.to_open3d(mesh)
    assert len(tm.triangles) == 2 + 2 + 1 + 3  # a k-gon makes k - 2 triangles
    assert tm.get_surface_area() == pytest.approx(polygon_area(mesh), rel=1e-12)

    cube = sk.read_mesh(str(MESHES / "cube.obj"))
    fine = sk.refine(cube, "catmull-clark", 2)
    closed = sk.to_open3d(fine)
    assert closed.is_watertight()
    assert closed.is_orientable()
    triangles = np.asarray(closed.triangles)
    edges = np.unique(np.sort(np.vstack([triangles[:, [0, 1]], triangles[:, [1, 2]], triangles[:, [2, 0]]]), axis=1),
                      axis=0)
    assert len(closed.vertices) - len(edges) + len(triangles) == 2  # a sphere's Euler characteristic

    box = o3d.geometry.TriangleMesh.create_box()
    box.compute_vertex_normals()
    back = sk.from_open3d(box)
    assert back.n_faces == 12
    assert back.point_roles["normal"] == "normals"
    assert np.allclose(np.linalg.norm(back.point_data["normal"], axis=1), 1)
    with pytest.warns(UserWarning, match="'normal' hold"):
        smooth = sk.refine(back, "loop", 1)
    assert smooth.n_faces == 48
    with pytest.raises(sk.Error, match="expected an open3d.geometry.TriangleMesh"):
        sk.from_open3d(mesh)


def test_trimesh_conversion_says_how_to_get_trimesh_when_it_is_missing():
    if HAS_TRIMESH:
        import trimesh
        tm = sk.to_trimesh(mixed_mesh())
        assert tm.area == pytest.approx(polygon_area(mixed_mesh()), rel=1e-12)
        assert np.array_equal(tm.face_attributes["face_id"], [0, 0, 1, 1, 2, 3, 3, 3])
        back = sk.from_trimesh(trimesh.creation.box())
        assert (back.n_points, back.n_faces) == (8, 12)
    else:
        with pytest.raises(ImportError, match="trimesh"):
            sk.to_trimesh(mixed_mesh())


@pytest.mark.skipif(not HAS_VTK, reason="python3-vtk9 is not installed")
def test_vtk_conversions_refuse_what_write_mesh_refuses_with_escaped_names():
    """Found by test_fuzz_conversions.py: to_vtk passed a 3-d point array to VTK (an
    AssertionError from numpy_to_vtk), from_vtk returned infinite points and indices past the
    last point, and a name's ESC reached the message raw."""
    from vtkmodules.util.numpy_support import numpy_to_vtk
    from vtkmodules.vtkCommonCore import vtkPoints
    from vtkmodules.vtkCommonDataModel import vtkPolyData
    mesh = mixed_mesh()
    mesh.point_data["block"] = np.zeros((9, 2, 2))
    with pytest.raises(sk.Error, match="point data 'block': expected 9 rows"):
        sk.to_vtk(mesh)
    poly = sk.to_vtk(mixed_mesh())
    points = vtkPoints()
    points.SetData(numpy_to_vtk(np.full((9, 3), np.inf), deep=True))
    poly.SetPoints(points)
    with pytest.raises(sk.Error, match=r"in\\x1bfinite: vertex 0 has a non-finite coordinate") as e:
        sk.from_vtk(poly, name="in\x1bfinite")
    assert "\x1b" not in str(e.value)
    cut = vtkPolyData()
    cut.SetPoints(sk.to_vtk(mixed_mesh()).GetPoints())
    cut.SetPolys(sk.to_vtk(sk.Mesh(np.zeros((12, 3)), [[0, 1, 11]])).GetPolys())
    with pytest.raises(sk.Error, match="11"):
        sk.from_vtk(cut)
