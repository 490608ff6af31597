"""stencils(): the subdivision matrices reproduce refine() as products, and have the
properties every subdivision matrix has (rows of affine weights, one row per new point)."""
import numpy as np
import pytest
import scipy.sparse

import subdivkit as sk
from conftest import CURVES, MESHES

CASES = [("cube.obj", "catmull-clark"), ("cube-creased.obj", "catmull-clark"), ("octahedron.obj", "loop"),
         ("octahedron.obj", "butterfly"), ("plane-with-hole.obj", "doo-sabin"), ("octahedron.obj", "sqrt3")]


@pytest.mark.parametrize("mesh_name,scheme", CASES)
def test_each_level_matrix_times_the_points_equals_refine(mesh_name, scheme):
    mesh = sk.read_mesh(MESHES / mesh_name)
    levels = sk.refine(mesh, scheme, 3, all_levels=True)
    matrices = sk.stencils(mesh, scheme, 3)
    assert len(matrices) == 3
    for l, S in enumerate(matrices):
        assert isinstance(S, scipy.sparse.csr_matrix)
        assert S.shape == (levels[l + 1].n_points, levels[l].n_points)
        # refine() evaluates the rules directly; the tables expand new-point terms, so the
        # two agree to round-off, not bit for bit (framework/scheme/refiner.h).
        assert np.abs(S @ levels[l].points - levels[l + 1].points).max() <= 1e-14


@pytest.mark.parametrize("mesh_name,scheme", CASES)
def test_the_composed_matrix_maps_the_input_to_the_finest_level(mesh_name, scheme):
    mesh = sk.read_mesh(MESHES / mesh_name)
    S = sk.stencils(mesh, scheme, 3, composed=True)
    per_level = sk.stencils(mesh, scheme, 3)
    product = per_level[2] @ per_level[1] @ per_level[0]
    assert abs(S - product).max() <= 1e-14
    assert np.abs(S @ mesh.points - sk.refine(mesh, scheme, 3).points).max() <= 1e-14


@pytest.mark.parametrize("mesh_name,scheme", CASES)
def test_rows_are_affine_combinations(mesh_name, scheme):
    # Subdivision commutes with translations only if every row sums to one.
    for S in sk.stencils(sk.read_mesh(MESHES / mesh_name), scheme, 2):
        assert np.abs(np.asarray(S.sum(axis=1)).ravel() - 1).max() <= 1e-14


def test_one_matrix_serves_many_positions():
    cube = sk.read_mesh(MESHES / "cube.obj")
    S = sk.stencils(cube, "catmull-clark", 2, composed=True)
    rng = np.random.default_rng(1)
    moved = cube.points + 0.1 * rng.standard_normal(cube.points.shape)
    assert np.abs(S @ moved - sk.refine(cube.with_points(moved), "catmull-clark", 2).points).max() <= 1e-14


def test_curve_scheme_matrices_refine_polylines():
    square = sk.read_mesh(CURVES / "square.obj")
    S = sk.stencils(square, "chaikin", 4, composed=True)
    assert np.abs(S @ square.points - sk.refine(square, "chaikin", 4).points).max() <= 1e-15


def test_zero_levels_composed_is_the_identity():
    cube = sk.read_mesh(MESHES / "cube.obj")
    assert (sk.stencils(cube, "catmull-clark", 0, composed=True) != scipy.sparse.identity(8)).nnz == 0
