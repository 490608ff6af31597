"""analyze(): eigen-analysis of surface schemes and symbol analysis of curve schemes."""

from dataclasses import dataclass

import numpy as np

from . import _subdivkit
from ._subdivkit import Error, Scheme
from ._checks import check_whole
from .mesh import _escaped, _type_name


@dataclass
class SurfaceAnalysis:
    """A surface scheme analysed at extraordinary vertices (faces, for dual schemes) of
    several valences, as ``subdiv analyze``.

    Arrays run over ``valences``:

    * ``subdominant`` (lambda_1), ``lambda2``, ``lambda3`` (|lambda_3|): float arrays;
    * ``c1``: bool array, the verdict that the scheme is C1 there (eigenvalue conditions
      and a regular, injective characteristic map); ``verdicts``: the verdicts as text;
    * ``eigenvalues``: one complex array per valence, sorted by modulus (the sizes differ:
      the invariant ring grows with the valence);
    * ``matrices``: the local subdivision matrices S; ``limit_masks`` and
      ``tangent_masks`` (2 rows): left eigenvectors of 1 and of lambda_1, lambda_2;
    * ``details``: everything else per valence, as dicts (checks, rings, curvature note;
      ``crease_eigenvalues`` with ``crease=True``: the spectrum of the crease points' own
      block, the crease curve's local matrix, where their rows read crease points only,
      else empty).
    """
    scheme: str
    valences: np.ndarray
    subdominant: np.ndarray
    lambda2: np.ndarray
    lambda3: np.ndarray
    c1: np.ndarray
    verdicts: list
    eigenvalues: list
    matrices: list
    limit_masks: list
    tangent_masks: list
    details: list

    def spectrum(self, count=8):
        """Moduli of the leading ``count`` eigenvalues per valence, (len(valences), count),
        NaN-padded: the data of a spectrum plot."""
        out = np.full((len(self.valences), count), np.nan)
        for i, values in enumerate(self.eigenvalues):
            moduli = np.abs(values[:count])
            out[i, :len(moduli)] = moduli
        return out

    def __str__(self):
        lines = [f"{_escaped(self.scheme)}: valence  lambda_1    lambda_2    |lambda_3|  verdict"]
        for i, n in enumerate(self.valences):
            lines.append(f"{'':>{len(self.scheme) + 2}}{n:>7}  {self.subdominant[i]:<10.6f}  {self.lambda2[i]:<10.6f}  "
                         f"{self.lambda3[i]:<10.6f}  {self.verdicts[i]}")
        return "\n".join(lines)


@dataclass
class CurveAnalysis:
    """A curve scheme's symbol analysis and local eigen-analysis, as ``subdiv analyze``.

    ``mask`` (coefficients a_first .. a_last, ``mask_first`` the index of the first),
    ``symbol`` (a(z) coefficients from z^symbol_lowest), ``convergent``, ``smoothness`` (the
    largest k with C^k proven, -1 if none), ``eigenvalues`` of the local subdivision matrix
    ``matrix`` (sorted by modulus), ``subdominant``, ``limit_mask`` and ``tangent_mask``
    (left eigenvectors), ``summary`` (the command line's text) and ``details`` (all fields).
    """
    scheme: str
    arity: int
    mask: np.ndarray
    mask_first: int
    symbol: np.ndarray
    symbol_lowest: int
    convergent: bool
    smoothness: int
    eigenvalues: np.ndarray
    subdominant: complex
    matrix: np.ndarray
    limit_mask: np.ndarray
    tangent_mask: np.ndarray
    summary: str
    details: dict

    def __str__(self):
        return self.summary


def _valence_list(valences):
    """The valences as ints; 3.5 or "4" is refused, not rounded."""
    try:
        values = np.atleast_1d(np.asarray(valences)).reshape(-1)
    except (TypeError, ValueError):
        values = None
    if values is None or (values.size and values.dtype.kind not in "iu"):
        raise Error(f"valences={valences!r}: give whole numbers, e.g. range(3, 13)")
    return [check_whole(int(n), "valences", "give whole numbers, e.g. range(3, 13)") for n in values]


def analyze(scheme, valences=range(3, 13), *, boundary=False, crease=False, corner=False,
            boundary_interpolation="edges-and-corners", level=0, max_ring=5, characteristic_map=True):
    """Analyse a scheme's convergence and smoothness.

    Surface schemes (returns SurfaceAnalysis): the local subdivision matrix around a vertex
    of each valence (an n-gon face for dual schemes) is built by the engine's own stencils
    and its eigen-structure checked (Reif 1995): lambda_0 = 1 simple, lambda_1 = lambda_2
    real with two eigenvectors dominating |lambda_3|, and a regular, injective
    characteristic map. ``boundary=True`` analyses boundary vertices instead (valences
    from 2); ``crease=True`` crease vertices (infinitely sharp ring edges 0 and n/2; a crease
    whose two sides do not read each other's points is judged as two boundaries, as
    ``subdiv analyze --crease`` does: docs/analysis.md); ``corner=True`` corner vertices (valences
    from 3; infinitely sharp ring edges 0, n/3 and 2n/3, each of the three sectors judged as a
    boundary vertex tagged as a corner, as ``subdiv analyze --corner``). Dual schemes are analysed at the
    face such a vertex's faces become. ``level`` picks the weights of level-dependent schemes.

    Curve schemes (returns CurveAnalysis; ``valences`` is ignored): the symbol a(z),
    convergence and C^k smoothness by difference schemes, and the local matrix's spectrum.

    ``scheme`` is a Scheme or a name/path for Scheme.load.
    """
    if isinstance(scheme, str):
        scheme = Scheme.load(scheme)
    if not isinstance(scheme, Scheme):
        raise Error(f"analyze: expected a subdivkit.Scheme or a scheme name, got {_type_name(scheme)}")
    result = _subdivkit._analyze(scheme, _valence_list(valences), bool(boundary), bool(crease), bool(corner),
                                 boundary_interpolation,
                                 check_whole(level, "level", "give the whole number of the level whose weights to analyse"),
                                 check_whole(max_ring, "max_ring", "give a whole number of rings"),
                                 bool(characteristic_map))
    if scheme.kind == "curve":
        r = result
        return CurveAnalysis(scheme=r["name"], arity=r["arity"], mask=r["mask"], mask_first=r["mask_first"],
                             symbol=r["symbol"], symbol_lowest=r["symbol_lowest"], convergent=r["convergent"],
                             smoothness=r["smoothness"], eigenvalues=r["eigenvalues"], subdominant=r["subdominant"],
                             matrix=r["matrix"], limit_mask=r["limit_mask"], tangent_mask=r["tangent_mask"],
                             summary=r["summary"], details=r)
    return SurfaceAnalysis(
        scheme=scheme.name,
        valences=np.array([r["valence"] for r in result], dtype=int),
        subdominant=np.array([r["lambda1"] for r in result]),
        lambda2=np.array([r["lambda2"] for r in result]),
        lambda3=np.array([r["lambda3"] for r in result]),
        c1=np.array([r["c1"] for r in result], dtype=bool),
        verdicts=[r["verdict"] for r in result],
        eigenvalues=[r["eigenvalues"] for r in result],
        matrices=[r["matrix"] for r in result],
        limit_masks=[r["limit_mask"] for r in result],
        tangent_masks=[r["tangent_masks"] for r in result],
        details=result)
