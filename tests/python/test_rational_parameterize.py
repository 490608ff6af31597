"""Rational subdivision (weights=) and Tutte parameterisation (subdivkit.parameterize) from Python."""
import math

import numpy as np
import pytest

import subdivkit
from conftest import MESHES, SOURCE_DIR, run_cli

CHAIKIN_UNIFORM = SOURCE_DIR / "examples" / "rational" / "chaikin-uniform.json"


def quarter_arcs():
    """Four open polylines of three weighted points: each a rational quadratic B-spline span
    that is a quarter of the unit circle (middle weight cos 45°, ends reflected)."""
    c = math.sqrt(0.5)
    arc = np.array([[2 - c, -c, 2 - c], [c, c, c], [-c, 2 - c, 2 - c]])  # homogeneous (x w, y w, w)
    points, weights = [], []
    for k in range(4):
        a = k * math.pi / 2
        rot = np.array([[math.cos(a), -math.sin(a)], [math.sin(a), math.cos(a)]])
        for h in arc:
            xy = rot @ (h[:2] / h[2])
            points.append([xy[0], xy[1], 0.0])
            weights.append(h[2])
    lines = np.arange(12, dtype=np.int32)
    return subdivkit.Mesh(np.array(points), lines=lines, line_offsets=[0, 3, 6, 9, 12]), np.array(weights)


@pytest.mark.parametrize("levels", [1, 3, 5])
def test_weighted_chaikin_arcs_lie_on_the_circle(levels):
    mesh, w = quarter_arcs()
    fine = subdivkit.refine(mesh, str(CHAIKIN_UNIFORM), levels, weights=w)
    W = fine.point_data["weight"]
    h = fine.points * W[:, None]
    for line in fine.line_list():
        mid = (h[line[:-1]] + h[line[1:]]) / (W[line[:-1]] + W[line[1:]])[:, None]
        assert np.abs(np.hypot(mid[:, 0], mid[:, 1]) - 1).max() <= 1e-12


def test_weights_one_give_the_plain_refinement_bit_for_bit():
    cube = subdivkit.read_mesh(MESHES / "cube.obj")
    plain = subdivkit.refine(cube, "catmull-clark", 2)
    ones = subdivkit.refine(cube, "catmull-clark", 2, weights=np.ones(cube.n_points))
    assert np.array_equal(plain.points, ones.points)


def test_weights_by_name_and_refusals():
    cube = subdivkit.read_mesh(MESHES / "cube.obj")
    w = np.linspace(0.5, 2.0, cube.n_points)
    by_array = subdivkit.refine(cube, "catmull-clark", 2, weights=w)
    named = subdivkit.Mesh(cube.points, cube.faces, point_data={"rw": w}, name=cube.name)
    by_name = subdivkit.refine(named, "catmull-clark", 2, weights="rw")
    assert np.array_equal(by_array.points, by_name.points)
    w[3] = 0
    with pytest.raises(subdivkit.Error, match="vertex 3"):
        subdivkit.refine(cube, "catmull-clark", 1, weights=w)
    with pytest.raises(subdivkit.Error, match="no point_data array"):
        subdivkit.refine(cube, "catmull-clark", 1, weights="nope")


def test_obj_fourth_coordinate_round_trip(tmp_path):
    cube = subdivkit.read_mesh(MESHES / "cube.obj")
    w = np.linspace(0.5, 2.0, cube.n_points)
    src = tmp_path / "weighted.obj"
    with open(src, "w") as f:
        for p, wi in zip(cube.points, w):
            f.write(f"v {p[0]!r} {p[1]!r} {p[2]!r} {wi!r}\n")
        for face in cube.face_list():
            f.write("f " + " ".join(str(i + 1) for i in face) + "\n")
    out = tmp_path / "refined.obj"
    run_cli("refine", src, "-s", "catmull-clark", "-l", "2", "-o", out)
    text = [line.split() for line in open(out) if line.startswith("v ")]
    assert all(len(t) == 5 for t in text)  # v x y z w
    expected = subdivkit.refine(cube, "catmull-clark", 2, weights=w)
    got = np.array([[float(x) for x in t[1:4]] for t in text])
    assert np.abs(got - expected.points).max() <= 1e-15
    assert np.allclose([float(t[4]) for t in text], expected.point_data["weight"], rtol=0, atol=1e-15)


def bumpy_disc(n=6):
    xs = np.linspace(0, 1, n + 1)
    points = np.array([[x ** 1.5, y, 0.3 * math.sin(3 * x) * math.cos(2 * y)] for y in xs for x in xs])
    faces = [[j * (n + 1) + i, j * (n + 1) + i + 1, (j + 1) * (n + 1) + i + 1, (j + 1) * (n + 1) + i]
             for j in range(n) for i in range(n)]
    return subdivkit.Mesh(points, np.array(faces, dtype=np.int32).reshape(-1), face_offsets=np.arange(0, 4 * len(faces) + 1, 4))


@pytest.mark.parametrize("weights", ["uniform", "mean-value"])
def test_parameterize_circle(weights):
    mesh = bumpy_disc()
    done = subdivkit.parameterize(mesh, weights=weights)
    uv, idx = done.face_varying["uv"]
    assert np.array_equal(idx, mesh.face_indices)
    r = np.hypot(uv[:, 0], uv[:, 1])
    assert abs(np.sort(r)[-24:] - 1).max() <= 1e-14  # the 24 boundary vertices on the unit circle
    assert (r[r < 1 - 1e-9]).size == mesh.n_points - 24
    for face in done.face_list():  # no flipped face
        p = uv[face]
        assert np.sum(p[:, 0] * np.roll(p[:, 1], -1) - np.roll(p[:, 0], -1) * p[:, 1]) > 0
    refined = subdivkit.refine(done, "catmull-clark", 2)
    assert "uv" in refined.face_varying


def test_parameterize_square_and_refusals():
    mesh = bumpy_disc()
    done = subdivkit.parameterize(mesh, boundary="square", corners=[0, 6, 48, 42])
    uv = done.face_varying["uv"][0]
    assert uv[[0, 6, 48, 42]].tolist() == [[0, 0], [1, 0], [1, 1], [0, 1]]
    with pytest.raises(subdivkit.Error, match="0 boundary loops"):
        subdivkit.parameterize(subdivkit.read_mesh(MESHES / "cube.obj"))
    with pytest.raises(subdivkit.Error, match="add boundary=\"square\""):
        subdivkit.parameterize(mesh, corners=[0, 6, 48, 42])


def test_limit_surface_of_a_weighted_mesh_is_the_rational_one():
    cube = subdivkit.read_mesh(MESHES / "cube.obj")
    w = np.linspace(0.5, 2.0, cube.n_points)
    uv = [[0.3, 0.6], [0.8, 0.3]]

    def at(weights):
        mesh = subdivkit.Mesh(cube.points, cube.faces, point_data={"weight": weights})
        return subdivkit.LimitSurface(mesh, "catmull-clark").evaluate([0, 4], uv, derivatives=2)

    plain = subdivkit.LimitSurface(cube, "catmull-clark").evaluate([0, 4], uv, derivatives=2)
    uneven, scaled = at(w), at(3 * w)
    assert not np.allclose(uneven.points, plain.points)  # the weights move the surface
    for name in ("points", "du", "dv", "duu", "duv", "dvv"):  # projective: only ratios of weights count
        assert np.allclose(getattr(uneven, name), getattr(scaled, name), rtol=1e-12, atol=1e-12)
    assert np.allclose(at(np.full(cube.n_points, 2.0)).points, plain.points, rtol=1e-13, atol=1e-13)
    with pytest.raises(subdivkit.Error, match="not linear"):
        subdivkit.LimitSurface(subdivkit.Mesh(cube.points, cube.faces, point_data={"weight": w}),
                               "catmull-clark").stencils([0], [[0.5, 0.5]])
