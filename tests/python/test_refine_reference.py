"""refine() against independent references: the `subdiv` command line's exact OBJ output
(read by a plain-text parser, not by the module), and a NumPy Catmull-Clark step written
from the rules of Catmull & Clark 1978."""
import numpy as np
import pytest

import subdivkit as sk
from conftest import MESHES, parse_obj, run_cli

CASES = [  # mesh, scheme, levels, extra CLI options
    ("cube.obj", "catmull-clark", 3, []),
    ("cube-creased.obj", "catmull-clark", 3, []),
    ("plane-with-hole.obj", "catmull-clark", 2, ["--boundary", "edges"]),
    ("octahedron.obj", "loop", 3, []),
    ("octahedron.obj", "sqrt3", 3, []),
    ("cube.obj", "doo-sabin", 2, []),
]


@pytest.mark.parametrize("mesh_name,scheme,levels,options", CASES)
def test_refine_equals_the_command_line_to_1e_15(tmp_path, mesh_name, scheme, levels, options):
    path = str(MESHES / mesh_name)
    out = tmp_path / "out.obj"
    run_cli("refine", path, "-s", scheme, "-l", levels, "-o", out, "-q", *options)
    expected_points, expected_faces = parse_obj(out)

    boundary = options[1] if options else "edges-and-corners"
    fine = sk.refine(sk.read_mesh(path), scheme, levels, boundary=boundary)

    assert fine.points.shape == expected_points.shape
    assert np.abs(fine.points - expected_points).max() <= 1e-15
    assert [list(f) for f in fine.face_list()] == expected_faces


def catmull_clark_step(points, faces):
    """One Catmull-Clark step on a closed quad-or-polygon mesh, straight from the rules:
    face point = centroid; edge point = (V1 + V2 + F1 + F2)/4; vertex point =
    (n-2)/n V + 1/n^2 sum(ring) + 1/n^2 sum(face points). Returns the new points, unordered."""
    face_points = np.array([points[f].mean(axis=0) for f in faces])
    edge_faces, ring, vertex_faces = {}, {}, {}
    for fi, f in enumerate(faces):
        for a, b in zip(f, np.roll(f, -1)):
            edge_faces.setdefault((min(a, b), max(a, b)), []).append(fi)
            ring.setdefault(a, set()).add(b)
            ring.setdefault(b, set()).add(a)
            vertex_faces.setdefault(a, []).append(fi)
    edge_points = [(points[a] + points[b] + face_points[fs].sum(axis=0)) / 4 for (a, b), fs in edge_faces.items()]
    vertex_points = []
    for v in range(len(points)):
        n = len(ring[v])
        vertex_points.append((n - 2) / n * points[v] + points[sorted(ring[v])].sum(axis=0) / n**2
                             + face_points[vertex_faces[v]].sum(axis=0) / n**2)
    return np.vstack([face_points, np.array(edge_points), np.array(vertex_points)])


def max_distance_to_matching_points(a, b):
    """Largest distance from a point of `a` to its nearest point of `b`, requiring the
    nearest points to be distinct (a one-to-one matching; the orders need not agree)."""
    d = np.linalg.norm(a[:, None, :] - b[None, :, :], axis=2)
    nearest = d.argmin(axis=1)
    assert len(set(nearest)) == len(a), "two points matched the same reference point"
    return d[np.arange(len(a)), nearest].max()


@pytest.mark.parametrize("mesh_name", ["cube.obj", "torus-quads.obj"])
def test_one_catmull_clark_step_equals_the_rules_written_in_numpy(mesh_name):
    mesh = sk.read_mesh(MESHES / mesh_name)
    expected = catmull_clark_step(mesh.points, mesh.face_list())
    fine = sk.refine(mesh, "catmull-clark", 1)
    assert fine.n_points == len(expected)
    assert max_distance_to_matching_points(fine.points, expected) <= 1e-15


def test_all_levels_returns_the_input_first_then_each_level():
    cube = sk.read_mesh(MESHES / "cube.obj")
    levels = sk.refine(cube, "catmull-clark", 3, all_levels=True)
    assert [m.n_faces for m in levels] == [6, 24, 96, 384]  # each quad splits into 4
    assert np.array_equal(levels[0].points, cube.points)
    assert np.array_equal(levels[-1].points, sk.refine(cube, "catmull-clark", 3).points)


def test_results_are_the_same_bits_for_any_thread_count():
    cube = sk.read_mesh(MESHES / "cube.obj")
    one = sk.refine(cube, "catmull-clark", 5, threads=1)
    two = sk.refine(cube, "catmull-clark", 5, threads=2)
    assert np.array_equal(one.points, two.points)


def test_a_sequence_string_runs_each_scheme_for_its_levels(tmp_path):
    path = str(MESHES / "cube.obj")
    out = tmp_path / "seq.obj"
    run_cli("refine", path, "-s", "catmull-clark-shape:1,catmull-clark", "-l", 3, "-o", out, "-q")
    expected, _ = parse_obj(out)
    fine = sk.refine(sk.read_mesh(path), "catmull-clark-shape:1,catmull-clark", 3)
    assert np.abs(fine.points - expected).max() <= 1e-15


def test_params_reach_every_scheme_of_a_sequence_as_with_the_command_line(tmp_path):
    path = str(MESHES / "cube.obj")
    out = tmp_path / "seq.obj"
    run_cli("refine", path, "-s", "catmull-clark-shape:1,catmull-clark", "-l", 3, "-p", "lambda=0.8", "-o", out, "-q")
    expected, _ = parse_obj(out)
    mesh = sk.read_mesh(path)
    fine = sk.refine(mesh, "catmull-clark-shape:1,catmull-clark", 3, params={"lambda": 0.8})
    assert np.abs(fine.points - expected).max() <= 1e-15
    default = sk.refine(mesh, "catmull-clark-shape:1,catmull-clark", 3)
    assert np.abs(default.points - expected).max() > 1e-3  # the parameter did something
    shape = sk.Scheme.load("catmull-clark-shape")
    assert np.array_equal(sk.refine(mesh, shape, 1, params={"lambda": 0.8}).points,
                          sk.refine(mesh, shape.with_params(**{"lambda": 0.8}), 1).points)


def test_point_data_is_refined_like_the_points_and_cell_data_follows_faces():
    cube = sk.read_mesh(MESHES / "cube.obj")
    cube.point_data["xyz"] = cube.points.copy()
    cube.point_data["x"] = cube.points[:, 0].copy()
    cube.cell_data["face_id"] = np.arange(cube.n_faces, dtype=float)
    fine = sk.refine(cube, "catmull-clark", 2, all_levels=True)
    assert np.abs(fine[-1].point_data["xyz"] - fine[-1].points).max() <= 1e-15
    assert fine[-1].point_data["x"].shape == (fine[-1].n_points,)
    # Each face of level 1 lies in one parent face, and each parent face makes 4 children.
    counts = np.bincount(fine[1].cell_data["face_id"].astype(int), minlength=6)
    assert list(counts) == [4] * 6
    assert sorted(np.bincount(fine[2].cell_data["face_id"].astype(int))) == [16] * 6


def test_curve_schemes_refine_polylines_like_the_command_line(tmp_path):
    path = str(MESHES.parent / "curves" / "open-zigzag.obj")
    out = tmp_path / "curve.obj"
    run_cli("refine", path, "-s", "four-point", "-l", 3, "-o", out, "-q")
    expected, _ = parse_obj(out)
    fine = sk.refine(sk.read_mesh(path), "four-point", 3)
    assert fine.n_lines == 1
    assert np.abs(fine.points - expected).max() <= 1e-15
