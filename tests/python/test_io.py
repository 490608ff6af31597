"""read_mesh / write_mesh round trips, tags, and data arrays in .vtp files."""
import warnings

import numpy as np
import pytest

import subdivkit as sk
from conftest import MESHES, parse_obj


def test_obj_round_trip_is_exact_with_creases_and_corners(tmp_path):
    mesh = sk.read_mesh(MESHES / "cube.obj")
    rng = np.random.default_rng(7)
    tagged = sk.Mesh(mesh.points + rng.standard_normal(mesh.points.shape) * 1e-3, mesh.faces,
                     creases=[[0, 1], [1, 2]], crease_sharpness=[2.5, 10], corners=[5], corner_sharpness=3)
    path = tmp_path / "tagged.obj"
    sk.write_mesh(path, tagged)
    back = sk.read_mesh(path)
    assert np.array_equal(back.points, tagged.points)  # OBJ is written with exact doubles
    assert np.array_equal(back.faces, tagged.faces)
    assert {tuple(sorted(c)) for c in back.creases} == {(0, 1), (1, 2)}
    assert sorted(back.crease_sharpness) == [2.5, 10]
    assert list(back.corners) == [5] and list(back.corner_sharpness) == [3]
    points, faces = parse_obj(path)  # and an independent reader agrees
    assert np.array_equal(points, tagged.points)


def test_refined_creases_keep_their_decayed_sharpness():
    mesh = sk.read_mesh(MESHES / "cube.obj")
    creased = sk.Mesh(mesh.points, mesh.faces, creases=[mesh.faces[0][:2]], crease_sharpness=2)
    one = sk.refine(creased, "catmull-clark", 1)
    assert len(one.creases) == 2 and np.allclose(one.crease_sharpness, 1)  # split in two, sharpness - 1


@pytest.mark.parametrize("extension", [".off", ".ply", ".vtp"])
def test_other_formats_round_trip(tmp_path, extension):
    mesh = sk.refine(sk.read_mesh(MESHES / "cube.obj"), "catmull-clark", 1)
    path = tmp_path / f"mesh{extension}"
    sk.write_mesh(path, mesh)
    back = sk.read_mesh(path)
    assert np.array_equal(back.points, mesh.points)
    assert np.array_equal(back.faces, mesh.faces)


def test_point_and_cell_data_go_to_vtp_and_warn_elsewhere(tmp_path):
    mesh = sk.read_mesh(MESHES / "cube.obj")
    mesh.point_data["height"] = mesh.points[:, 2].copy()
    mesh.cell_data["id"] = np.arange(6.0)
    sk.write_mesh(tmp_path / "data.vtp", mesh)
    text = (tmp_path / "data.vtp").read_bytes()
    assert b'Name="height"' in text and b'Name="id"' in text
    with pytest.warns(UserWarning, match="no place for point or cell data 'height', 'id'"):
        sk.write_mesh(tmp_path / "data.obj", mesh)


@pytest.mark.parametrize("extension", [".vtp", ".ply"])
def test_point_and_cell_data_come_back_from_the_file(tmp_path, extension):
    mesh = sk.read_mesh(MESHES / "cube.obj")
    mesh.point_data["height"] = mesh.points[:, 2].copy()
    mesh.point_data["seven"] = np.arange(8 * 7, dtype=float).reshape(8, 7)
    mesh.cell_data["id"] = np.arange(6.0)
    sk.write_mesh(tmp_path / f"data{extension}", mesh)
    back = sk.read_mesh(tmp_path / f"data{extension}")
    assert np.array_equal(back.point_data["height"].reshape(-1), mesh.points[:, 2])
    assert np.array_equal(back.point_data["seven"], mesh.point_data["seven"])
    assert np.array_equal(back.cell_data["id"].reshape(-1), np.arange(6.0))
    # Read data refines like any other: the height of a refined cube is its z coordinate.
    refined = sk.refine(back, "catmull-clark", 2)
    assert np.allclose(refined.point_data["height"].reshape(-1), refined.points[:, 2], atol=1e-14)


def test_writing_refuses_before_creating_anything(tmp_path):
    mesh = sk.read_mesh(MESHES / "cube.obj")
    with pytest.raises(sk.Error, match="unknown|extension|format"):
        sk.write_mesh(tmp_path / "mesh.xyz", mesh)
    with pytest.raises(sk.Error):
        sk.write_mesh(tmp_path / "missing-dir" / "mesh.obj", mesh)
    assert list(tmp_path.iterdir()) == []


def test_polylines_are_read_as_lines():
    curve = sk.read_mesh(MESHES.parent / "curves" / "two-strokes.obj")
    assert curve.n_faces == 0 and curve.n_lines == 3  # three 'l' records
    assert len(curve.line_list()) == 3


def test_face_varying_uvs_come_from_obj_and_refine_with_their_seam(tmp_path):
    tube = sk.read_mesh(MESHES / "textured-tube.obj")
    assert set(tube.face_varying) == {"uv"}
    uv, index = tube.face_varying["uv"]
    assert uv.shape == (36, 2) and index.shape == (tube.n_faces * 4,)  # 9 columns of vt: the seam twice
    fine = sk.refine(tube, "catmull-clark", 2)
    fine_uv, fine_index = fine.face_varying["uv"]
    assert fine_index.shape == (fine.n_faces * 4,)
    # The seam stays: the vertices where u wraps have two values, one at u = 0 and one at u = 1.
    corners = fine.face_indices
    seam = [v for v in np.unique(corners) if len(np.unique(fine_uv[fine_index[corners == v]][:, 0].round(12))) > 1]
    assert len(seam) == 4 * 3 + 1  # the seam column's vertices after two levels
    # "all" (the default) is linear in every face: the UVs of the rows stay at v = k/12.
    assert np.allclose(np.unique(fine_uv[:, 1].round(12)), np.arange(13) / 12)
    sk.write_mesh(tmp_path / "tube.obj", fine)
    back = sk.read_mesh(tmp_path / "tube.obj")
    assert np.array_equal(back.face_varying["uv"][1], fine_index)
    assert np.allclose(back.face_varying["uv"][0], fine_uv)
    with pytest.raises(sk.Error, match="fvar_boundary='sideways'"):
        sk.refine(tube, "catmull-clark", 1, fvar_boundary="sideways")
    with pytest.raises(sk.Error, match="corner indices"):
        sk.refine(sk.Mesh(tube.points, tube.faces, face_varying={"uv": (uv, index[:-1])}), "catmull-clark", 1)
