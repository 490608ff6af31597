"""A seeded fuzz test of the Python API (issue 33; Atheris is not in Debian): random
attribute assignments and calls on subdivkit objects — Mesh arrays of the wrong dtype,
shape or size, NaN, infinities, huge and negative values; Scheme, Evaluator and LimitSurface
methods with wrong arguments. Every case must either work (and then give finite numbers) or
raise subdivkit.Error, TypeError or ValueError: never crash the interpreter, never another
exception type. The seed is fixed, so a failure names its case and replays; the number of
cases is fixed and each is small, so the test takes a few seconds.
"""
import random
import time

import numpy as np
import pytest

import subdivkit as sk
from conftest import MESHES

SEED = 33  # any fixed value: the cases replay exactly
CASES = 1500
TIME_LIMIT = 60.0  # seconds, a guard against a hang (a case runs in milliseconds)

ALLOWED = (sk.Error, TypeError, ValueError)

SPECIAL = [0.0, -0.0, 1.0, -1.0, -5.0, 0.5, np.nan, np.inf, -np.inf, 1e308, -1e308, 5e-324, 2.0**31, 2.0**40,
           -2.0**63, 1e20]
DTYPES = [np.float64, np.float32, np.int32, np.int64, np.uint8, np.int8, np.bool_, np.complex128, object, np.uint64]
SHAPES = [(0,), (1,), (3,), (8,), (24,), (8, 3), (8, 2), (6, 4), (3, 8), (8, 4), (2, 2, 2), (7, 3), (9, 3), (6,),
          (12, 2), (0, 3), (1, 1)]


def random_array(rng):
    shape = rng.choice(SHAPES)
    dtype = rng.choice(DTYPES)
    size = int(np.prod(shape))
    kind = rng.random()
    if kind < 0.4:
        values = [rng.choice(SPECIAL) for _ in range(size)]
    elif kind < 0.7:
        values = [rng.randrange(-10, 30) for _ in range(size)]
    else:
        values = [rng.uniform(-2, 2) for _ in range(size)]
    try:
        with np.errstate(all="ignore"):
            return np.array(values, dtype=np.float64).astype(dtype).reshape(shape)
    except (ValueError, OverflowError, TypeError):
        return np.array(values, dtype=np.float64).reshape(shape)


def random_value(rng):
    r = rng.random()
    if r < 0.65:
        return random_array(rng)
    if r < 0.75:
        return random_array(rng).tolist()
    return rng.choice([None, "text", b"\x1b[2J", 3, -1, 2.5, float("nan"), [], [[]], {"a": 1}, (1, 2), object(),
                       [[0, 1, 2], [0, 1]], [[0, 1, "x"]], 10**30])


def fresh_mesh(rng):
    if rng.random() < 0.5:
        return sk.read_mesh(str(MESHES / "cube.obj"))
    n = rng.randrange(1, 4)
    xs, ys = np.meshgrid(np.arange(n + 1, dtype=float), np.arange(n + 1, dtype=float))
    points = np.column_stack([xs.ravel(), ys.ravel(), np.zeros(xs.size)])
    faces = [[j * (n + 1) + i, j * (n + 1) + i + 1, (j + 1) * (n + 1) + i + 1, (j + 1) * (n + 1) + i]
             for j in range(n) for i in range(n)]
    return sk.Mesh(points, faces)


ATTRIBUTES = ["points", "face_indices", "face_offsets", "line_indices", "line_offsets", "creases", "crease_sharpness",
              "corners", "corner_sharpness", "name"]


def spoil(rng, mesh):
    """One random assignment to the mesh; its own refusal is fine (the test goes on)."""
    target = rng.random()
    value = random_value(rng)
    if target < 0.55:
        setattr(mesh, rng.choice(ATTRIBUTES), value)
    elif target < 0.7:
        mesh.point_data[rng.choice(["weight", "x", "uv", "t\x00"])] = value
    elif target < 0.8:
        mesh.cell_data[rng.choice(["label", "c"])] = value
    elif target < 0.9:
        mesh.face_varying["uv"] = (value, random_value(rng)) if rng.random() < 0.8 else value
    else:
        mesh.point_roles[rng.choice(["uv", "x"])] = rng.choice(["normals", "texture_coordinates", "nonsense", 3])


def finite(values):
    return all(np.all(np.isfinite(np.asarray(v, dtype=float))) for v in values)


def call(rng, mesh, tmp_path):
    """One random call; returns the arrays it computed (to be finite)."""
    scheme = rng.choice(["catmull-clark", "loop", "bilinear", "butterfly", "doo-sabin", "no-such-scheme", 7, None])
    levels = rng.choice([0, 1, 2, -1, 2.5, "1", 10**9])
    what = rng.randrange(8)
    if what == 0:
        fine = sk.refine(mesh, scheme, levels)
        return [fine.points]
    if what == 1:
        return [sk.limit_positions(mesh, scheme).points]
    if what == 2:
        ev = sk.Evaluator(mesh, scheme, levels)
        return [ev.evaluate(random_value(rng) if rng.random() < 0.5 else mesh.points)]
    if what == 3:
        surface = sk.LimitSurface(mesh, scheme)
        faces = random_value(rng) if rng.random() < 0.6 else [0]
        uv = random_value(rng) if rng.random() < 0.6 else [[0.5, 0.5]]
        r = surface.evaluate(faces, uv, rng.choice([0, 1, 2, 3, -1, 1.5, "1"]))
        return [r.points]
    if what == 4:
        s = sk.stencils(mesh, scheme, levels, composed=rng.random() < 0.5)
        return [s.data] if hasattr(s, "data") else []
    if what == 5:
        name = rng.choice(["out.obj", "out.ply", "out.off", "out.stl", "out.vtp", "out\x1b.obj", "out.xyz"])
        sk.write_mesh(str(tmp_path / name), mesh)
        return []
    if what == 6:
        loaded = sk.Scheme.load(rng.choice(["catmull-clark", "loop", "four-point"]))
        params = {rng.choice(["w", "beta", "n", "nope"]): rng.choice(SPECIAL + ["x", "warren", None])}
        loaded.with_params(**params)
        return []
    sk.Scheme.from_dict(rng.choice([{}, {"name": 3}, {"name": "x", "split": "quad", "rules": random_value(rng)},
                                    {"name": "x\x1b[2J", "split": rng.choice(["quad", "bad", 5])}, []]))
    return []


def test_random_assignments_and_calls_raise_clear_errors_or_give_finite_results(tmp_path):
    rng = random.Random(SEED)
    start = time.monotonic()
    outcomes = {"ok": 0, "refused": 0}
    for case in range(CASES):
        assert time.monotonic() - start < TIME_LIMIT, f"case {case}: the fuzz test ran past {TIME_LIMIT} s"
        mesh = fresh_mesh(rng)
        try:
            for _ in range(rng.randrange(0, 3)):
                spoil(rng, mesh)
            results = call(rng, mesh, tmp_path)
        except ALLOWED as e:
            outcomes["refused"] += 1
            assert str(e) or isinstance(e, TypeError), f"case {case}: an empty message ({type(e).__name__})"
            assert "\x1b" not in str(e), f"case {case}: a raw ESC in the message {str(e)!r}"
            continue
        except Exception as e:  # noqa: BLE001 - the finding: an exception of another type
            pytest.fail(f"case {case} (seed {SEED}): {type(e).__name__}: {e}")
        outcomes["ok"] += 1
        assert finite(results), f"case {case} (seed {SEED}): a result holds NaN or infinity"
    # Both outcomes must occur, or the generator tests nothing.
    assert outcomes["ok"] > CASES // 20 and outcomes["refused"] > CASES // 20, outcomes


def test_limit_surface_face_numbers_beyond_32_bits_and_complex_parameters_are_refused():
    """Found by the fuzz test: face numbers were cast to int32 (2**32 + 1 became face 1) and
    complex parameters lost their imaginary part, both without a word."""
    surface = sk.LimitSurface(sk.read_mesh(str(MESHES / "cube.obj")))
    with pytest.raises(sk.Error, match="face number 4294967297 is beyond 32-bit"):
        surface.evaluate(np.array([2**32 + 1], dtype=np.int64), [[0.5, 0.5]])
    with pytest.raises(sk.Error, match="uv: give numbers, got an array of dtype complex128"):
        surface.evaluate([1], np.array([[0.5 + 1j, 0.5]]))
