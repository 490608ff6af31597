"""Point and cell arrays keep their role (normals, texture coordinates, colours) and integer
arrays stay integers, through read_mesh, refine and write_mesh, as in the C++ library and
the `subdiv` command line (framework/io/mesh_data.h ArrayRole, framework/primvar)."""
import warnings

import numpy as np
import pytest

import subdivkit as sk
from conftest import MESHES, run_cli


def cube_with_arrays():
    cube = sk.read_mesh(MESHES / "cube.obj")
    p = cube.points
    cube.point_data["height"] = p[:, 2].copy()
    cube.point_data["label"] = np.array([3, 3, 3, 3, 7, 7, 7, 9], dtype=np.int64)
    centred = p - p.mean(axis=0)
    cube.point_data["normal"] = centred / np.linalg.norm(centred, axis=1, keepdims=True)
    cube.point_data["uv"] = p[:, :2].copy()
    cube.point_data["color"] = np.tile(np.array([[255, 128, 0]], dtype=np.uint8), (8, 1))
    cube.point_roles = {"normal": "normals", "uv": "texture_coordinates", "color": "color"}
    cube.cell_data["material"] = np.arange(6, dtype=np.int32)
    cube.cell_data["area"] = np.ones(6)
    return cube


@pytest.mark.parametrize("extension", [".vtp", ".ply"])
def test_roles_and_integer_arrays_survive_a_file(tmp_path, extension):
    cube = cube_with_arrays()
    sk.write_mesh(tmp_path / f"cube{extension}", cube)
    back = sk.read_mesh(tmp_path / f"cube{extension}")
    assert back.point_roles == cube.point_roles
    for name in ("label", "color"):
        assert back.point_data[name].dtype == np.int32, name
        assert np.array_equal(back.point_data[name].reshape(8, -1), np.asarray(cube.point_data[name]).reshape(8, -1))
    assert back.cell_data["material"].dtype == np.int32
    assert np.array_equal(back.cell_data["material"].reshape(-1), np.arange(6))
    assert back.point_data["height"].dtype == np.float64 and back.cell_data["area"].dtype == np.float64
    assert np.allclose(back.point_data["normal"], cube.point_data["normal"], atol=1e-12)


def test_refine_takes_labels_by_origin_and_leaves_normals_out_with_a_warning():
    cube = cube_with_arrays()
    with pytest.warns(UserWarning, match="'normal'.*normals, which refinement does not carry"):
        fine = sk.refine(cube, "catmull-clark", 2, all_levels=True)
    for level in fine[1:]:
        assert "normal" not in level.point_data
        assert level.point_roles == {"uv": "texture_coordinates", "color": "color"}
        label = level.point_data["label"]
        assert label.dtype == np.int32
        # Labels are never averaged: every value is one of the input's.
        assert set(np.unique(label)) <= {3, 7, 9}
        # Float data is refined like the points: an affine function of them stays that function.
        assert np.allclose(level.point_data["height"], level.points[:, 2], atol=1e-13)
        assert np.allclose(level.point_data["uv"], level.points[:, :2], atol=1e-13)
        assert level.cell_data["material"].dtype == np.int32
    # Old vertices keep their labels (vertex points come first in the child numbering).
    assert np.array_equal(fine[1].point_data["label"][:8], cube.point_data["label"])
    # A constant colour stays that colour, as integers.
    assert np.array_equal(np.unique(fine[2].point_data["color"], axis=0), [[255, 128, 0]])


def test_refine_gives_what_the_command_line_gives(tmp_path):
    cube = cube_with_arrays()
    sk.write_mesh(tmp_path / "cube.vtp", cube)
    run_cli("refine", tmp_path / "cube.vtp", "--scheme", "doo-sabin", "-l", "2", "-o", tmp_path / "cli.vtp",
            "--quiet")
    cli = sk.read_mesh(tmp_path / "cli.vtp")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # the normals note
        ours = sk.refine(sk.read_mesh(tmp_path / "cube.vtp"), "doo-sabin", 2)
    assert np.allclose(ours.points, cli.points, atol=1e-12)
    assert np.array_equal(ours.face_indices, cli.face_indices)
    for name in ("height", "label", "uv", "color"):
        assert ours.point_data[name].dtype == cli.point_data[name].dtype, name
        assert np.allclose(ours.point_data[name], cli.point_data[name], atol=1e-12), name
    assert "normal" not in ours.point_data and "normal" not in cli.point_data
    assert ours.point_roles == cli.point_roles
    # Cell data: the dual split's vertex and edge faces take their first corner's face value.
    for name in ("material", "area"):
        assert np.array_equal(ours.cell_data[name], cli.cell_data[name]), name
    assert -1 not in ours.cell_data["material"]


def test_formats_keep_what_their_roles_allow(tmp_path):
    cube = cube_with_arrays()
    # OBJ keeps the per-point texture coordinates (as vt) and says what it leaves out.
    with pytest.warns(UserWarning) as caught:
        sk.write_mesh(tmp_path / "cube.obj", cube)
    message = str(caught[0].message)
    assert "'height'" in message and "'label'" in message and "'uv'" not in message
    back = sk.read_mesh(tmp_path / "cube.obj")
    uv, index = back.face_varying["uv"]
    assert np.allclose(uv[index], cube.points[cube.face_indices, :2])
    # OFF keeps normals, colours and texture coordinates.
    with pytest.warns(UserWarning) as caught:
        sk.write_mesh(tmp_path / "cube.off", cube)
    message = str(caught[0].message)
    assert "'normal'" not in message and "'color'" not in message and "'uv'" not in message
    off = sk.read_mesh(tmp_path / "cube.off")
    assert off.point_roles == cube.point_roles


def test_bad_roles_and_integers_are_refused():
    cube = sk.read_mesh(MESHES / "cube.obj")
    cube.point_data["n"] = cube.points.copy()
    cube.point_roles = {"n": "normal-ish"}
    with pytest.raises(sk.Error, match="role 'normal-ish' is not one of data, normals, texture_coordinates, color"):
        sk.refine(cube, "catmull-clark", 1)
    cube.point_roles = {}
    cube.point_data["big"] = np.full(8, 2**40, dtype=np.int64)
    with pytest.raises(sk.Error, match="'big': integer values must fit in 32 bits"):
        sk.refine(cube, "catmull-clark", 1)


def triangulated(quads):
    """Each quad cut along its first diagonal, with its UV corners."""
    uv, index = quads.face_varying["uv"]
    corners = quads.faces
    uv_corners = index.reshape(-1, 4)
    cut = [0, 1, 2, 0, 2, 3]
    return sk.Mesh(quads.points, corners[:, cut].reshape(-1, 3),
                   face_varying={"uv": (uv, uv_corners[:, cut].reshape(-1))})


def test_face_varying_uvs_through_sqrt3_and_mid_edge():
    # Every split carries UVs with seams (docs/primvars.md, "Which splits"). The tube's UVs
    # are bilinear in each face, the default mode "all" is linear, mid-edge points are edge
    # midpoints and sqrt3's face points centroids: every value stays in the unit square, and
    # the seam (u = 0 beside u = 1) stays at the old vertices.
    tube = sk.read_mesh(MESHES / "textured-tube.obj")
    for scheme, mesh in (("mid-edge", tube), ("sqrt3", triangulated(tube))):
        fine = sk.refine(mesh, scheme, 2)
        uv, index = fine.face_varying["uv"]
        assert index.shape == (len(fine.face_indices),) and index.max() < len(uv)
        assert uv.min() >= -1e-12 and uv.max() <= 1 + 1e-12
    fine = sk.refine(triangulated(tube), "sqrt3", 1)
    uv, index = fine.face_varying["uv"]
    u_at = {}
    for v, u in zip(fine.face_indices, uv[index, 0]):
        u_at.setdefault(v, set()).add(round(u, 12))
    assert any({0.0, 1.0} <= us for us in u_at.values())
