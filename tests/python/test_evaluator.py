"""Evaluator: a refinement prepared once and evaluated for many point sets. Whatever points
one evaluator is given, in whatever order, its values are refine()'s bit for bit."""
import threading

import numpy as np
import pytest

import subdivkit as sk
from conftest import MESHES


def semi_sharp_cube():
    # cube-creased.obj's creases and corner with sharpness that decays over the levels
    # (fractional, so that Chaikin's rule differs from the uniform one).
    c = sk.read_mesh(MESHES / "cube-creased.obj")
    return sk.Mesh(c.points, c.face_indices, face_offsets=c.face_offsets, creases=c.creases,
                   crease_sharpness=[0.5, 1.5, 2.25, 10], corners=c.corners, corner_sharpness=[1.7], name="semi-sharp")


def read(name):
    return lambda: sk.read_mesh(MESHES / name)


# (id, mesh, scheme, levels, keyword arguments as refine takes them)
CASES = [
    ("catmull-clark-creases", semi_sharp_cube, "catmull-clark", 3, {}),
    ("catmull-clark-chaikin", semi_sharp_cube, "catmull-clark", 3, {"crease_method": "chaikin"}),
    ("loop", read("octahedron.obj"), "loop", 3, {}),
    ("sequence", read("cube.obj"), "catmull-clark-shape:1,catmull-clark", 3, {"params": {"lambda": 0.8}}),
    ("loop-composite", read("octahedron.obj"), "loop-composite", 2, {}),  # smoothing passes
    ("sqrt3-start-level", read("octahedron.obj"), "sqrt3", 3, {"start_level": 1}),
    ("doo-sabin-boundary", read("plane-with-hole.obj"), "doo-sabin", 2, {"boundary": "edges"}),
    ("butterfly-scheme-object", read("octahedron.obj"), sk.Scheme.load("butterfly"), 2, {}),
]


def frames(mesh, count=4, seed=7):
    """The mesh's own points, then moved, scaled and sheared versions of them."""
    rng = np.random.default_rng(seed)
    p = mesh.points
    out = [p]
    for k in range(1, count):
        out.append(p * (1 + 0.5 * k) + 0.2 * rng.standard_normal(p.shape) + [k, -2 * k, 0.5])
    return out


@pytest.mark.parametrize("case", CASES, ids=[c[0] for c in CASES])
def test_one_evaluator_gives_refines_points_bit_for_bit_frame_after_frame(case):
    _, make, scheme, levels, kwargs = case
    mesh = make()
    ev = sk.Evaluator(mesh, scheme, levels, **kwargs)
    sequence = frames(mesh)
    expected = [sk.refine(mesh.with_points(p), scheme, levels, **kwargs).points for p in sequence]
    # Forwards, then backwards: nothing of one frame stays in the evaluator's buffers.
    for p, e in zip(sequence + sequence[::-1], expected + expected[::-1]):
        got = ev.evaluate(p)
        assert got.shape == e.shape and got.dtype == np.float64
        assert np.array_equal(got, e)


@pytest.mark.parametrize("case", CASES, ids=[c[0] for c in CASES])
def test_mesh_is_refines_finest_level(case):
    _, make, scheme, levels, kwargs = case
    mesh = make()
    ev = sk.Evaluator(mesh, scheme, levels, **kwargs)
    moved = frames(mesh)[2]
    for got, points in ((ev.mesh(), mesh.points), (ev.mesh(moved), moved)):
        expected = sk.refine(mesh.with_points(points), scheme, levels, **kwargs)
        assert isinstance(got, sk.Mesh) and got.name == mesh.name
        for key in ("points", "face_indices", "face_offsets", "creases", "crease_sharpness", "corners",
                    "corner_sharpness"):
            assert np.array_equal(getattr(got, key), getattr(expected, key)), key
    assert ev.levels == levels and ev.n_base_points == mesh.n_points
    assert ev.n_points == expected.n_points and ev.n_faces == expected.n_faces
    assert np.array_equal(ev.face_offsets, expected.face_offsets)
    assert np.array_equal(ev.creases, expected.creases)
    assert np.array_equal(ev.crease_sharpness, expected.crease_sharpness)


def test_affine_maps_commute_with_evaluation():
    # Every rule is an affine combination: evaluate(A p + t) = A evaluate(p) + t.
    mesh = semi_sharp_cube()
    ev = sk.Evaluator(mesh, "catmull-clark", 3)
    rng = np.random.default_rng(3)
    for _ in range(3):
        p = mesh.points + 0.3 * rng.standard_normal(mesh.points.shape)
        A, t = rng.standard_normal((3, 3)), rng.standard_normal(3)
        assert np.abs(ev.evaluate(p @ A.T + t) - (ev.evaluate(p) @ A.T + t)).max() <= 1e-12


def test_any_number_of_columns_is_refined_column_by_column():
    mesh = sk.read_mesh(MESHES / "octahedron.obj")
    ev = sk.Evaluator(mesh, "loop", 3)
    rng = np.random.default_rng(5)
    colour = rng.random((mesh.n_points, 4))
    height = mesh.points[:, 2] * 2
    p0, p1 = frames(mesh, 2)
    # Two frames side by side and a colour: the columns do not mix.
    both = ev.evaluate(np.hstack([p0, p1, colour]))
    assert both.shape == (ev.n_points, 10)
    assert np.array_equal(both[:, :3], ev.evaluate(p0)) and np.array_equal(both[:, 3:6], ev.evaluate(p1))
    # refine() carries point data by the same rules.
    refined = sk.refine(sk.Mesh(p1, mesh.faces, point_data={"colour": colour, "height": height}), "loop", 3)
    assert np.array_equal(ev.evaluate(colour), refined.point_data["colour"])
    one = ev.evaluate(height)  # 1-d in, 1-d out
    assert one.shape == (ev.n_points,) and np.array_equal(one, refined.point_data["height"])
    # Integers and float32 are converted, as Mesh converts points.
    assert np.array_equal(ev.evaluate(np.arange(mesh.n_points)), ev.evaluate(np.arange(mesh.n_points, dtype=float)))
    assert np.array_equal(ev.evaluate(p0.astype(np.float32)), ev.evaluate(p0.astype(np.float32).astype(float)))


def test_zero_levels_is_the_identity():
    cube = sk.read_mesh(MESHES / "cube.obj")
    ev = sk.Evaluator(cube, "catmull-clark", 0)
    p = frames(cube)[1]
    assert ev.levels == 0 and np.array_equal(ev.evaluate(p), p)
    assert np.array_equal(ev.faces, cube.faces)


def test_the_evaluator_hands_out_copies_and_keeps_its_own_topology():
    cube = sk.read_mesh(MESHES / "cube.obj")
    ev = sk.Evaluator(cube, "catmull-clark", 2)
    assert not ev.face_indices.flags.writeable and not ev.faces.flags.writeable
    first = ev.mesh()
    first.face_indices[:] = 0  # the caller's Mesh is the caller's to change
    cube.points[:] = 0         # mesh() refines the points the evaluator was made with
    again = ev.mesh()
    assert np.array_equal(again.face_indices, ev.face_indices) and again.face_indices.max() > 0
    assert np.array_equal(again.points, sk.refine(sk.read_mesh(MESHES / "cube.obj"), "catmull-clark", 2).points)
    assert "2 level(s) of catmull-clark" in repr(ev) and "8 -> 98 points" in repr(ev)


def test_threads_take_turns_on_one_evaluator_with_the_same_bits():
    mesh = sk.read_mesh(MESHES / "torus-quads.obj")
    sequence = frames(mesh, 6)
    expected = [sk.refine(mesh.with_points(p), "catmull-clark", 3, threads=1).points for p in sequence]
    ev = sk.Evaluator(mesh, "catmull-clark", 3)  # all cores inside each call
    results = {}

    def work(k):
        for _ in range(3):
            results[k] = ev.evaluate(sequence[k])

    workers = [threading.Thread(target=work, args=(k,)) for k in range(len(sequence))]
    for w in workers:
        w.start()
    for w in workers:
        w.join()
    for k, e in enumerate(expected):
        assert np.array_equal(results[k], e)


def test_bad_points_are_refused_with_the_reason():
    cube = sk.read_mesh(MESHES / "cube.obj")
    ev = sk.Evaluator(cube, "catmull-clark", 2)
    with pytest.raises(sk.Error, match=r"7 rows for a base mesh of 8 points"):
        ev.evaluate(cube.points[:7])
    with pytest.raises(sk.Error, match=r"expected shape \(8, c\) with c >= 1 columns.*got \(8, 3, 1\)"):
        ev.evaluate(cube.points[:, :, None])
    with pytest.raises(sk.Error, match=r"got \(8, 0\)"):
        ev.evaluate(np.zeros((8, 0)))
    with pytest.raises(sk.Error, match=r"got \(\)"):
        ev.evaluate(1.0)
    with pytest.raises(sk.Error, match="expected numbers"):
        ev.evaluate(np.full((8, 3), "x"))
    bad = cube.points.copy()
    bad[5, 1] = np.nan
    with pytest.raises(sk.Error, match=r"point 5 has a non-finite value \(nan\) in column 1"):
        ev.evaluate(bad)
    bad[5, 1] = np.inf
    with pytest.raises(sk.Error, match=r"point 5 has a non-finite value \(inf\)"):
        ev.evaluate(bad)
    with pytest.raises(sk.Error, match=r"a Mesh needs points of shape \(8, 3\), got \(8, 2\)"):
        ev.mesh(cube.points[:, :2])
    # mesh()'s refusals name mesh(), the method called, not the evaluate() it calls.
    with pytest.raises(sk.Error, match=r"^Evaluator\.mesh: 3 rows for a base mesh of 8 points"):
        ev.mesh(cube.points[:3])
    # A refused call leaves the evaluator as it was.
    assert np.array_equal(ev.evaluate(cube.points), sk.refine(cube, "catmull-clark", 2).points)


def refine_error(*args, **kwargs):
    with pytest.raises(sk.Error) as e:
        sk.refine(*args, **kwargs)
    return str(e.value)


@pytest.mark.parametrize("args,kwargs", [
    (("catmull-clark", -1), {}),
    (("catmull-clark", 1), {"boundary": "corners"}),
    (("catmull-clark", 1), {"crease_method": "sharp"}),
    (("catmull-clark", 1), {"threads": -2}),
    (("no-such-scheme", 1), {}),
    (("catmull-clark-shape:1,catmull-clark", 2), {"params": {"lambda": True}}),
], ids=["levels", "boundary", "crease_method", "threads", "scheme", "params"])
def test_bad_arguments_are_refused_as_refine_refuses_them(args, kwargs):
    cube = sk.read_mesh(MESHES / "cube.obj")
    expected = refine_error(cube, *args, **kwargs)
    with pytest.raises(sk.Error) as e:
        sk.Evaluator(cube, *args, **kwargs)
    assert str(e.value) == expected


def test_bad_meshes_are_refused_as_refine_refuses_them():
    square = [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]]
    for mesh in (sk.Mesh([[0, 0, np.nan], [1, 0, 0], [1, 1, 0], [0, 1, 0]], [[0, 1, 2, 3]]),
                 sk.Mesh(square, [[0, 1, 2, 7]]), sk.Mesh(square)):
        expected = refine_error(mesh, "catmull-clark", 1)
        with pytest.raises(sk.Error) as e:
            sk.Evaluator(mesh, "catmull-clark", 1)
        assert str(e.value) == expected
    with pytest.raises(sk.Error, match="expected a subdivkit.Mesh"):
        sk.Evaluator(np.zeros((8, 3)))
    with pytest.raises(sk.Error, match="'chaikin' is a curve scheme; the Evaluator refines surfaces"):
        sk.Evaluator(sk.Mesh(square, lines=[[0, 1, 2, 3, 0]]), "chaikin", 2)
