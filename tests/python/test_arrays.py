"""NumPy arrays in any layout: converted where the meaning is clear, refused where not;
results come back C-contiguous without copies."""
import numpy as np
import pytest

import subdivkit as sk
from conftest import MESHES


@pytest.fixture
def cube():
    return sk.read_mesh(MESHES / "cube.obj")


def reference(cube):
    return sk.refine(cube, "catmull-clark", 2).points


def test_float32_int_fortran_and_strided_points_are_converted(cube):
    expected = reference(cube)
    # The cube's coordinates are +-0.5: exact in float32.
    layouts = {
        "float32": cube.points.astype(np.float32),
        "fortran": np.asfortranarray(cube.points),
        "strided": np.repeat(cube.points, 2, axis=0)[::2],
        "list": cube.points.tolist(),
    }
    for name, points in layouts.items():
        mesh = sk.Mesh(points, cube.faces)
        assert mesh.points.dtype == np.float64 and mesh.points.flags.c_contiguous, name
        assert np.array_equal(sk.refine(mesh, "catmull-clark", 2).points, expected), name
    doubled = sk.Mesh((2 * cube.points).astype(np.int64), cube.faces)
    assert np.array_equal(sk.refine(doubled, "catmull-clark", 2).points, 2 * expected)


def test_faces_in_every_accepted_form_give_the_same_mesh(cube):
    expected = reference(cube)
    forms = {
        "int64 (m, k)": cube.faces.astype(np.int64),
        "uint16 (m, k)": cube.faces.astype(np.uint16),
        "fortran (m, k)": np.asfortranarray(cube.faces),
        "lists": cube.faces.tolist(),
    }
    for name, faces in forms.items():
        assert np.array_equal(sk.refine(sk.Mesh(cube.points, faces), "catmull-clark", 2).points, expected), name
    flat = sk.Mesh(cube.points, cube.face_indices.astype(np.int64), face_offsets=np.arange(0, 25, 4))
    assert np.array_equal(sk.refine(flat, "catmull-clark", 2).points, expected)


def test_meaningless_arrays_are_refused_with_a_reason(cube):
    with pytest.raises(sk.Error, match="integer indices.*float64"):
        sk.Mesh(cube.points, cube.faces.astype(float))
    with pytest.raises(sk.Error, match=r"shape \(n, 3\)"):
        sk.Mesh(cube.points[:, :2], cube.faces)
    with pytest.raises(sk.Error, match="expected numbers"):
        sk.Mesh(np.array([["a", "b", "c"]]), [])
    with pytest.raises(sk.Error, match="out of range"):
        sk.Mesh(cube.points, cube.faces - 1)
    with pytest.raises(sk.Error, match="face_offsets"):
        sk.Mesh(cube.points, cube.face_indices, face_offsets=[0, 4, 3])
    with pytest.raises(sk.Error, match="one value per entry"):
        sk.Mesh(cube.points, cube.faces, creases=[[0, 1]], crease_sharpness=[1, 2])
    cube.point_data["bad"] = np.zeros(3)
    with pytest.raises(sk.Error, match="point data 'bad'"):
        sk.refine(cube, "catmull-clark", 1)


def test_mixed_faces_have_csr_arrays_but_no_rectangular_view():
    points = [[0, 0, 0], [1, 0, 0], [2, 0, 0], [0, 1, 0], [1, 1, 0]]
    mesh = sk.Mesh(points, [[0, 1, 4, 3], [1, 2, 4]])
    assert list(mesh.face_offsets) == [0, 4, 7]
    assert list(mesh.face_sizes) == [4, 3]
    assert [list(f) for f in mesh.face_list()] == [[0, 1, 4, 3], [1, 2, 4]]
    with pytest.raises(sk.Error, match="face_indices and face_offsets"):
        mesh.faces
    fine = sk.refine(mesh, "catmull-clark", 1)
    assert fine.faces.shape == (7, 4)  # Catmull-Clark makes quads of anything


def test_results_are_contiguous_views_without_copies(cube):
    fine = sk.refine(cube, "catmull-clark", 2)
    assert fine.points.dtype == np.float64 and fine.points.flags.c_contiguous
    assert fine.face_indices.dtype == np.int32
    assert np.shares_memory(fine.faces, fine.face_indices)  # (m, k) is a view


def test_stencils_accept_any_layout_of_positions(cube):
    S = sk.stencils(cube, "catmull-clark", 2, composed=True)
    assert np.abs(S @ np.asfortranarray(cube.points) - reference(cube)).max() <= 1e-14
    assert np.abs(S @ cube.points.astype(np.float32) - reference(cube)).max() <= 1e-7


def test_described_arrays_count_vertex_edge_and_face_points():
    """arrays="all" (as --arrays all): one Catmull-Clark step makes a point per vertex (origin
    0), edge (1) and face (2) of the cube; a face point's valence is its face's size (4), an
    edge point's 4, a kept vertex keeps its valence (3); each child face's parent_face and
    base_face is the cube face it lies in, four children each."""
    cube = sk.read_mesh(str(MESHES / "cube.obj"))
    one = sk.refine(cube, "catmull-clark", 1, arrays="all")
    origin, valence = one.point_data["origin"], one.point_data["valence"]
    assert [int((origin == k).sum()) for k in (0, 1, 2)] == [8, 12, 6]
    assert set(valence[origin == 0]) == {3} and set(valence[origin > 0]) == {4}
    assert np.array_equal(one.point_data["level"], np.ones(one.n_points))
    assert np.array_equal(np.bincount(one.cell_data["parent_face"].astype(int)), [4] * 6)
    two = sk.refine(cube, "catmull-clark", 2, arrays="base_face")
    assert set(two.point_data) == set() and set(two.cell_data) == {"base_face"}
    assert np.array_equal(np.bincount(two.cell_data["base_face"].astype(int)), [16] * 6)
    with pytest.raises(sk.Error, match="unknown array 'origins'"):
        sk.refine(cube, "catmull-clark", 1, arrays="origins")
