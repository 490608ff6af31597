"""The exact limit surface at any (face, u, v): subdivkit.evaluate and subdivkit.LimitSurface.

The same evaluation as ``subdiv evaluate`` (docs/limit.md), through the library's pipeline:
positions with first and second derivatives, exact to round-off (no approximation near
extraordinary vertices), in OpenSubdiv Bfr's parameterisation, and the same points as limit
stencils (weights over the control points) for cheap re-evaluation.
"""

import warnings
from dataclasses import dataclass

import numpy as np

from . import _subdivkit
from ._subdivkit import Error, Scheme
from ._checks import check_mesh, check_progress, check_threads, check_whole
from .mesh import Mesh, _as_array, _data_shapes_like, _face_varying_triples
from .refinement import _scipy_sparse


def _check_order(derivatives):
    if isinstance(derivatives, bool) or not isinstance(derivatives, (int, np.integer)) or not 0 <= derivatives <= 2:
        raise Error(f"derivatives={derivatives!r}: give 0 (positions), 1 (also du, dv) or 2 (also duu, duv, dvv)")
    return int(derivatives)


def _points(faces, uv):
    """(n,) int32 faces and (n, 2) float64 parameters; a single point may be given as a
    scalar face and a pair."""
    f = _as_array(faces, "faces", "an (n,) array of face numbers")
    if f.size and f.dtype.kind not in "iu":
        raise Error(f"faces: give an int array of face numbers, got dtype {f.dtype}")
    # Checked before the cast to int32, which would wrap 2**32 + 1 to face 1 without a word.
    if f.size and (int(f.min()) < -2**31 or int(f.max()) >= 2**31):
        raise Error(f"faces: face number {int(f.max()) if int(f.max()) >= 2**31 else int(f.min())} is beyond "
                    "32-bit face numbers")
    f = np.ascontiguousarray(np.atleast_1d(f), dtype=np.int32)
    u = _as_array(uv, "uv", "an (n, 2) array: one row (u, v) per point")
    if u.size and u.dtype.kind not in "fiu":  # complex parameters would lose their imaginary part
        raise Error(f"uv: give numbers, got an array of dtype {u.dtype}")
    p = np.ascontiguousarray(u, dtype=np.float64)
    if p.ndim == 1 and p.shape == (2,) and f.shape == (1,):
        p = p.reshape(1, 2)
    if f.shape == (0,) and p.shape == (0,):  # evaluate([], []): no points, as an empty (0, 2) uv
        p = p.reshape(0, 2)
    if f.ndim != 1 or p.ndim != 2 or p.shape[1] != 2 or p.shape[0] != f.shape[0]:
        raise Error(f"faces {tuple(f.shape)} and uv {tuple(p.shape)}: give n faces and an (n, 2) array of (u, v)")
    return f, p


def _sampled_mesh(method, r, name):
    """The Mesh of a tessellation's arrays, after warning (UserWarning) where its Normals are
    (0, 0, 0): sample points where the surface has no normal."""
    for warning in r["warnings"]:
        warnings.warn(f"{method}: {warning}", UserWarning, stacklevel=3)
    return Mesh._from_arrays(r, name=name, point_data=_data_shapes_like(r["point_data"], {}),
                             cell_data=_data_shapes_like(r["cell_data"], {}), face_varying=r["face_varying"],
                             point_roles=r["point_roles"], cell_roles=r["cell_roles"])


@dataclass
class LimitEvaluation:
    """Points of the limit surface (evaluate's result), one row per (face, u, v).

    ``points`` (n, k): the limit of the control points' columns (positions: k = 3);
    ``du``, ``dv`` (n, k): derivatives along the face's u and v (with ``derivatives`` >= 1);
    ``duu``, ``duv``, ``dvv`` (n, k): second derivatives (with ``derivatives`` = 2). NaN where
    a derivative does not exist: first and second at an extraordinary vertex itself (the
    parameterisation is singular there), second derivatives where the scheme is not C2
    (everywhere for the butterflies; for mid-edge schemes on the knot lines of their
    four-direction box spline, docs/limit.md). Unrequested orders are None.
    """
    points: np.ndarray
    du: np.ndarray | None = None
    dv: np.ndarray | None = None
    duu: np.ndarray | None = None
    duv: np.ndarray | None = None
    dvv: np.ndarray | None = None


@dataclass
class LimitStencils:
    """Limit stencils (LimitSurface.stencils' result): scipy.sparse CSR matrices with one row
    per (face, u, v) and one column per vertex of the mesh, so that ``points @ P`` (and
    ``du @ P``, ...) is the limit for control points P. A row is empty where the derivative
    does not exist (``has_first``, ``has_second`` say where it does)."""
    points: object
    du: object = None
    dv: object = None
    duu: object = None
    duv: object = None
    dvv: object = None
    has_first: np.ndarray | None = None
    has_second: np.ndarray | None = None


class LimitSurface:
    """A mesh's limit surface prepared once, to evaluate at any number of (face, u, v).

    ``LimitSurface(mesh, scheme)`` loads the scheme and the mesh as refine() does (its
    creases, corners and option tags, ``boundary``, ``crease_method``) and checks that the
    scheme can be evaluated: a stationary linear scheme with the binary quad or triangle
    split (Catmull-Clark, Loop, the butterflies, bilinear, composite split + averaging
    schemes, JSON schemes of that kind) on any mesh, non-manifold ones included; with the
    dual split (Doo-Sabin, even-degree quad B-splines: the quad split's (u, v) read as nested
    quadrants), the √3 or the mid-edge split, or a plugin's split that scales faces, where
    docs/limit.md's table "What is supported" says; or a sequence "A:k,B" (B's limit over the
    mesh A makes). Others raise subdivkit.Error saying why (non-linear and level-dependent
    rules, a boundary, crease or non-manifold element a split does not take yet). Running out
    of memory part-way raises MemoryError naming the argument to lower (samples, the number of
    points, derivatives). The mesh's face-varying arrays (UVs) are evaluated with
    ``evaluate_face_varying``, in the linear-interpolation mode ``fvar_boundary`` ("none",
    "corners-only", "corners-plus1", "corners-plus2", "boundaries", "all"), as refine().

    The parameters are OpenSubdiv Bfr's: a quad's corners at (0,0), (1,0), (1,1), (0,1); a
    triangle's at (0,0), (1,0), (0,1); another face of a quad scheme is n sub-quads
    (Bfr's QUAD_SUBFACES, docs/limit.md).

    What is learnt about the mesh is kept between calls, so later calls are faster; calls
    release the GIL and may run from several Python threads at once.

    The mesh is copied when the surface is made: changing the Mesh afterwards (its points,
    faces or tags) does not change the surface. Evaluate other positions with
    ``evaluate(points=...)``; for another topology make a new LimitSurface. It cannot be
    pickled or copied (it holds the prepared native surface): pickle the Mesh, which can be,
    and make the LimitSurface again where it is needed.

    Examples
    --------
    >>> S = sk.LimitSurface(cube, "catmull-clark")
    >>> r = S.evaluate([0, 3], [[0.5, 0.5], [0.1, 0.2]], derivatives=2)
    >>> r.points.shape, r.duu.shape                 # (2, 3) (2, 3)
    >>> W = S.stencils([0, 3], [[0.5, 0.5], [0.1, 0.2]])
    >>> W.points @ cube.points                      # the same points, from weights
    """

    def __init__(self, mesh, scheme="catmull-clark", *, params=None, boundary="edges-and-corners",
                 crease_method="uniform", feature_angle=-1.0, fvar_boundary="all"):
        check_mesh(mesh, "LimitSurface")
        self._prepared = _subdivkit._prepare_limit_surface(mesh, scheme, params, str(boundary), str(crease_method),
                                                           float(feature_angle), _face_varying_triples(mesh),
                                                           str(fvar_boundary))
        self.name = mesh.name
        self.scheme = scheme.name if isinstance(scheme, Scheme) else str(scheme)

    def __reduce__(self):
        raise TypeError("a LimitSurface cannot be pickled or copied: it holds the prepared native surface; "
                        "pickle its Mesh instead and make LimitSurface(mesh, scheme) again where it is needed")

    @property
    def triangles(self):
        """True when the scheme's split makes triangles (faces are parameterised as triangles)."""
        return self._prepared.triangles

    @property
    def n_points(self):
        """The number of control points (rows ``evaluate(points=...)`` takes)."""
        return self._prepared.vertex_count

    @property
    def n_faces(self):
        return self._prepared.face_count

    @property
    def face_varying(self):
        """The names of the mesh's face-varying arrays (``mesh.face_varying``) that
        evaluate_face_varying evaluates (normals are not)."""
        return list(self._prepared.face_varying)

    def evaluate(self, faces, uv, derivatives=1, *, points=None, threads=0):
        """The limit at (faces[i], uv[i]): a LimitEvaluation.

        faces : (n,) int array; uv : (n, 2) float array of (u, v) in each face's domain.
        derivatives : 0 positions only, 1 also du and dv, 2 also duu, duv, dvv.
        points : (n_points, k) control values to evaluate instead of the mesh's points (new
            positions of an animation, colours, ...); the evaluation is linear in them.
        threads : worker threads, 0 for all cores.

        Raises subdivkit.Error naming the first bad point ("point i (face f, u, v): why") —
        a face that does not exist, a hole, (u, v) outside the face's domain — or the first
        non-finite value of ``points`` ("vertex i has a non-finite value"), before anything is
        evaluated. A scheme that converges but is not C1 where the mesh is regular (its
        subdominant eigenvalues there are not the parameters' scale per step: 1/2 for binary
        splits and plugins' splits scaling by 2, 1/3 per double √3 step) has no derivatives:
        ``derivatives`` >= 1 raises subdivkit.Error saying so (and tessellate(), whose
        normals need them, too); ``derivatives=0`` evaluates the positions.
        """
        order = _check_order(derivatives)
        f, p = _points(faces, uv)
        values, channels = None, 3
        if points is not None:
            given = _as_array(points, "points", "one row of values per control point")
            if given.size and given.dtype.kind not in "fiu":  # as uv: strings, objects, complex
                raise Error(f"points: give numbers, got an array of dtype {given.dtype}")
            values = np.ascontiguousarray(given, dtype=np.float64)
            if values.ndim == 1:
                values = values.reshape(-1, 1)
            if values.ndim != 2 or values.shape[0] != self.n_points:
                raise Error(f"points {tuple(values.shape)}: give one row per control point ({self.n_points} rows)")
            if values.shape[1] == 0:  # no columns: the native side would read the mesh's points instead
                raise Error(f"points {tuple(values.shape)}: give at least one column of values per control point")
            channels = values.shape[1]
        r = self._prepared.evaluate(f, p, order, values, channels, check_threads(threads))
        return LimitEvaluation(points=r["points"], du=r.get("du"), dv=r.get("dv"), duu=r.get("duu"),
                               duv=r.get("duv"), dvv=r.get("dvv"))

    def evaluate_face_varying(self, name, faces, uv, derivatives=1, *, threads=0):
        """Face-varying array ``name`` (UVs with seams) at the same (faces[i], uv[i]): a
        LimitEvaluation with (n, k) arrays, k the array's columns.

        The array's limit is OpenSubdiv's face-varying surface (Bfr's InitFaceVaryingSurface)
        in the mode ``fvar_boundary`` chose: "all" (the default, as OpenSubdiv's) bilinear in
        each face; "none" ... "boundaries" the scheme's limit of the values, seams and the
        mode's corners kept sharp (docs/primvars.md). Arguments as evaluate().
        """
        order = _check_order(derivatives)
        f, p = _points(faces, uv)
        r = self._prepared.evaluate_face_varying(str(name), f, p, order, check_threads(threads))
        return LimitEvaluation(points=r["points"], du=r.get("du"), dv=r.get("dv"), duu=r.get("duu"),
                               duv=r.get("duv"), dvv=r.get("dvv"))

    def tessellate(self, samples=4, *, threads=0, progress=None):
        """The limit surface as a crack-free Mesh, as ``subdiv evaluate --samples N`` writes it.

        samples : segments per face edge, 1 to 1024 as ``--samples``: a quad becomes
            samples x samples quads, a triangle of a triangle scheme samples² triangles,
            another face of a quad scheme its sub-faces of samples/2 x samples/2 (then
            samples must be even).
        threads : worker threads, 0 for all cores.
        progress : called as ``progress(phase, done)`` on the calling thread, as for
            refine(): ``done`` is None when the phase starts ("sampling the limit surface,
            8 x 8 per face", the phase ``subdiv evaluate --samples`` shows a bar for), then
            the share done, 0 to 1. An exception it raises stops the sampling and comes
            back from here.

        Points on a base vertex or edge are evaluated once and shared, so a closed mesh
        gives a closed surface. point_data: "Normals" (the unit limit normal, role
        "normals"), "base_face" and "uv" (the face and (u, v) each point was evaluated at);
        cell_data: "base_face". The mesh's face-varying arrays come back in face_varying,
        sampled at every corner in the mode ``fvar_boundary`` chose, split at their seams.
        A mesh with rational weights is sampled as the rational surface. Where the surface
        has no normal (its tangents parallel or zero: coincident control points, a surface
        folded flat) "Normals" is (0, 0, 0) and a UserWarning says how many such points
        there are and the first one's face and (u, v).
        """
        check_progress(progress, "tessellate")
        r = self._prepared.tessellate(check_whole(samples, "samples", "give a whole number of segments per face edge"),
                                      check_threads(threads), progress)
        return _sampled_mesh("tessellate", r, self.name)

    def approximate_bezier(self, samples=4, *, threads=0):
        """Loop & Schaefer's (2008) bicubic patches tessellated, as ``subdiv evaluate
        --approximate bezier --samples N`` writes them (docs/limit.md).

        One patch per quad of a manifold mesh, for a scheme whose limit over regular quads
        is the bicubic B-spline (else subdivkit.Error says why); faces that are not quads and
        semi-sharp creases and corners are read on the level where every face is a quad and
        the tags have decayed (one step, or ceil(sharpness) steps), one patch per face there;
        boundaries and infinitely sharp creases where the scheme's are the cubic B-spline's
        (a crease with one face on a side is refused, naming the place); darts take the
        smooth vertex's masks. Exact where every corner is regular (valence 4 inside, two
        faces on each side of a boundary or crease, a corner of one face). point_data:
        "Normals" (of the tangent patches: continuous across edges),
        "base_face", "uv", "limit_distance" (to the exact limit at the same (face, u, v));
        cell_data: "base_face", "limit_distance" (the largest over the base face's samples).
        Normals (0, 0, 0) with a UserWarning where the patches have none, as tessellate's.
        """
        r = self._prepared.approximate_bezier(check_whole(samples, "samples", "give a whole number of segments per face edge"), check_threads(threads))
        return _sampled_mesh("approximate_bezier", r, self.name)

    def approximate_gregory(self, samples=4, *, threads=0):
        """Loop, Schaefer, Ni & Castaño's (2009) bicubic Gregory patches tessellated, as
        ``subdiv evaluate --approximate gregory --samples N`` writes them (docs/limit.md).

        One patch per quad of a manifold mesh, for a scheme whose limit over regular
        quads is the bicubic B-spline (else subdivkit.Error says why); faces that are not
        quads, semi-sharp tags, boundaries and infinitely sharp creases as approximate_bezier
        covers them (a crease with one face on a side is refused, naming the place); darts
        take the smooth vertex's masks. Exact where every corner is regular; elsewhere the patches meet with one normal across every edge that
        is not a crease (G1) and their corners are the limit's positions and tangent planes. point_data: "Normals"
        (the patches' own), "base_face", "uv", "limit_distance" (to the exact limit at the
        same (face, u, v)); cell_data: "base_face", "limit_distance" (the largest over the
        base face's samples). Normals (0, 0, 0) with a UserWarning where the patches have
        none, as tessellate's.
        """
        r = self._prepared.approximate_gregory(check_whole(samples, "samples", "give a whole number of segments per face edge"), check_threads(threads))
        return _sampled_mesh("approximate_gregory", r, self.name)

    def stencils(self, faces, uv, derivatives=1, *, threads=0):
        """The same points as weights over the control points: a LimitStencils of
        scipy.sparse CSR matrices (needs SciPy), ``W.points @ P == evaluate(..., points=P).points``
        to round-off for any P. Arguments as evaluate()."""
        order = _check_order(derivatives)
        f, p = _points(faces, uv)
        r = self._prepared.stencils(f, p, order, check_threads(threads))
        sparse = _scipy_sparse()

        def matrix(name):
            t = r.get(name)
            return None if t is None else sparse.csr_matrix((t["data"], t["indices"], t["indptr"]), shape=t["shape"])

        return LimitStencils(points=matrix("points"), du=matrix("du"), dv=matrix("dv"), duu=matrix("duu"),
                             duv=matrix("duv"), dvv=matrix("dvv"), has_first=r["has_first"].astype(bool),
                             has_second=r["has_second"].astype(bool))


def evaluate(mesh, scheme="catmull-clark", faces=(), uv=(), derivatives=1, *, params=None,
             boundary="edges-and-corners", crease_method="uniform", threads=0):
    """Points of the exact limit surface at (faces[i], uv[i]): a LimitEvaluation.

    ``evaluate(mesh, scheme, faces, uv, derivatives=1)`` is
    ``LimitSurface(mesh, scheme, ...).evaluate(faces, uv, derivatives)``; use a LimitSurface
    to evaluate the same mesh more than once. The result's ``points`` (n, 3), ``du``, ``dv``
    and with ``derivatives=2`` ``duu``, ``duv``, ``dvv`` are NaN where the derivative does not
    exist. The same numbers as ``subdiv evaluate --at``.
    """
    return LimitSurface(mesh, scheme, params=params, boundary=boundary,
                        crease_method=crease_method).evaluate(faces, uv, derivatives, threads=threads)
