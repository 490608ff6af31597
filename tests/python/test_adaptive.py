"""subdivkit.refine_adaptive: feature-adaptive refinement through the pipeline.

Properties: the command line writes the same mesh (both translate one request); the mesh is
closed and watertight (every edge in exactly two faces, Euler characteristic 2 on a cube);
the faces grow linearly with the level, not as 4^L; with limit=True every vertex is on the
limit surface (subdivkit.evaluate at its corner's (face, u, v)); with a tolerance, the
bilinear patches of the faces are within it at 9 x 9 points; bad arguments are refused."""
import numpy as np
import pytest

import subdivkit as sk
from conftest import MESHES, run_cli


def cube():
    return sk.read_mesh(str(MESHES / "cube.obj"))


def edges_faces(mesh):
    counts = {}
    off, idx = mesh.face_offsets, mesh.face_indices
    for f in range(mesh.n_faces):
        corners = idx[off[f]:off[f + 1]]
        for a, b in zip(corners, np.roll(corners, -1)):
            key = (min(a, b), max(a, b))
            counts[key] = counts.get(key, 0) + 1
    return counts


def test_closed_watertight_and_linear_in_the_level():
    faces = []
    for levels in range(1, 7):
        m = sk.refine_adaptive(cube(), "catmull-clark", levels)
        counts = edges_faces(m)
        assert set(counts.values()) == {2}
        assert m.n_points - len(counts) + m.n_faces == 2
        assert m.cell_data["face_level"].max() == levels
        faces.append(m.n_faces)
    steps = np.diff(faces)
    assert np.all(steps[2:] == steps[2])  # the same number of faces added per level


def test_limit_points_are_the_evaluators_and_the_tolerance_holds():
    mesh = cube()
    m, info = sk.refine_adaptive(mesh, "catmull-clark", 5, tolerance=0.01, limit=True, info=True)
    assert info.uniform_faces == 6 * 4 ** 5 and m.n_faces < info.uniform_faces // 10
    base = m.cell_data["base_face"]
    face_of_corner = np.repeat(base, np.diff(m.face_offsets))
    r = sk.evaluate(mesh, "catmull-clark", face_of_corner, info.corner_uv, derivatives=0)
    assert np.abs(r.points - m.points[m.face_indices]).max() < 1e-12
    # Quads: the bilinear patch of the face's own corners (the extreme (u, v)) against the limit.
    worst = 0.0
    for f in range(0, m.n_faces, 7):
        uv = info.corner_uv[m.face_offsets[f]:m.face_offsets[f + 1]]
        p = m.points[m.face_indices[m.face_offsets[f]:m.face_offsets[f + 1]]]
        lo, hi = uv.min(axis=0), uv.max(axis=0)
        corner = [np.flatnonzero(np.all(np.isclose(uv, c), axis=1))[0]
                  for c in ([lo[0], lo[1]], [hi[0], lo[1]], [hi[0], hi[1]], [lo[0], hi[1]])]
        s, t = np.meshgrid(np.linspace(0, 1, 9), np.linspace(0, 1, 9))
        s, t = s.ravel(), t.ravel()
        w = np.stack([(1 - s) * (1 - t), s * (1 - t), s * t, (1 - s) * t], axis=1)
        q = np.stack([lo[0] + s * (hi[0] - lo[0]), lo[1] + t * (hi[1] - lo[1])], axis=1)
        exact = sk.evaluate(mesh, "catmull-clark", np.full(len(q), base[f]), q, derivatives=0).points
        worst = max(worst, np.linalg.norm(w @ p[corner] - exact, axis=1).max())
    assert worst <= 0.01


def test_the_command_line_writes_the_same_mesh(tmp_path):
    out = tmp_path / "adaptive.obj"
    printed = run_cli("refine", MESHES / "cube.obj", "--adaptive", "4", "--limit", "-o", out).stdout
    assert "240 faces" in printed  # 96 + 72 (L - 2) on a cube (tests/unit/limit/adaptive_refine_test.cpp)
    written = sk.read_mesh(str(out))
    ours = sk.refine_adaptive(cube(), "catmull-clark", 4, limit=True)
    assert written.n_faces == ours.n_faces and written.n_points == ours.n_points
    assert np.abs(written.points - ours.points).max() < 1e-12  # OBJ keeps 17 significant digits
    assert np.array_equal(written.face_indices, ours.face_indices)


def test_bad_arguments_are_refused():
    with pytest.raises(sk.Error, match="levels=13"):
        sk.refine_adaptive(cube(), "catmull-clark", 13)
    with pytest.raises(sk.Error, match="tolerance"):
        sk.refine_adaptive(cube(), "catmull-clark", 2, tolerance=-1)
    with pytest.raises(sk.Error, match="binary quad and triangle splits"):
        sk.refine_adaptive(cube(), "doo-sabin", 2)


def test_point_arrays_are_placed_like_the_positions():
    # Refinement and limit are affine-invariant, so an affine image of the positions stays
    # that image of the output positions.
    c = cube()
    m = sk.Mesh(c.points, face_offsets=c.face_offsets, faces=c.face_indices,
                point_data={"height": 2 * c.points[:, 2] - c.points[:, 0]})
    for limit in (False, True):
        r = sk.refine_adaptive(m, "catmull-clark", 3, limit=limit)
        assert np.allclose(r.point_data["height"].ravel(), 2 * r.points[:, 2] - r.points[:, 0], atol=1e-12)


@pytest.mark.parametrize("mode", ["none", "corners-only", "corners-plus1", "corners-plus2", "boundaries", "all"])
def test_face_varying_arrays_with_seams_are_uniform_refinements_values(mode):
    # A cube unwrapped face by face (every edge a seam, three values at every vertex), refined
    # adaptively with a tolerance that splits every face to level 2: every corner's value is
    # the one uniform refinement gives the same corner of the same face (faces found by their
    # centroid, corners by their position).
    c = cube()
    rng = np.random.default_rng(3)
    st = rng.uniform(0, 1, (24, 2))
    m = sk.Mesh(c.points, c.faces, face_varying={"st": (st, np.arange(24))})
    a = sk.refine_adaptive(m, "catmull-clark", 2, tolerance=1e-300, fvar_boundary=mode)
    u = sk.refine(m, "catmull-clark", 2, fvar_boundary=mode)
    assert a.n_faces == u.n_faces == 96
    av, ai = a.face_varying["st"]
    uv, ui = u.face_varying["st"]
    centre = u.points[u.faces].mean(axis=1)
    worst = 0.0
    for f in range(a.n_faces):
        corners = a.face_indices[a.face_offsets[f]:a.face_offsets[f + 1]]
        g = np.argmin(np.linalg.norm(centre - a.points[corners].mean(axis=0), axis=1))
        for k, v in zip(range(a.face_offsets[f], a.face_offsets[f + 1]), corners):
            j = np.argmin(np.linalg.norm(u.points[u.faces[g]] - a.points[v], axis=1))
            assert np.linalg.norm(u.points[u.faces[g][j]] - a.points[v]) < 1e-12
            worst = max(worst, np.abs(av[ai[k]] - uv[ui[4 * g + j]]).max())
    assert worst < 1e-14


def test_face_varying_arrays_on_the_limit_and_rational_meshes():
    # A seamless channel that is an affine image of the positions, in the mode "none": its
    # limit is that image of the limit positions (it refines like them); in the mode "all"
    # it is bilinear over each base face (closed forms, independent of the evaluator).
    c = cube()
    st = np.column_stack([c.points[:, 0] + 2 * c.points[:, 2], c.points[:, 1] - c.points[:, 2] + 0.5])
    m = sk.Mesh(c.points, c.faces, face_varying={"st": (st, c.face_indices.copy())})
    smooth = sk.refine_adaptive(m, "catmull-clark", 3, limit=True, fvar_boundary="none")
    values, index = smooth.face_varying["st"]
    p = smooth.points[smooth.face_indices]
    assert np.abs(values[index] - np.column_stack([p[:, 0] + 2 * p[:, 2], p[:, 1] - p[:, 2] + 0.5])).max() < 1e-12
    linear, info = sk.refine_adaptive(m, "catmull-clark", 3, limit=True, info=True)
    values, index = linear.face_varying["st"]
    base = np.repeat(linear.cell_data["base_face"], np.diff(linear.face_offsets))
    u, v = info.corner_uv[:, 0], info.corner_uv[:, 1]
    corners = st[c.faces[base]]  # (corners, 4, 2)
    w = np.column_stack([(1 - u) * (1 - v), u * (1 - v), u * v, (1 - u) * v])
    assert np.abs(values[index] - np.einsum("ck,ckj->cj", w, corners)).max() < 1e-12
    # Without limit positions the channel is refined with the faces: the mode "all" gives the
    # same bilinear values at the levels, the mode "none" the image of the level's positions.
    plain = sk.refine_adaptive(m, "catmull-clark", 3)
    values, index = plain.face_varying["st"]
    assert np.abs(values[index] - linear.face_varying["st"][0][linear.face_varying["st"][1]]).max() < 1e-14
    smooth_plain = sk.refine_adaptive(m, "catmull-clark", 3, fvar_boundary="none")
    values, index = smooth_plain.face_varying["st"]
    p = smooth_plain.points[smooth_plain.face_indices]
    assert np.abs(values[index] - np.column_stack([p[:, 0] + 2 * p[:, 2], p[:, 1] - p[:, 2] + 0.5])).max() < 1e-13
    # Rational: equal weights give the polynomial mesh; uneven ones move it, and a tolerance is refused.
    twos = sk.Mesh(c.points, c.faces, point_data={"weight": np.full(8, 2.0)})
    assert np.abs(sk.refine_adaptive(twos, "catmull-clark", 3, limit=True).points
                  - sk.refine_adaptive(c, "catmull-clark", 3, limit=True).points).max() < 1e-13
    uneven = sk.Mesh(c.points, c.faces, point_data={"weight": np.linspace(0.5, 2.0, 8)})
    assert np.abs(sk.refine_adaptive(uneven, "catmull-clark", 3).points
                  - sk.refine_adaptive(c, "catmull-clark", 3).points).max() > 1e-3
    with pytest.raises(sk.Error, match="homogeneous"):
        sk.refine_adaptive(uneven, "catmull-clark", 3, tolerance=1e-3)


def test_triangle_transitions_tile_the_polygons_with_the_same_points():
    # transitions="triangles": every face a triangle or quad, the same points as the polygon
    # output (with limit positions), watertight with the same Euler characteristic, each
    # corner's (u, v) one of its polygon's, and the faces' (u, v) areas per base face the same.
    p, pi = sk.refine_adaptive(cube(), "catmull-clark", 4, limit=True, info=True)
    t, ti = sk.refine_adaptive(cube(), "catmull-clark", 4, limit=True, info=True, transitions="triangles")
    assert np.array_equal(p.points, t.points)
    sizes = np.diff(t.face_offsets)
    assert set(sizes) == {3, 4} and np.diff(p.face_offsets).max() > 4
    counts = edges_faces(t)
    assert set(counts.values()) == {2}
    assert t.n_points - len(counts) + t.n_faces == 2

    def uv_areas(mesh, info):
        areas = np.zeros(6)
        off, uv = mesh.face_offsets, info.corner_uv
        for f in range(mesh.n_faces):
            c = uv[off[f]:off[f + 1]]
            a = 0.5 * np.sum(c[:, 0] * np.roll(c[:, 1], -1) - np.roll(c[:, 0], -1) * c[:, 1])
            assert a > 0
            areas[mesh.cell_data["base_face"][f]] += a
        return areas

    np.testing.assert_allclose(uv_areas(t, ti), uv_areas(p, pi), atol=1e-14)
    np.testing.assert_allclose(uv_areas(t, ti), np.ones(6), atol=1e-14)
    with pytest.raises(sk.Error, match="transitions"):
        sk.refine_adaptive(cube(), "catmull-clark", 2, transitions="quads")


def test_non_manifold_flaps_share_their_hinge():
    # Three flaps on one hinge edge (examples/meshes/flap-fan.obj): the hinge is isolated to
    # level 3 in every flap, its 8 segments each in the three flaps' faces, its points one
    # vertex each (not one per flap); the Euler characteristic is the uniform level's.
    fan = sk.read_mesh(str(MESHES / "flap-fan.obj"))
    m, info = sk.refine_adaptive(fan, "catmull-clark", 3, limit=True, info=True)
    counts = edges_faces(m)
    assert sorted(set(counts.values())) == [1, 2, 3]
    assert sum(1 for c in counts.values() if c == 3) == 8
    uniform = sk.refine(fan, "catmull-clark", 3)
    uniform_edges = edges_faces(uniform)
    assert m.n_points - len(counts) + m.n_faces == uniform.n_points - len(uniform_edges) + uniform.n_faces
    assert m.n_faces < info.uniform_faces == uniform.n_faces
    assert len(np.unique(np.round(m.points, 12), axis=0)) == m.n_points
    base = m.cell_data["base_face"]
    face_of_corner = np.repeat(base, np.diff(m.face_offsets))
    r = sk.evaluate(fan, "catmull-clark", face_of_corner, info.corner_uv, derivatives=0)
    assert np.abs(r.points - m.points[m.face_indices]).max() < 1e-12
