"""The seeded fuzz test of test_fuzz_api.py, extended to what came later (issue 33): the
conversions to and from VTK and Open3D (subdivkit.conversions) and refine_adaptive. Spoiled
meshes (test_fuzz_api.spoil), foreign objects built with wrong indices, NaN points, odd
array names (a NUL, an ESC) and dtypes, and wrong arguments: every case must work (and then
give finite numbers, and a round trip the same mesh) or raise subdivkit.Error, TypeError or
ValueError, with a message that holds no raw control byte. Each library's cases run where
it is installed (python3-vtk9, python3-open3d); refine_adaptive's always.
"""
import importlib.util
import random
import time

import numpy as np
import pytest

import subdivkit as sk
from test_fuzz_api import ALLOWED, SPECIAL, finite, fresh_mesh, random_array, random_value, spoil

SEED = 3301  # any fixed value: the cases replay exactly
CASES = 600
TIME_LIMIT = 90.0  # seconds, a guard against a hang

HAS_VTK = importlib.util.find_spec("vtkmodules") is not None
HAS_OPEN3D = importlib.util.find_spec("open3d") is not None

NAMES = ["a", "t\x00x", "e\x1b[2J", "", "\x9b31m", "normal", "color"]


def clean_message(e):
    text = str(e)
    return not any(ord(c) < 0x20 and c not in "\n\t" or 0x7F <= ord(c) <= 0x9F for c in text)


# ---- refine_adaptive ---------------------------------------------------------------------------

def adaptive_case(rng, mesh):
    def sometimes(valid, spoiled, p=0.15):  # a valid value mostly, so that the work is reached
        return rng.choice(spoiled) if rng.random() < p else rng.choice(valid)

    scheme = sometimes(["catmull-clark", "catmull-clark", "loop", "bilinear"], ["sqrt3", "no-such-scheme", 7, None])
    levels = sometimes([0, 1, 2, 3, np.int64(2)], [-1, 13, 2.5, "1", True, 10**9], 0.2)
    kwargs = {}
    if rng.random() < 0.3:
        kwargs["tolerance"] = sometimes([0.0, 0.01, 0.3, 5e-324, 1e308], SPECIAL + ["x", None])
    if rng.random() < 0.3:
        kwargs["limit"] = sometimes([True, False], ["yes", None])
    if rng.random() < 0.2:
        kwargs["boundary"] = sometimes(["edges-and-corners", "edges"], ["none", "bad\x1b", 3])
    if rng.random() < 0.2:
        kwargs["crease_method"] = sometimes(["uniform", "chaikin"], ["bad\x00", None])
    if rng.random() < 0.2:
        kwargs["feature_angle"] = sometimes([-1.0, 0.0, 30.0, 180.0], SPECIAL + ["x"])
    if rng.random() < 0.1:
        kwargs["params"] = rng.choice([{}, {"w": 0.1}, {"nope": 1}, {"\x1b": "\x00"}, [1], "x"])
    if rng.random() < 0.1:
        kwargs["threads"] = rng.choice([0, 1, 2, -1, 10**6, "2"])
    out, info = sk.refine_adaptive(mesh, scheme, levels, info=True, **kwargs)
    # Every face comes from a base face, at a level no finer than asked.
    assert np.all((out.cell_data["base_face"] >= 0) & (out.cell_data["base_face"] < mesh.n_faces))
    assert np.all(out.cell_data["face_level"] <= int(levels))
    assert sum(info.split_faces) >= 0
    return [out.points]


# ---- VTK ---------------------------------------------------------------------------------------

def spoiled_polydata(rng):
    """A vtkPolyData with random points, cells (indices out of range, negative, empty cells)
    and arrays (odd names, types, sizes)."""
    from vtkmodules.util.numpy_support import numpy_to_vtk, numpy_to_vtkIdTypeArray
    from vtkmodules.vtkCommonCore import vtkPoints
    from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData
    poly = vtkPolyData()
    n = rng.choice([0, 1, 4, 9])
    if rng.random() < 0.9:
        pts = vtkPoints()
        xyz = np.array([[rng.choice(SPECIAL) if rng.random() < 0.1 else rng.uniform(-2, 2) for _ in range(3)]
                        for _ in range(n)], dtype=float).reshape(-1, 3)
        pts.SetData(numpy_to_vtk(xyz, deep=True))
        poly.SetPoints(pts)

    def cells(count):
        sizes = [rng.choice([0, 1, 2, 3, 4, 5]) for _ in range(count)]
        offsets = np.concatenate([[0], np.cumsum(sizes)]).astype(np.int64)
        conn = np.array([rng.choice([0, 1, 2, 3, n - 1, n, -1, 2**40]) if rng.random() < 0.15
                         else rng.randrange(max(n, 1)) for _ in range(int(offsets[-1]))], dtype=np.int64)
        a = vtkCellArray()
        a.SetData(numpy_to_vtkIdTypeArray(offsets, deep=True), numpy_to_vtkIdTypeArray(conn, deep=True))
        return a

    poly.SetPolys(cells(rng.choice([0, 1, 3, 6])))
    if rng.random() < 0.3:
        poly.SetLines(cells(rng.choice([1, 2])))
    if rng.random() < 0.05:
        poly.SetVerts(cells(1))
    for attributes, rows in ((poly.GetPointData(), n), (poly.GetCellData(), poly.GetNumberOfCells())):
        for _ in range(rng.randrange(0, 3)):
            values = np.asarray(random_array(rng))
            if values.dtype.kind not in "fiu" or values.size == 0:
                continue
            if values.ndim > 2:  # VTK holds tuples: a 3-d array cannot be one
                values = values.reshape(len(values), -1)
            if rng.random() < 0.7 and values.size >= rows > 0:
                values = values.reshape(-1)[:rows * (values.size // rows)].reshape(rows, -1)
            array = numpy_to_vtk(np.ascontiguousarray(values), deep=True)
            array.SetName(rng.choice(NAMES))
            attributes.AddArray(array)
    return poly


def vtk_case(rng, mesh):
    if rng.random() < 0.5:
        back = sk.from_vtk(sk.to_vtk(mesh))
        assert np.array_equal(back.points, mesh.points), "to_vtk / from_vtk moved the points"
        assert [list(f) for f in back.face_list()] == [list(f) for f in mesh.face_list()]
        return [back.points]
    polydata = spoiled_polydata(rng) if rng.random() < 0.9 else rng.choice([None, 3, "x", mesh])
    got = sk.from_vtk(polydata, name=rng.choice(["p", "n\x00m", "e\x1b"]))
    return [sk.refine(got, "catmull-clark", 1).points] if got.n_faces else [got.points]


# ---- Open3D ------------------------------------------------------------------------------------

def open3d_case(rng, mesh):
    import open3d as o3d
    if rng.random() < 0.5:
        if rng.random() < 0.3:
            mesh.point_data["c"], mesh.point_roles["c"] = random_value(rng), rng.choice(["color", "normals"])
        tm = sk.to_open3d(mesh)
        assert np.array_equal(np.asarray(tm.vertices), mesh.points)
        back = sk.from_open3d(tm)
        return [back.points]
    n = rng.choice([0, 1, 4, 8])
    tm = o3d.geometry.TriangleMesh()
    tm.vertices = o3d.utility.Vector3dVector(np.array([[rng.choice(SPECIAL) if rng.random() < 0.1 else
                                                        rng.uniform(-1, 1) for _ in range(3)] for _ in range(n)],
                                                      dtype=float).reshape(-1, 3))
    tris = np.array([[rng.choice([0, 1, n - 1, n, -1, 2**31 - 1]) if rng.random() < 0.15 else rng.randrange(max(n, 1))
                      for _ in range(3)] for _ in range(rng.choice([0, 1, 4]))], dtype=np.int32).reshape(-1, 3)
    tm.triangles = o3d.utility.Vector3iVector(tris)
    if rng.random() < 0.3 and n:
        tm.vertex_colors = o3d.utility.Vector3dVector(np.full((n, 3), rng.choice(SPECIAL)))
    got = sk.from_open3d(tm if rng.random() < 0.9 else rng.choice([None, mesh, "x"]))
    return [sk.refine(got, "loop", 1).points] if got.n_faces else [got.points]


def test_conversions_and_adaptive_refinement_raise_clear_errors_or_give_finite_results():
    rng = random.Random(SEED)
    kinds = [adaptive_case] + ([vtk_case] if HAS_VTK else []) + ([open3d_case] if HAS_OPEN3D else [])
    start = time.monotonic()
    outcomes = {k.__name__: {"ok": 0, "refused": 0} for k in kinds}
    for case in range(CASES):
        assert time.monotonic() - start < TIME_LIMIT, f"case {case}: the fuzz test ran past {TIME_LIMIT} s"
        kind = rng.choice(kinds)
        mesh = fresh_mesh(rng)
        try:
            for _ in range(rng.randrange(0, 3)):
                spoil(rng, mesh)
            results = kind(rng, mesh)
        except ALLOWED as e:
            outcomes[kind.__name__]["refused"] += 1
            assert str(e) or isinstance(e, TypeError), f"case {case}: an empty message ({type(e).__name__})"
            assert clean_message(e), f"case {case}: a raw control byte in the message {str(e)!r}"
            continue
        except Exception as e:  # noqa: BLE001 - the finding: an exception of another type
            pytest.fail(f"case {case} (seed {SEED}, {kind.__name__}): {type(e).__name__}: {e}")
        outcomes[kind.__name__]["ok"] += 1
        assert finite(results), f"case {case} (seed {SEED}, {kind.__name__}): a result holds NaN or infinity"
    for name, o in outcomes.items():  # both outcomes must occur, or the generator tests nothing
        assert o["ok"] > 10 and o["refused"] > 10, (name, outcomes)
