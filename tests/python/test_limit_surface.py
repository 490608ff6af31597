"""subdivkit.evaluate and subdivkit.LimitSurface: the exact limit surface at (face, u, v).

Properties, not our numbers pasted back: the command line gives the same numbers (both
translate one pipeline request); stencils applied to the control points are the evaluated
points; affine invariance; second derivatives are central differences of the first; the
limit at a base vertex is the vertex's limit position (subdivkit.limit_positions); bad
points, schemes and sequences are refused with their reasons; a sequence's limit is its
last scheme's over the mesh its head makes."""
import warnings

import numpy as np
import pytest

import subdivkit as sk
from conftest import MESHES, run_cli


def cube():
    return sk.read_mesh(str(MESHES / "cube.obj"))


def random_points(n_faces, n, seed=3, triangles=False):
    rng = np.random.default_rng(seed)
    faces = rng.integers(0, n_faces, n).astype(np.int32)
    uv = rng.uniform(0.0, 1.0, (n, 2))
    if triangles:
        over = uv.sum(axis=1) > 1
        uv[over] = 1 - uv[over]
    return faces, uv


def test_the_command_line_gives_the_same_numbers(tmp_path):
    faces, uv = random_points(6, 12)
    points = tmp_path / "points.csv"
    points.write_text("face,u,v\n" + "".join(f"{f},{u!r},{v!r}\n" for f, (u, v) in zip(faces, uv)))
    out = tmp_path / "out.csv"
    run_cli("evaluate", MESHES / "cube.obj", "--at", points, "--derivatives", "2", "-o", out)
    written = np.loadtxt(out, delimiter=",", skiprows=1)
    r = sk.evaluate(cube(), "catmull-clark", faces, uv, derivatives=2)
    ours = np.hstack([r.points, r.du, r.dv, r.duu, r.duv, r.dvv])
    assert np.array_equal(written[:, 3:], ours)  # the CLI writes the shortest exact form


def test_stencils_applied_to_the_points_are_the_evaluated_points():
    mesh = cube()
    S = sk.LimitSurface(mesh, "catmull-clark")
    faces, uv = random_points(6, 20, seed=5)
    r = S.evaluate(faces, uv, derivatives=2)
    W = S.stencils(faces, uv, derivatives=2)
    assert W.points.shape == (20, mesh.n_points)
    for name in ("points", "du", "dv", "duu", "duv", "dvv"):
        assert np.abs(getattr(W, name) @ mesh.points - getattr(r, name)).max() < 1e-12
    assert np.allclose(np.asarray(W.points.sum(axis=1)).ravel(), 1.0, atol=1e-13)  # affine weights


def test_other_values_and_affine_invariance():
    mesh = cube()
    S = sk.LimitSurface(mesh, "catmull-clark")
    faces, uv = random_points(6, 10, seed=7)
    base = S.evaluate(faces, uv, derivatives=2)
    A = np.array([[1.0, 0.3, 0.0], [0.0, 2.0, 0.1], [0.2, 0.0, 0.5]])
    t = np.array([3.0, -1.0, 2.0])
    moved = S.evaluate(faces, uv, derivatives=2, points=mesh.points @ A.T + t)
    assert np.abs(moved.points - (base.points @ A.T + t)).max() < 1e-12
    assert np.abs(moved.du - base.du @ A.T).max() < 1e-12
    assert np.abs(moved.duu - base.duu @ A.T).max() < 1e-12
    one = S.evaluate(faces, uv, derivatives=0, points=mesh.points[:, 2])  # any number of columns
    assert one.points.shape == (10, 1) and one.du is None
    assert np.abs(one.points[:, 0] - base.points[:, 2]).max() < 1e-15


def test_second_derivatives_are_differences_of_the_first_and_nan_at_an_extraordinary_vertex():
    S = sk.LimitSurface(cube(), "catmull-clark")
    u, v, h = 0.02, 0.03, 1e-6
    r = S.evaluate([0], [[u, v]], derivatives=2)
    d = S.evaluate([0, 0, 0, 0], [[u + h, v], [u - h, v], [u, v + h], [u, v - h]], derivatives=1)
    assert np.abs((d.du[0] - d.du[1]) / (2 * h) - r.duu[0]).max() < 1e-6
    assert np.abs((d.dv[2] - d.dv[3]) / (2 * h) - r.dvv[0]).max() < 1e-6
    assert np.abs((d.du[2] - d.du[3]) / (2 * h) - r.duv[0]).max() < 1e-6
    at = S.evaluate([0], [[0.0, 0.0]], derivatives=2)  # a valence-3 vertex
    assert np.isfinite(at.points).all() and np.isnan(at.du).all() and np.isnan(at.duu).all()


def test_mid_edge_second_derivatives_are_differences_of_the_first_and_nan_where_knot_lines_cross():
    # Two mid-edge steps refine the four-direction quadratic box spline (docs/limit.md): exact
    # second derivatives inside its pieces (quadratics, so central differences of the first
    # derivatives agree to rounding), none where it is only C1 or at an extraordinary point.
    S = sk.LimitSurface(cube(), "mid-edge")
    u, v, h = 0.3, 0.15, 1e-5
    r = S.evaluate([0], [[u, v]], derivatives=2)
    assert np.isfinite(r.duu).all()
    d = S.evaluate([0, 0, 0, 0], [[u + h, v], [u - h, v], [u, v + h], [u, v - h]], derivatives=1)
    assert np.abs((d.du[0] - d.du[1]) / (2 * h) - r.duu[0]).max() < 1e-6
    assert np.abs((d.dv[2] - d.dv[3]) / (2 * h) - r.dvv[0]).max() < 1e-6
    assert np.abs((d.du[2] - d.du[3]) / (2 * h) - r.duv[0]).max() < 1e-6
    W = S.stencils([0], [[u, v]], derivatives=2)
    assert np.abs(W.duu @ cube().points - r.duu).max() < 1e-12
    # A face's centre, a point of u + v = 1/2 (a knot line of the halved grid the descent ends
    # in next to the valence-3 corners), a valence-3 vertex.
    at = S.evaluate([0, 0, 0], [[0.5, 0.5], [0.25, 0.25], [0.0, 0.0]], derivatives=2)
    assert np.isfinite(at.du[:2]).all() and np.isnan(at.duu[:2]).all()
    assert np.isnan(at.du[2]).all() and np.isnan(at.duu[2]).all()


def test_at_a_vertex_the_limit_is_the_vertex_limit_position():
    mesh = sk.read_mesh(str(MESHES / "octahedron.obj"))
    S = sk.LimitSurface(mesh, "loop")
    assert S.triangles
    limit = sk.limit_positions(mesh, "loop").points
    faces = mesh.face_indices.reshape(-1, 3)
    corners = [[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]]
    for f in range(mesh.n_faces):
        r = S.evaluate([f] * 3, corners, derivatives=0)
        assert np.abs(r.points - limit[faces[f]]).max() < 1e-12


def test_unused_vertices_keep_the_numbering():
    mesh = cube()
    points = np.vstack([mesh.points[:3], [[9.0, 9.0, 9.0]], mesh.points[3:]])  # vertex 3 unused
    faces = np.where(mesh.face_indices >= 3, mesh.face_indices + 1, mesh.face_indices)
    padded = sk.Mesh(points, faces.reshape(-1, 4))
    S = sk.LimitSurface(padded, "catmull-clark")
    assert S.n_points == 9
    W = S.stencils([2], [[0.3, 0.6]])
    assert W.points.shape == (1, 9) and W.points[0, 3] == 0
    expected = sk.evaluate(mesh, "catmull-clark", [2], [[0.3, 0.6]]).points
    assert np.abs(W.points @ points - expected).max() < 1e-13
    assert np.abs(S.evaluate([2], [[0.3, 0.6]], points=points).points - expected).max() < 1e-13


def test_bad_points_schemes_and_arguments_are_refused():
    S = sk.LimitSurface(cube(), "catmull-clark")
    with pytest.raises(sk.Error, match=r"point 1 \(face 6, u 0.5, v 0.5\): face 6 does not exist"):
        S.evaluate([0, 6], [[0.5, 0.5], [0.5, 0.5]])
    with pytest.raises(sk.Error, match=r"point 0 .*outside"):
        S.evaluate([0], [[1.5, 0.5]])
    with pytest.raises(sk.Error, match="derivatives=3"):
        S.evaluate([0], [[0.5, 0.5]], derivatives=3)
    with pytest.raises(sk.Error, match="int array"):
        S.evaluate([0.5], [[0.5, 0.5]])
    with pytest.raises(sk.Error, match=r"\(n, 2\)"):
        S.evaluate([0, 1], [[0.5, 0.5]])
    with pytest.raises(sk.Error, match="one row per control point"):
        S.evaluate([0], [[0.5, 0.5]], points=np.zeros((3, 3)))
    # NaN control values were evaluated into NaN points without a word (Evaluator refused them).
    bad = np.zeros((8, 2))
    bad[5, 1] = np.nan
    with pytest.raises(sk.Error, match=r"vertex 5 has a non-finite value \(nan\) in column 1"):
        S.evaluate([0], [[0.5, 0.5]], points=bad)
    with pytest.raises(sk.Error, match="points: give numbers, got an array of dtype <U3"):
        S.evaluate([0], [[0.5, 0.5]], points="abc")  # numpy's ValueError before
    assert np.isfinite(S.evaluate([0], [[0.5, 0.5]]).points).all()  # the surface still works
    with pytest.raises(sk.Error, match="mid-edge split and the mesh has a boundary"):
        sk.LimitSurface(sk.read_mesh(str(MESHES / "plane-with-hole.obj")), "mid-edge")
    with pytest.raises(sk.Error, match="an odd number: one mid-edge step turns the faces"):
        sk.LimitSurface(sk.read_mesh(str(MESHES / "cube.obj")), "mid-edge:1,doo-sabin")
    with pytest.raises(sk.Error, match="expected a subdivkit.Mesh"):
        sk.evaluate("cube.obj", "catmull-clark", [0], [[0.5, 0.5]])


def test_face_varying_uvs_at_the_same_points_in_each_mode(tmp_path):
    tube = sk.read_mesh(str(MESHES / "textured-tube.obj"))
    faces = np.array([0, 5, 11, 23], dtype=np.int32)
    uv = np.array([[0.3, 0.4], [0.5, 0.5], [0.0, 1.0], [1.0, 0.25]])
    linear = sk.LimitSurface(tube, "catmull-clark")
    assert linear.face_varying == ["uv"]
    r = linear.evaluate_face_varying("uv", faces, uv, derivatives=1)
    # The mode "all" is bilinear in each face: the corners' values interpolated.
    values, index = tube.face_varying["uv"]
    for i, (f, (u, v)) in enumerate(zip(faces, uv)):
        c = values[index[tube.face_offsets[f]:tube.face_offsets[f + 1]]]
        expected = (1 - u) * (1 - v) * c[0] + u * (1 - v) * c[1] + u * v * c[2] + (1 - u) * v * c[3]
        assert np.abs(r.points[i] - expected).max() < 1e-14
        assert np.abs(r.du[i] - ((1 - v) * (c[1] - c[0]) + v * (c[2] - c[3]))).max() < 1e-14
    smooth = sk.LimitSurface(tube, "catmull-clark", fvar_boundary="none").evaluate_face_varying("uv", faces, uv)
    assert smooth.points.shape == (4, 2)
    # The command line writes the same values as columns uv_0, uv_1.
    points = tmp_path / "points.csv"
    points.write_text("face,u,v\n" + "".join(f"{f},{u!r},{v!r}\n" for f, (u, v) in zip(faces, uv)))
    out = tmp_path / "out.csv"
    run_cli("evaluate", MESHES / "textured-tube.obj", "--at", points, "--fvar-boundary", "none", "-o", out)
    assert out.read_text().splitlines()[0].endswith(",uv_0,uv_1")
    written = np.loadtxt(out, delimiter=",", skiprows=1)
    assert np.array_equal(written[:, -2:], smooth.points)
    with pytest.raises(sk.Error, match="face-varying array 'st': the mesh has 'uv'"):
        linear.evaluate_face_varying("st", faces, uv)


def test_sqrt3_is_evaluated_in_the_triadic_parameterisation(tmp_path):
    # Kobbelt's sqrt3 on the octahedron: the command line's numbers; at a base vertex the
    # vertex's limit position; at a face's (1/3, 1/3), where the first step puts the face's
    # point, the limit position of that level-1 vertex (sk.limit_positions of the refined
    # mesh: child vertices keep the parent's numbers, then one per face).
    mesh = sk.read_mesh(str(MESHES / "octahedron.obj"))
    faces, uv = random_points(8, 3, seed=9, triangles=True)
    points = tmp_path / "points.csv"
    points.write_text("face,u,v\n" + "".join(f"{f},{u!r},{v!r}\n" for f, (u, v) in zip(faces, uv)))
    out = tmp_path / "out.csv"
    run_cli("evaluate", MESHES / "octahedron.obj", "-s", "sqrt3", "--at", points, "-o", out)
    written = np.loadtxt(out, delimiter=",", skiprows=1)
    r = sk.evaluate(mesh, "sqrt3", faces, uv)
    assert np.array_equal(written[:, 3:], np.hstack([r.points, r.du, r.dv]))
    S = sk.LimitSurface(mesh, "sqrt3")
    assert S.triangles
    limit = sk.limit_positions(mesh, "sqrt3").points
    corners = mesh.face_indices.reshape(-1, 3)
    at_corner = S.evaluate([0, 0, 0], [[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]], derivatives=0)
    assert np.abs(at_corner.points - limit[corners[0]]).max() < 1e-13
    refined = sk.refine(mesh, "sqrt3", 1)
    level1 = sk.limit_positions(refined, "sqrt3", start_level=1).points
    centre = S.evaluate([5], [[1.0 / 3, 1.0 / 3]], derivatives=0)
    assert np.abs(centre.points[0] - level1[mesh.n_points + 5]).max() < 1e-13


def test_dual_schemes_are_evaluated_with_stencils_and_the_command_line_numbers(tmp_path):
    # Doo-Sabin on the cube: the same numbers as the command line, stencils reproduce the
    # evaluation, and the limit at a face centre is the centroid of the face for a
    # symmetric face rule (Doo & Sabin 1978) — here each cube face's centre.
    faces, uv = random_points(6, 10, seed=5)
    points = tmp_path / "points.csv"
    points.write_text("face,u,v\n" + "".join(f"{f},{u!r},{v!r}\n" for f, (u, v) in zip(faces, uv)))
    out = tmp_path / "out.csv"
    run_cli("evaluate", MESHES / "cube.obj", "-s", "doo-sabin", "--at", points, "-o", out)
    written = np.loadtxt(out, delimiter=",", skiprows=1)
    r = sk.evaluate(cube(), "doo-sabin", faces, uv)
    assert np.array_equal(written[:, 3:], np.hstack([r.points, r.du, r.dv]))
    S = sk.LimitSurface(cube(), "doo-sabin")
    W = S.stencils(faces, uv)
    P = cube().points
    assert np.allclose(W.points @ P, r.points, atol=1e-13)
    assert np.allclose(W.du @ P, r.du, atol=1e-13)
    centres = S.evaluate(np.arange(6, dtype=np.int32), np.full((6, 2), 0.5))
    corners = cube().face_indices.reshape(6, 4)
    assert np.allclose(centres.points, P[corners].mean(axis=1), atol=1e-14)


def test_a_sequence_is_the_limit_of_its_last_scheme():
    # Catmull-Clark's own levels before it change nothing: the same limit, in the same (u, v).
    faces, uv = random_points(6, 12, seed=9)
    a = sk.evaluate(cube(), "catmull-clark", faces, uv, derivatives=2)
    b = sk.evaluate(cube(), "catmull-clark:2,catmull-clark", faces, uv, derivatives=2)
    for x, y in ((a.points, b.points), (a.du, b.du), (a.dv, b.dv), (a.duu, b.duu)):
        assert np.allclose(x, y, atol=1e-10, equal_nan=True)
    # sqrt3's own levels before it, one or two, on the open tube: its new triangles straddle
    # the old edges, and the point is followed through them (docs/limit.md, sequences).
    tube = sk.read_mesh(str(MESHES / "textured-tube-triangles.obj"))
    faces, uv = random_points(tube.n_faces, 12, seed=4, triangles=True)
    a = sk.evaluate(tube, "sqrt3", faces, uv, derivatives=1)
    for head in ("sqrt3:1,sqrt3", "sqrt3:2,sqrt3"):
        b = sk.evaluate(tube, head, faces, uv, derivatives=1)
        for x, y in ((a.points, b.points), (a.du, b.du), (a.dv, b.dv)):
            assert np.allclose(x, y, atol=1e-10, equal_nan=True)


def test_tessellate_gives_the_closed_sampled_limit_with_its_normals_and_uvs():
    """LimitSurface.tessellate(N) is `subdiv evaluate --samples N`'s mesh: 6 N² quads for the
    cube, every edge in two faces (crack-free), each point the limit at its (face, u, v),
    unit normals along du x dv; the tube's UVs split at their seam (more values than points)."""
    cube = sk.read_mesh(str(MESHES / "cube.obj"))
    S = sk.LimitSurface(cube, "catmull-clark")
    t = S.tessellate(4)
    assert t.n_faces == 6 * 16
    edges = {}
    for f in t.face_list():
        for a, b in zip(f, np.roll(f, -1)):
            edges[frozenset((int(a), int(b)))] = edges.get(frozenset((int(a), int(b))), 0) + 1
    assert set(edges.values()) == {2}
    r = S.evaluate(t.point_data["base_face"], t.point_data["uv"], derivatives=1)
    assert np.abs(r.points - t.points).max() == 0
    normal = np.cross(r.du, r.dv)
    regular = np.isfinite(normal).all(axis=1)  # no derivatives at the cube's corners: the normal is their limit
    assert regular.sum() == t.n_points - 8
    normal = normal[regular] / np.linalg.norm(normal[regular], axis=1)[:, None]
    assert np.abs(np.einsum("ij,ij->i", normal, t.point_data["Normals"][regular]) - 1).max() < 1e-12
    assert np.abs(np.linalg.norm(t.point_data["Normals"], axis=1) - 1).max() < 1e-12
    assert t.point_roles["Normals"] == "normals"
    assert t.cell_data["base_face"].shape == (t.n_faces,)
    tube = sk.LimitSurface(sk.read_mesh(str(MESHES / "textured-tube.obj")), "catmull-clark").tessellate(4)
    values, corners = tube.face_varying["uv"]
    assert corners.shape == (tube.face_indices.shape[0],) and len(values) > tube.n_points
    with pytest.raises(sk.Error, match="use an even N"):
        sk.LimitSurface(sk.read_mesh(str(MESHES / "pyramid.obj")), "catmull-clark").tessellate(3)


def test_tessellate_takes_the_command_lines_cap_and_reports_its_progress():
    """tessellate(N) refuses N beyond `subdiv evaluate --samples`'s 1024 at once, by name and with
    the range (it used to start on 10**6 segments per edge until memory ran out), and reports the
    phase the command line draws a bar for, then shares done from 0 to 1."""
    S = sk.LimitSurface(cube(), "catmull-clark")
    for n in (1025, 10**6, 0):
        with pytest.raises(sk.Error, match=f"samples {n}: give 1 to 1024 segments per face edge"):
            S.tessellate(n)
    cli = run_cli("evaluate", MESHES / "cube.obj", "--samples", "1025", "-o", "never.vtp", check=False)
    assert cli.returncode != 0 and "1 to 1024" in cli.stderr
    calls = []
    m = S.tessellate(8, progress=lambda phase, done: calls.append((phase, done)))
    assert m.n_faces == 6 * 64
    assert calls[0] == ("sampling the limit surface, 8 x 8 per face", None)
    shares = [d for p, d in calls[1:]]
    assert shares and all(0 <= d <= 1 for d in shares) and shares == sorted(shares)
    with pytest.raises(sk.Error, match="progress=3"):
        S.tessellate(2, progress=3)


def test_approximate_bezier_is_the_command_line_mesh_and_exact_where_every_valence_is_4(tmp_path):
    """LimitSurface.approximate_bezier(N) is `subdiv evaluate --approximate bezier --samples N`'s
    mesh (one pipeline request); on a regular torus the patches are the exact limit; a
    triangle scheme is refused with the reason."""
    S = sk.LimitSurface(cube(), "catmull-clark")
    a = S.approximate_bezier(4)
    out = tmp_path / "a.obj"
    run_cli("evaluate", MESHES / "cube.obj", "--approximate", "bezier", "--samples", "4", "-o", out)
    written = sk.read_mesh(str(out))
    assert np.allclose(written.points, a.points, rtol=0, atol=1e-12)
    d = a.cell_data["limit_distance"]
    assert d.min() > 1e-4  # every face of the cube touches a valence-3 corner
    base = a.cell_data["base_face"]
    assert all(np.all(d[base == f] == d[base == f][0]) for f in range(6))  # one value per base face
    torus = sk.read_mesh(str(MESHES / "torus-quads.obj"))
    t = sk.LimitSurface(torus, "catmull-clark").approximate_bezier(3)
    assert t.point_data["limit_distance"].max() < 1e-12
    with pytest.raises(sk.Error, match="triangles"):
        sk.LimitSurface(cube(), "loop").approximate_bezier(2)


def test_approximate_gregory_is_the_command_line_mesh_and_exact_where_every_valence_is_4(tmp_path):
    """LimitSurface.approximate_gregory(N) is `subdiv evaluate --approximate gregory --samples N`'s
    mesh; on a regular torus and a tube with regular boundaries the Gregory patches are the
    exact limit; a triangle scheme is refused with the reason."""
    a = sk.LimitSurface(cube(), "catmull-clark").approximate_gregory(4)
    out = tmp_path / "g.obj"
    run_cli("evaluate", MESHES / "cube.obj", "--approximate", "gregory", "--samples", "4", "-o", out)
    assert np.allclose(sk.read_mesh(str(out)).points, a.points, rtol=0, atol=1e-12)
    assert a.cell_data["limit_distance"].min() > 1e-4  # every face of the cube touches a valence-3 corner
    torus = sk.read_mesh(str(MESHES / "torus-quads.obj"))
    assert sk.LimitSurface(torus, "catmull-clark").approximate_gregory(3).point_data["limit_distance"].max() < 1e-12
    tube = sk.read_mesh(str(MESHES / "textured-tube.obj"))  # two faces at every boundary vertex, valence 4 inside
    assert sk.LimitSurface(tube, "catmull-clark").approximate_gregory(2).point_data["limit_distance"].max() < 1e-12
    with pytest.raises(sk.Error, match="triangles"):
        sk.LimitSurface(cube(), "loop").approximate_gregory(2)


def test_approximations_of_triangles_are_built_on_their_sub_faces(tmp_path):
    """A mesh with triangles is approximated on the level one step makes (every face a quad):
    the same mesh as the command line's, and every base vertex, edge middle and face centre
    (corners of the patches there) on the exact limit."""
    pyramid = sk.read_mesh(str(MESHES / "pyramid.obj"))
    S = sk.LimitSurface(pyramid, "catmull-clark")
    for kind in ("bezier", "gregory"):
        a = getattr(S, "approximate_" + kind)(2)
        out = tmp_path / (kind + ".obj")
        run_cli("evaluate", MESHES / "pyramid.obj", "--approximate", kind, "--samples", "2", "-o", out)
        assert np.allclose(sk.read_mesh(str(out)).points, a.points, rtol=0, atol=1e-12)
        # --samples 2: the quad's samples and the triangles' sub-face corners are the level-1 vertices.
        assert a.point_data["limit_distance"].max() < 1e-12
        assert set(a.cell_data["base_face"]) == set(range(5))


def test_a_non_manifold_mesh_is_evaluated_flap_by_flap():
    # Three flaps on one hinge edge (vertices 0 and 1): the hinge is infinitely sharp, so
    # every flap's limit along it is the straight hinge, and each flap is smooth.
    fan = sk.read_mesh(str(MESHES / "flap-fan.obj"))
    S = sk.LimitSurface(fan, "catmull-clark")
    hinge_faces = [f for f, face in enumerate(fan.faces) if {0, 1} <= set(face)]
    assert len(hinge_faces) == 3
    hinge = fan.points[1] - fan.points[0]
    for f in hinge_faces:
        corners = list(fan.faces[f])
        # The face's u runs from corner 0 to corner 1: the hinge when it starts at vertex 0.
        assert corners[:2] == [0, 1]
        r = S.evaluate(np.full(5, f), np.array([[t, 0.0] for t in (0, 0.25, 0.5, 0.75, 1)]))
        np.testing.assert_allclose(r.points, fan.points[0] + np.outer([0, 0.25, 0.5, 0.75, 1], hinge), atol=1e-14)
    W = S.stencils(np.array(hinge_faces), np.full((3, 2), 0.3))
    np.testing.assert_allclose(W.points @ fan.points, S.evaluate(np.array(hinge_faces), np.full((3, 2), 0.3)).points,
                               atol=1e-14)


@pytest.mark.parametrize("kind", ["approximate_bezier", "approximate_gregory"])
def test_an_approximation_refused_names_the_python_method_not_the_command_line_option(kind):
    """The pipeline's refusal names the approximation as Python calls it: the command line's
    '--approximate bezier' meant nothing to a Python user."""
    with pytest.raises(sk.Error) as refused:
        getattr(sk.LimitSurface(sk.read_mesh(str(MESHES / "octahedron.obj")), "loop"), kind)(2)
    message = str(refused.value)
    assert message.startswith(kind + "(): ")
    assert "triangles" in message
    assert "--approximate" not in message


@pytest.mark.parametrize("kind", ["approximate_bezier", "approximate_gregory"])
@pytest.mark.parametrize("tags, why", [("t corner 1/1/0 0 10", "a cone point"),
                                       ("t crease 2/1/0 4 5 9.5", "more than"),
                                       (None, "non-manifold")])
def test_every_refusal_of_an_approximation_offers_the_exact_limit_in_python_words(tmp_path, kind, tags, why):
    """A cone point, a semi-sharp tag that would take millions of patches and a non-manifold
    vertex are refused with the fix (the exact limit) in words a Python user can follow: the
    command line's '(without --approximate)' was left in them."""
    if tags is None:
        mesh = sk.read_mesh(str(MESHES / "flap-fan.obj"))
    else:
        (tmp_path / "m.obj").write_text((MESHES / "cube.obj").read_text() + tags + "\n")
        mesh = sk.read_mesh(str(tmp_path / "m.obj"))
    with pytest.raises(sk.Error) as refused:
        getattr(sk.LimitSurface(mesh, "catmull-clark"), kind)(2)
    message = str(refused.value)
    assert message.startswith(kind + "(): ")
    assert why in message
    assert "evaluate the exact limit instead" in message
    assert "--approximate" not in message


def test_sample_points_without_a_normal_are_zero_with_a_warning():
    """A pillow (two quads back to back) folds flat along its edges, where du x dv = 0: the
    Normals there are (0, 0, 0), said by a UserWarning with their count and the first place;
    a surface with a normal everywhere gives unit normals and no warning."""
    pillow = sk.Mesh(np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]], dtype=float),
                     [[0, 1, 2, 3], [3, 2, 1, 0]])
    with pytest.warns(UserWarning, match=r"tessellate: the limit surface has no normal at \d+ of \d+ points "
                                         r"\(the first at face \d+"):
        m = sk.LimitSurface(pillow).tessellate(4)
    n = np.linalg.norm(m.point_data["Normals"], axis=1)
    assert np.any(n == 0) and np.all((n == 0) | np.isclose(n, 1.0))
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        n = np.linalg.norm(sk.LimitSurface(cube()).tessellate(4).point_data["Normals"], axis=1)
    assert np.allclose(n, 1.0)


def test_a_limit_surface_refuses_pickling_and_copies_by_saying_what_to_do_and_keeps_its_mesh():
    """pickle and copy raised "cannot pickle '_LimitSurface' object" (the native class's name);
    they now say what to pickle instead. The surface keeps the mesh it was made from: changing
    the Mesh afterwards changes nothing, as the docstring says."""
    import copy
    import pickle
    mesh = cube()
    S = sk.LimitSurface(mesh, "catmull-clark")
    for how in (pickle.dumps, copy.copy, copy.deepcopy):
        with pytest.raises(TypeError, match="pickle its Mesh instead and make LimitSurface"):
            how(S)
    before = S.evaluate([0], [[0.3, 0.3]]).points
    mesh.points[:] = mesh.points * 2
    assert np.array_equal(S.evaluate([0], [[0.3, 0.3]]).points, before)
    assert np.array_equal(S.evaluate([0], [[0.3, 0.3]], points=mesh.points).points, 2 * before)
    assert pickle.loads(pickle.dumps(mesh)).n_faces == mesh.n_faces


def test_points_without_columns_are_refused_not_read_as_the_mesh_points():
    # An (n_points, 0) array has no values to evaluate: the result had the mesh's positions,
    # three columns the caller did not give.
    S = sk.LimitSurface(cube(), "catmull-clark")
    with pytest.raises(sk.Error, match=r"points \(8, 0\): give at least one column"):
        S.evaluate([0], [[0.5, 0.5]], points=np.zeros((8, 0)))
    one = S.evaluate([0], [[0.5, 0.5]], points=np.arange(8.0))  # a column: its limit, one value
    assert one.points.shape == (1, 1)


def test_no_points_given_as_empty_lists_evaluate_to_empty_arrays():
    # evaluate([], []) is an empty request, as evaluate([], np.empty((0, 2))) already was.
    S = sk.LimitSurface(cube(), "catmull-clark")
    r = S.evaluate([], [], derivatives=2)
    assert r.points.shape == (0, 3) and r.du.shape == (0, 3) and r.duu.shape == (0, 3)
    assert sk.evaluate(cube(), "catmull-clark").points.shape == (0, 3)  # the defaults faces=(), uv=()
    assert S.stencils([], []).points.shape == (0, 8)


def test_a_scheme_not_c1_raises_for_derivatives_and_evaluates_positions(tmp_path):
    # Catmull-Clark keeping 0.9 of the vertex: converges, but its regular vertices'
    # subdominant eigenvalues (0.569, 0.5) are not the parameters' 1/2.
    path = tmp_path / "stiff.json"
    path.write_text('{"name": "stiff", "split": "quad", "faces": "any", "curve": "cubic-bspline", "rules": {'
                    '"face": [{"sum": "vertices", "w": "1/k"}],'
                    '"edge": [{"sum": "ends", "w": "1/4"}, {"sum": "faces", "new": "face", "w": "1/4"}],'
                    '"vertex": [{"at": "self", "w": "0.9"}, {"sum": "ring", "w": "0.05/n"},'
                    '{"sum": "faces", "new": "face", "w": "0.05/n"}]}}')
    S = sk.LimitSurface(cube(), str(path))
    with pytest.raises(sk.Error, match="is not C1, so its limit has no derivatives"):
        S.evaluate([0], [[0.3, 0.2]])
    assert np.isfinite(S.evaluate([0], [[0.3, 0.2]], derivatives=0).points).all()
    # limit_positions, as refine --limit: the positions, and no normals (zero) with the reason.
    L = sk.limit_positions(cube(), str(path))
    assert np.isfinite(L.points).all()
    assert not L.normals.any() and not L.normal_exact.any()
    assert any("is not C1" in why for why in L.approximate_reasons)
    assert sk.limit_positions(cube(), "catmull-clark").normals.any()
