"""The subdivkit API used with full type annotations: `mypy --strict` checks this file
against the package's stubs (tests/install/typing_test.sh), and running it checks that
what the stubs promise holds at run time (dtypes, shapes, return kinds).

    PYTHONPATH=build/python /usr/bin/python3 tests/install/typed_usage.py examples/meshes/cube.obj
"""
import sys

import numpy as np
import numpy.typing as npt

import subdivkit as sk


def catmull_clark_counts(mesh: sk.Mesh, levels: int) -> tuple[int, int]:
    """Vertices and faces after `levels` Catmull-Clark steps on a closed quad mesh: each step
    makes V + E + F vertices and 4F quads, and E becomes 2E + 4F (Catmull & Clark 1978)."""
    v, f = mesh.n_points, mesh.n_faces
    e = (v + f - 2)  # Euler's formula for a closed genus-0 mesh: V - E + F = 2
    for _ in range(levels):
        v, e, f = v + e + f, 2 * e + 4 * f, 4 * f
    return v, f


def check(path: str) -> None:
    cube: sk.Mesh = sk.read_mesh(path)
    points: npt.NDArray[np.float64] = cube.points
    assert points.dtype == np.float64 and points.shape == (cube.n_points, 3)

    fine: sk.Mesh = sk.refine(cube, "catmull-clark", 2)
    assert (fine.n_points, fine.n_faces) == catmull_clark_counts(cube, 2)
    faces: npt.NDArray[np.int32] = fine.faces
    assert faces.dtype == np.int32 and faces.shape == (fine.n_faces, 4)
    levels: list[sk.Mesh] = sk.refine(cube, "catmull-clark", 2, all_levels=True)
    assert [m.n_faces for m in levels] == [6, 24, 96]

    # The same points three ways: refine, the Evaluator, and the composed stencil matrix.
    evaluator = sk.Evaluator(cube, "catmull-clark", 2)
    moved: npt.NDArray[np.float64] = cube.points * 2.0 + 1.0
    by_evaluator: npt.NDArray[np.float64] = evaluator.evaluate(moved)
    by_refine = sk.refine(cube.with_points(moved), "catmull-clark", 2).points
    assert np.array_equal(by_evaluator, by_refine)
    # Affine invariance: refining an affine image of the mesh is the affine image of the result.
    assert np.allclose(by_evaluator, fine.points * 2.0 + 1.0, atol=1e-12)

    loop: sk.Scheme = sk.Scheme.load("loop")
    params: dict[str, float | str] = loop.parameters
    assert loop.kind == "surface" and isinstance(params, dict)

    limit: sk.LimitPoints = sk.limit_positions(cube, "catmull-clark")
    assert limit.normals is not None and limit.normals.shape == (cube.n_points, 3)

    analysis = sk.analyze("catmull-clark", [3, 5])
    assert isinstance(analysis, sk.SurfaceAnalysis)
    # Catmull-Clark's subdominant eigenvalue at valence n (Doo & Sabin 1978):
    # lambda_1 = (5 + cos(2 pi/n) + cos(pi/n) sqrt(2 (9 + cos(2 pi/n)))) / 16.
    n = analysis.valences.astype(float)
    c = np.cos(2 * np.pi / n)
    expected = (5 + c + np.cos(np.pi / n) * np.sqrt(2 * (9 + c))) / 16
    assert np.allclose(analysis.subdominant, expected, atol=1e-12), (analysis.subdominant, expected)

    # The limit at a face's corner is the corner vertex's limit position.
    surface: sk.LimitSurface = sk.LimitSurface(cube, "catmull-clark")
    corner: sk.LimitEvaluation = surface.evaluate(np.array([0], dtype=np.int32), np.array([[0.0, 0.0]]), 2)
    first = int(cube.face_indices[0])
    assert np.allclose(corner.points[0], limit.points[first], atol=1e-12)
    assert corner.duu is not None and bool(np.isnan(corner.duu).all())  # none at a valence-3 vertex

    try:
        sk.Scheme.load("no-such-scheme")
    except sk.Error as e:
        message: str = str(e)
        assert "no-such-scheme" in message
    else:
        raise AssertionError("an unknown scheme must raise subdivkit.Error")
    print(f"typed_usage.py: ok ({fine.n_points} points, {fine.n_faces} faces at level 2)")


if __name__ == "__main__":
    check(sys.argv[1])
