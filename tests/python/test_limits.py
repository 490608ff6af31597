"""limit_positions() and interpolate() against closed forms and against each other."""
import numpy as np
import pytest

import subdivkit as sk
from conftest import CURVES, MESHES, parse_obj, run_cli


def neighbours(mesh):
    """Per vertex: edge neighbours and, for quads, the diagonal (face-opposite) vertices."""
    edges = [set() for _ in range(mesh.n_points)]
    diagonals = [[] for _ in range(mesh.n_points)]
    for f in mesh.face_list():
        k = len(f)
        for i, v in enumerate(f):
            edges[v].update((f[(i + 1) % k], f[i - 1]))
            diagonals[v].append(f[(i + 2) % k])
    return edges, diagonals


@pytest.mark.parametrize("mesh_name", ["cube.obj", "torus-quads.obj"])
def test_catmull_clark_limit_points_are_the_closed_form(mesh_name):
    # Halstead, Kass & DeRose 1993: the limit of a vertex of valence n on a quad mesh is
    # (n^2 V + 4 sum(E_j) + sum(F_j)) / (n (n + 5)), E_j edge neighbours, F_j diagonals.
    mesh = sk.read_mesh(MESHES / mesh_name)
    edges, diagonals = neighbours(mesh)
    P = mesh.points
    expected = np.array([(len(e) ** 2 * P[v] + 4 * P[list(e)].sum(axis=0) + P[d].sum(axis=0))
                         / (len(e) * (len(e) + 5)) for v, (e, d) in enumerate(zip(edges, diagonals))])
    limit = sk.limit_positions(mesh, "catmull-clark")
    assert limit.exact.all()
    assert np.abs(limit.points - expected).max() <= 1e-14


def test_cube_limit_normals_point_along_the_diagonals():
    cube = sk.read_mesh(MESHES / "cube.obj")
    limit = sk.limit_positions(cube, "catmull-clark")
    expected = cube.points / np.linalg.norm(cube.points, axis=1, keepdims=True)  # the cube is centred
    assert np.abs(limit.normals - expected).max() <= 1e-12


def test_limit_points_are_where_refinement_converges():
    octahedron = sk.read_mesh(MESHES / "octahedron.obj")
    limit = sk.limit_positions(octahedron, "loop").points
    # Loop's vertex points keep their index at every level (they come first). Their distance
    # to the limit shrinks at least by lambda_1 = 3/8 (valence 4) per level.
    levels = sk.refine(octahedron, "loop", 6, all_levels=True)
    errors = [np.abs(m.points[:octahedron.n_points] - limit).max() for m in levels]
    assert errors[-1] <= 1e-5
    assert all(later <= 3 / 8 * earlier for earlier, later in zip(errors, errors[1:]))


def test_closed_cubic_bspline_limit_points_are_one_four_one_over_six():
    square = sk.read_mesh(CURVES / "square.obj")
    limit = sk.limit_positions(square, "cubic-bspline").points
    ring = square.line_list()[0]
    ring = ring[:-1] if ring[0] == ring[-1] else ring  # a closed polygon repeats its first vertex
    P = square.points[ring]
    expected = (np.roll(P, 1, axis=0) + 4 * P + np.roll(P, -1, axis=0)) / 6
    assert np.abs(limit[ring] - expected).max() <= 1e-15


def test_interpolation_puts_the_limit_surface_through_the_targets():
    cube = sk.read_mesh(MESHES / "cube.obj")
    result = sk.interpolate(cube, "catmull-clark", tolerance=1e-12)
    assert result.converged
    assert result.max_residual[-1] <= 1e-12
    assert result.max_residual[0] > result.max_residual[-1]
    # Check with an independent evaluation of the new control mesh's limit.
    assert np.abs(sk.limit_positions(result.mesh, "catmull-clark").points - cube.points).max() <= 1e-12


def test_local_interpolation_moves_only_the_selected_vertices():
    cube = sk.read_mesh(MESHES / "cube.obj")
    result = sk.interpolate(cube, "catmull-clark", select=[0, 3], tolerance=1e-12)
    moved = np.any(result.mesh.points != cube.points, axis=1)
    assert list(np.flatnonzero(moved)) == [0, 3]
    assert np.abs(result.limit[[0, 3]] - cube.points[[0, 3]]).max() <= 1e-12
    mask = np.zeros(8, dtype=bool)
    mask[[0, 3]] = True
    assert np.array_equal(sk.interpolate(cube, "catmull-clark", select=mask, tolerance=1e-12).mesh.points,
                          result.mesh.points)


def test_lin_2015_two_step_interpolation_with_a_shape_parameter():
    cross = sk.read_mesh(MESHES / "cross.obj")
    result = sk.interpolate(cross, "catmull-clark-shape:1,catmull-clark", params={"lambda": 0.5},
                            select=[0, 1, 2, 3], tolerance=1e-12)
    assert result.converged
    assert np.abs(result.limit[:4] - cross.points[:4]).max() <= 1e-12


@pytest.mark.parametrize("mesh_path,scheme,select", [(MESHES / "cross.obj", "catmull-clark-shape:1,catmull-clark", "0,1,2,3"),
                                                     (CURVES / "open-zigzag.obj", "cubic-bspline", "1,2")])
def test_cli_and_python_interpolate_alike_and_theorem_two_predicts_the_fixed_points(tmp_path, mesh_path, scheme,
                                                                                     select):
    """One pipeline request (framework/pipeline/interpolate_request.h) under both front-ends:
    the same control points; and where the fixed vertices' limit points end, measured here
    from the result, is what the reported note says."""
    params = ["--param", "lambda=0.5"] if "shape" in scheme else []
    out = tmp_path / "out.obj"
    printed = run_cli("interpolate", mesh_path, "-s", scheme, "--select", select, "--tol", "1e-12", *params,
                      "-o", out).stdout
    cli_points, _ = parse_obj(out)
    mesh = sk.read_mesh(mesh_path)
    chosen = [int(v) for v in select.split(",")]
    result = sk.interpolate(mesh, scheme, params={"lambda": 0.5} if params else None, select=chosen, tolerance=1e-12)
    assert np.abs(result.mesh.points - cli_points).max() <= 1e-15
    assert result.fixed_note and result.fixed_note in printed
    fixed = np.setdiff1d(np.arange(mesh.n_points), chosen)
    offset = np.linalg.norm(result.limit[fixed] - mesh.points[fixed], axis=1).max()
    stated = float(result.fixed_note.split("end up to ")[1].split(" ")[0])
    assert stated == pytest.approx(offset, rel=1e-5)
    agreement = float(result.fixed_note.split("agrees to ")[1].rstrip(")"))
    assert agreement <= 1e-9 * max(1.0, offset)
