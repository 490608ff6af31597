"""analyze() against closed forms from the literature (docs/references.md)."""
import numpy as np
import pytest

import subdivkit as sk

VALENCES = np.arange(3, 13)


def catmull_clark_subdominant(n):
    """Halstead, Kass & DeRose 1993: lambda = (4 + A_n)/16,
    A_n = 1 + cos(2 pi/n) + cos(pi/n) sqrt(2 (9 + cos(2 pi/n)))."""
    c = np.cos(2 * np.pi / n)
    return (4 + 1 + c + np.cos(np.pi / n) * np.sqrt(2 * (9 + c))) / 16


def test_catmull_clark_subdominant_eigenvalue_is_the_closed_form():
    a = sk.analyze("catmull-clark", valences=range(3, 13))
    assert list(a.valences) == list(VALENCES)
    expected = catmull_clark_subdominant(VALENCES)
    assert np.abs(a.subdominant - expected).max() <= 1e-10
    assert np.abs(a.lambda2 - expected).max() <= 1e-10  # a double eigenvalue
    assert a.c1.all()
    for values in a.eigenvalues:
        assert abs(values[0] - 1) <= 1e-12  # affine invariance
        assert abs(values[1]) == pytest.approx(abs(values[2]))


def test_loop_subdominant_eigenvalue_is_three_eighths_plus_a_quarter_cosine():
    # Loop 1987: the edge rule gives lambda_1 = 3/8 + cos(2 pi/n)/4 for every valence.
    a = sk.analyze("loop", valences=VALENCES)
    assert np.abs(a.subdominant - (3 / 8 + np.cos(2 * np.pi / VALENCES) / 4)).max() <= 1e-10


def test_limit_masks_are_left_eigenvectors_of_one():
    a = sk.analyze("catmull-clark", valences=[4])
    mask = a.limit_masks[0]
    assert mask.sum() == pytest.approx(1, abs=1e-12)
    # The bicubic B-spline's limit point: 4/9 on the vertex, 1/9 on its 4 edge neighbours,
    # 1/36 on its 4 diagonal neighbours.
    nonzero = np.sort(mask[np.abs(mask) > 1e-12])
    assert np.allclose(nonzero, sorted([4 / 9] + [1 / 9] * 4 + [1 / 36] * 4), atol=1e-12)
    # Tangent masks annihilate constants (two rows).
    assert a.tangent_masks[0].shape[0] == 2
    assert np.abs(a.tangent_masks[0].sum(axis=1)).max() <= 1e-12


def test_spectrum_is_a_padded_array_of_moduli():
    a = sk.analyze("catmull-clark", valences=[3, 5])
    s = a.spectrum(6)
    assert s.shape == (2, 6)
    assert s[:, 0] == pytest.approx([1, 1])
    assert s[:, 1] == pytest.approx(catmull_clark_subdominant(np.array([3, 5])))


def test_curve_schemes_give_their_symbol_and_spectrum():
    b = sk.analyze("cubic-bspline")
    assert isinstance(b, sk.CurveAnalysis)
    # Mask (1, 4, 6, 4, 1)/8 on -2..2; C2; eigenvalues 1, 1/2, 1/4, 1/8, 1/8 (Zorin et al. 2000).
    assert b.mask_first == -2 and np.allclose(b.mask, np.array([1, 4, 6, 4, 1]) / 8)
    assert b.convergent and b.smoothness == 2
    assert np.allclose(np.sort(np.abs(b.eigenvalues))[::-1], [1, 1 / 2, 1 / 4, 1 / 8, 1 / 8])
    assert np.allclose(b.limit_mask[np.abs(b.limit_mask) > 1e-12], [1 / 6, 4 / 6, 1 / 6])
    fp = sk.analyze(sk.Scheme.load("four-point", w=1 / 16))
    assert fp.convergent and fp.smoothness == 1  # C1, not C2 (Dyn, Levin, Gregory 1987)


def test_a_scheme_that_fails_says_why():
    # Bilinear subdivision keeps the control mesh (piecewise linear): at a vertex of valence
    # n the eigenvalue 1/2 has multiplicity n (every ring edge is its own linear piece), so
    # the subdominant pair does not dominate and there is no tangent plane.
    a = sk.analyze("bilinear", valences=[3, 5])
    assert not a.c1.any()
    assert np.allclose(a.subdominant, 0.5) and np.allclose(a.lambda3, 0.5)
    assert all(v.startswith("fails:") and "multiplicity" in v for v in a.verdicts)


def test_crease_analysis_judges_each_side_as_a_boundary():
    # A crease of valence n with sharp ring edges 0 and n/2 splits the ring into two sides of
    # n/2 faces; where the sides' rows do not read each other (Catmull-Clark), each side is the
    # boundary of valence n/2 + 1 (docs/analysis.md), so the spectra agree. The regular crease
    # (n = 4) is the cubic B-spline's: subdominant eigenvalue 1/2; Loop's regular crease too.
    crease = sk.analyze("catmull-clark", [4, 6, 8], crease=True)
    boundary = sk.analyze("catmull-clark", [3, 4, 5], boundary=True)
    assert np.allclose(crease.subdominant, boundary.subdominant, atol=1e-12)
    assert abs(crease.subdominant[0] - 0.5) < 1e-12 and bool(crease.c1[0])
    loop = sk.analyze("loop", [6], crease=True)
    assert abs(loop.subdominant[0] - 0.5) < 1e-12 and bool(loop.c1[0])
    with pytest.raises(sk.Error):
        sk.analyze("catmull-clark", [4], crease=True, boundary=True)


def test_corner_analysis_judges_each_sector_as_a_boundary_corner():
    # Three sharp ring edges at 0, n/3, 2n/3: the crease points are three cubic B-spline
    # curves ending at the kept corner (1 once, 1/2 three times); sectors of one face are the
    # regular corner patch, C1 (docs/analysis.md, "Corners").
    a = sk.analyze("catmull-clark", [3, 6], corner=True)
    assert bool(a.c1[0]) and "3 sectors" in a.verdicts[0]
    for details in a.details:
        crease = details["crease_eigenvalues"]
        assert np.allclose(crease[:4], [1, 0.5, 0.5, 0.5], atol=1e-9)
    with pytest.raises(sk.Error, match="valence 3 or more"):
        sk.analyze("catmull-clark", [2], corner=True)
    with pytest.raises(sk.Error):
        sk.analyze("catmull-clark", [4], corner=True, crease=True)


def test_dual_crease_points_refine_by_chaikins_rule():
    # Doo-Sabin's crease points follow Chaikin's curve (docs/features.md): their own local
    # matrix has the quadratic B-spline's eigenvalues 1, 1/2, 1/4 (Chaikin 1974), then smaller.
    a = sk.analyze("doo-sabin", [4, 6], crease=True)
    for details in a.details:
        crease = details["crease_eigenvalues"]
        assert np.allclose(crease[:3], [1, 0.5, 0.25], atol=1e-9)
        assert np.all(np.abs(crease[3:]) <= 0.25 + 1e-9)
    assert sk.analyze("doo-sabin", [4]).details[0]["crease_eigenvalues"].size == 0
