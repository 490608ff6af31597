"""Refinement, stencil matrices, limit points and progressive interpolation."""

import warnings
from dataclasses import dataclass, field

import numpy as np

from . import _subdivkit
from ._subdivkit import Error, Scheme
from .mesh import _ARRAYS as _MESH_ARRAYS
from ._checks import check_mesh, check_progress, check_threads, check_whole
from .mesh import Mesh, _data_arrays, _data_shapes_like, _face_varying_triples, _escaped, _quoted

BOUNDARY_MODES = ("edges-and-corners", "edges", "none")


def _check_levels(levels):
    return check_whole(levels, "levels", "give a whole number of levels")


def _check_start_level(start_level):
    return check_whole(start_level, "start_level", "give the whole number of the mesh's level (0: a base mesh)")
    return progress


def _with_weights(mesh, weights):
    """The point data with ``weights`` (an array, or a point_data name) as the array "weight"."""
    point_data, roles = dict(mesh.point_data or {}), dict(mesh.point_roles or {})
    if weights is None:
        return point_data, roles
    if isinstance(weights, str):
        if weights not in point_data:
            raise Error(f"weights={weights!r}: the mesh has no point_data array of that name "
                        f"(it has {', '.join(map(repr, point_data)) or 'none'})")
        weights = point_data.pop(weights)
    w = np.asarray(weights, dtype=np.float64).reshape(-1)
    if w.shape[0] != mesh.n_points:
        raise Error(f"weights: expected one weight per point ({mesh.n_points}), got {w.shape[0]}")
    point_data["weight"] = w
    roles.pop("weight", None)
    return point_data, roles


def refine(mesh, scheme="catmull-clark", levels=1, *, params=None, boundary="edges-and-corners",
           crease_method="uniform", threads=0, all_levels=False, start_level=0, fvar_boundary="all", weights=None,
           arrays="none", progress=None):
    """Refine a mesh ``levels`` times with a scheme; return the finest level as a Mesh.

    Parameters
    ----------
    mesh : Mesh
        Polygons for a surface scheme, polylines for a curve scheme.
    scheme : Scheme, str or os.PathLike
        A Scheme, a built-in name, a .json path, or a sequence "A:1,B:3" (A for one level,
        then B; a name without ":N" takes the rest of ``levels``), as ``--scheme``.
    levels : int
        Refinement steps, 0 to 30.
    params : dict, optional
        Parameter values, as ``--param``: for a Scheme they replace its own; for a
        sequence they go to every scheme that has the parameter, e.g.
        ``refine(mesh, "catmull-clark-shape:1,catmull-clark", 3, params={"lambda": 0.8})``.
    boundary : str
        'edges-and-corners' (boundary corners stay; the default), 'edges' or 'none', as
        OpenSubdiv's boundary interpolation.
    crease_method : str
        How semi-sharp creases decay: 'uniform' or 'chaikin'.
    threads : int
        Worker threads, 0 for all cores. Results are the same bits for any count.
    all_levels : bool
        Return the list of every level, the input first, instead of the finest.
    start_level : int
        How many steps made the input already (sqrt3's alternating boundary rule and
        level-dependent formulas count from the original mesh).
    fvar_boundary : str
        How face-varying data (``mesh.face_varying``, e.g. UVs with seams) is refined, as
        OpenSubdiv's FVarLinearInterpolation: 'none', 'corners-only', 'corners-plus1',
        'corners-plus2', 'boundaries' or 'all' (OpenSubdiv's default), as ``--fvar-boundary``.
    weights : array_like or str, optional
        Rational subdivision (docs/rational.md): one weight w > 0 per point, or the name of
        the point_data array holding them. The scheme refines the homogeneous points
        (w*p, w) and the result's points are projected back; the refined weights come back
        as point_data "weight". Without it, a point_data array named "weight" (read_mesh
        gives OBJ's ``v x y z w`` so) is used, if any. With all weights 1 the points are the
        plain refinement's, bit for bit.
    arrays : str
        SubdivKit's own arrays added to each level, as ``subdiv refine --arrays`` writes
        them to .vtp: "none" (the default), "all", "default" or a comma list of names.
        point_data gets "origin" (what each point was made from: 0 an old vertex, 1 an
        edge, 2 a face, 3 a face corner of a dual scheme), "valence", "level" and "vertex_class" (0 smooth, 1 dart, 2
        crease, 3 corner); cell_data gets "parent_face" (the face of the level above) and
        "base_face" (the input face each face lies in, -1 for faces a dual split makes
        around edges and vertices). "sharpness", "cell_kind" and "corner_sharpness" are
        how a .vtp file holds creases and corners; a Mesh holds them in ``creases``,
        ``crease_sharpness``, ``corners`` and ``corner_sharpness``, so they add nothing
        here. A user array of the same name is kept instead.
    progress : callable, optional
        Called as ``progress(phase, done)`` on the calling thread: ``done`` is None when a
        phase starts ("level 2/3: 768 faces"), then the share of the levels' work done, 0 to
        1 (levels weighed by their faces), after each level and within it after each pass
        and each kind of new point, as ``subdiv refine``'s bar shows it. An exception
        it raises stops the refinement and comes back from refine().

    The mesh's float point_data is refined with the same rules as the points (any number
    of columns), in the same pass; integer point_data (labels) is taken by origin, never
    averaged; arrays whose ``point_roles`` entry is "normals" (and a face-varying "normal")
    are left out with a UserWarning. cell_data follows each face into its children (the
    faces a dual split makes around vertices and across edges take the value of their
    first corner's face). Every split carries face_varying data, sqrt3 and mid-edge included
    (docs/primvars.md says how). The roles come back with the arrays. Crease sharpness
    decays per level as in OpenSubdiv. The GIL is released while the engine works.
    """
    check_mesh(mesh, "refine")
    levels = _check_levels(levels)
    check_progress(progress, "refine")
    point_data, point_roles = _with_weights(mesh, weights)
    refined = _subdivkit._refine(mesh, scheme, params, levels, boundary, crease_method, check_threads(threads), bool(all_levels),
                                 _check_start_level(start_level),
                                 _data_arrays(point_data, point_roles, mesh.n_points, "point data"),
                                 _data_arrays(mesh.cell_data, mesh.cell_roles, mesh.n_faces, "cell data"),
                                 _face_varying_triples(mesh), str(fvar_boundary), str(arrays), progress)
    for warning in refined[0]["warnings"] if refined else []:
        warnings.warn(f"refine: {warning}", UserWarning, stacklevel=2)
    if refined and refined[0]["dropped"]:
        warnings.warn(f"refine: {', '.join(repr(n) for n in refined[0]['dropped'])} hold(s) normals, which refinement "
                      "does not carry (a mix of unit normals is no normal); limit_positions() gives the exact limit "
                      "normals", UserWarning, stacklevel=2)
    meshes = [Mesh._from_arrays(level, name=mesh.name,
                                point_data=_data_shapes_like(level["point_data"], point_data),
                                cell_data=_data_shapes_like(level["cell_data"], mesh.cell_data),
                                face_varying=level["face_varying"], point_roles=level["point_roles"],
                                cell_roles=level["cell_roles"])
              for level in refined]
    return meshes if all_levels else meshes[-1]


class Evaluator:
    """A mesh's refinement prepared once, to evaluate for many point sets.

    ``Evaluator(mesh, scheme, levels)`` refines the topology of ``mesh`` once and makes every
    step ready (weight tables, per-vertex rules, creases and corners, the order of the
    work); each ``evaluate(points)`` then only computes points, level after level. Use it
    when the connectivity stays and the points move: animation frames, interactive editing,
    fitting. ``evaluate(p)`` gives the same bits as
    ``refine(mesh.with_points(p), scheme, levels, ...).points`` with the same arguments, for
    any thread count, without building a matrix (``stencils`` does that).

    Parameters
    ----------
    mesh : Mesh
        Polygons for a surface scheme; its faces, creases and corners (with their
        sharpness) are refined once. Its point_data, cell_data and face_varying data are not
        carried (``evaluate`` carries any per-point array).
    scheme : Scheme, str or os.PathLike
        A surface Scheme, a built-in name, a .json path, or a sequence "A:1,B:3", as in
        refine(). Curve schemes are refused: ``stencils(..., composed=True)`` serves polylines.
    levels : int
        Refinement steps, 0 to 30.
    params, boundary, crease_method, start_level
        As in refine().
    threads : int
        Worker threads for the preparation and every ``evaluate``, 0 for all cores.

    Raises subdivkit.Error as refine() does for bad meshes, schemes and options.

    Examples
    --------
    >>> ev = sk.Evaluator(cube, "catmull-clark", 3)
    >>> for frame in frames:                      # each (8, 3): the cube's points, moved
    ...     fine = ev.evaluate(frame)             # (386, 3)
    >>> ev.mesh(frames[0])                        # the finest level as a Mesh

    ``evaluate`` takes any number of columns (positions, colours, several frames side by
    side: the rules are linear, so each column is refined on its own) and releases the GIL,
    so frames can be evaluated from several Python threads (the calls on one Evaluator take
    turns; use one Evaluator per thread to run them at once).
    """

    def __init__(self, mesh, scheme="catmull-clark", levels=1, *, params=None, boundary="edges-and-corners",
                 crease_method="uniform", threads=0, start_level=0):
        check_mesh(mesh, "Evaluator")
        levels = _check_levels(levels)
        self._prepared = _subdivkit._prepare_evaluator(mesh, scheme, params, levels, boundary, crease_method,
                                                       check_threads(threads), _check_start_level(start_level))
        self.name = mesh.name
        self.scheme = scheme.name if isinstance(scheme, Scheme) else str(scheme)
        # mesh() without points refines the points the mesh had when the evaluator was made.
        self._base_points = mesh.points.copy()
        # The finest level's faces and tags, read-only: mesh() hands out copies.
        topology = self._prepared.topology()
        for a in topology.values():
            a.setflags(write=False)
        self._finest = Mesh._from_arrays(topology, name=mesh.name)

    @property
    def levels(self):
        """Refinement steps from the base mesh to the finest level."""
        return self._prepared.levels

    @property
    def n_base_points(self):
        """Rows ``evaluate`` takes: the base mesh's points."""
        return self._prepared.n_base_points

    @property
    def n_points(self):
        """Rows ``evaluate`` returns: the finest level's points."""
        return self._prepared.n_points

    @property
    def n_faces(self):
        """The finest level's faces (holes left out, as refine() leaves them out)."""
        return self._finest.n_faces

    @property
    def face_indices(self):
        """The finest level's face corners, int32 (read-only; with ``face_offsets``, CSR as in Mesh)."""
        return self._finest.face_indices

    @property
    def face_offsets(self):
        """The finest level's face offsets (m + 1 values, read-only)."""
        return self._finest.face_offsets

    @property
    def face_sizes(self):
        """Corners per finest face, (m,) int32."""
        return self._finest.face_sizes

    @property
    def faces(self):
        """The finest level's faces as an (m, k) read-only view when all are k-gons (as Mesh.faces)."""
        return self._finest.faces

    def face_list(self):
        """The finest level's faces as a list of index arrays."""
        return self._finest.face_list()

    @property
    def creases(self):
        """The finest level's creased vertex pairs (c, 2), with ``crease_sharpness`` (decayed per level)."""
        return self._finest.creases

    @property
    def crease_sharpness(self):
        return self._finest.crease_sharpness

    @property
    def corners(self):
        """The finest level's corner vertices, with ``corner_sharpness``."""
        return self._finest.corners

    @property
    def corner_sharpness(self):
        return self._finest.corner_sharpness

    def evaluate(self, points):
        """Values at the base mesh's points carried to the finest level's points.

        ``points``: (n_base_points, c) numbers, c >= 1 (positions, or any per-point data),
        or (n_base_points,) for one column. Returns a new float64 array of shape
        (n_points, c), or (n_points,). Raises subdivkit.Error for other shapes and for NaN
        or infinite values (which refinement would spread to the neighbours).
        """
        return self._evaluate(points, "Evaluator.evaluate")

    def _evaluate(self, points, what):
        """evaluate(), its refusals naming `what`: the method the user called."""
        a = np.asarray(points)
        if a.dtype.kind not in "fiu":
            raise Error(f"{what}: expected numbers, got an array of dtype {a.dtype}")
        if a.ndim not in (1, 2) or (a.ndim == 2 and a.shape[1] == 0):
            raise Error(f"{what}: expected shape ({self.n_base_points}, c) with c >= 1 columns, or "
                        f"({self.n_base_points},), got {a.shape}")
        if a.shape[0] != self.n_base_points:
            raise Error(f"{what}: {a.shape[0]} rows for a base mesh of {self.n_base_points} points; give one row per "
                        f"point of the mesh the Evaluator was made for")
        values = self._prepared.evaluate(np.ascontiguousarray(a.reshape(len(a), -1), dtype=np.float64))
        return values.reshape(-1) if a.ndim == 1 else values

    def mesh(self, points=None):
        """The finest level as a Mesh: its faces, creases and corners, with ``evaluate(points)``
        as points (``points`` (n_base_points, 3)), or the refined points of the mesh the
        Evaluator was made with when ``points`` is None. The same as refine()'s Mesh but for
        point, cell and face-varying data, which it does not carry."""
        if points is None:
            points = self._base_points
        shape = np.shape(points)
        if len(shape) != 2 or shape[1] != 3:
            raise Error(f"Evaluator.mesh: a Mesh needs points of shape ({self.n_base_points}, 3), got {shape}; "
                        "evaluate() carries other data")
        arrays = {key: np.array(getattr(self._finest, key)) for key in _MESH_ARRAYS if key != "points"}
        arrays["points"] = self._evaluate(points, "Evaluator.mesh")
        return Mesh._from_arrays(arrays, name=self.name)

    def __repr__(self):
        return (f"<subdivkit.Evaluator {_quoted(self.name)}: {self.levels} level(s) of {_escaped(self.scheme)}, "
                f"{self.n_base_points} -> {self.n_points} points, {self.n_faces} faces>")


def _scipy_sparse():
    try:
        import scipy.sparse
    except ImportError as e:  # SciPy is optional for everything but matrices
        raise ImportError("subdivkit.stencils returns scipy.sparse matrices and needs SciPy: install it "
                          "(Debian: apt-get install python3-scipy; pip: pip install scipy)") from e
    return scipy.sparse


def stencils(mesh, scheme="catmull-clark", levels=1, *, composed=False, params=None, boundary="edges-and-corners",
             crease_method="uniform", threads=0, start_level=0):
    """The subdivision matrices of a mesh: ``P_fine = S @ P``.

    Returns a list of ``scipy.sparse.csr_matrix``, one per level (level l's rows are the
    points of level l + 1, its columns those of level l), or, with ``composed=True``, one
    matrix from the input's points straight to the finest level's. Topology is refined
    once; new positions (animation, editing, fitting) then cost one product. The rows
    are the engine's stencil tables and sum to 1.

    Arguments as refine() (``params`` too). Needs SciPy (imported on first use). Non-linear schemes
    (plugin rules) have no matrix and raise subdivkit.Error.
    """
    check_mesh(mesh, "stencils")
    levels = _check_levels(levels)
    tables = _subdivkit._stencils(mesh, scheme, params, levels, bool(composed), boundary, crease_method, check_threads(threads),
                                  _check_start_level(start_level))
    sparse = _scipy_sparse()
    matrices = [sparse.csr_matrix((t["data"], t["indices"], t["indptr"]), shape=t["shape"]) for t in tables]
    return matrices[0] if composed else matrices


@dataclass
class LimitPoints:
    """Limit positions of a mesh's vertices (limit_positions' result).

    ``points`` (n, 3): each vertex's point on the limit surface (or curve); ``normals`` (n, 3):
    unit limit normals (surfaces; zero where none exists, None for curves; all zero for a scheme
    that is not C1 where the mesh is regular, whose limit has no normals, the reason in
    ``approximate_reasons``); ``exact`` (n,)
    bool: False where the position had to be approximated (reasons in ``approximate_reasons``).
    """
    points: np.ndarray
    normals: np.ndarray = None
    exact: np.ndarray = None
    normal_exact: np.ndarray = None
    approximate_reasons: list = field(default_factory=list)


def limit_positions(mesh, scheme="catmull-clark", *, params=None, boundary="edges-and-corners",
                    crease_method="uniform", start_level=0):
    """Where each vertex of the mesh ends up on the limit surface, with limit normals.

    The masks come from the scheme's own eigen-analysis (left eigenvectors of the local
    subdivision matrix), as ``subdiv refine --limit``; vertices whose neighbourhood is
    unusual are refined locally first. For curve schemes and polylines, the limit points of
    the control points (no normals). ``params`` as in refine(). Returns a LimitPoints.
    """
    check_mesh(mesh, "limit_positions")
    r = _subdivkit._limit_positions(mesh, scheme, params, boundary, crease_method, _check_start_level(start_level))
    if "normals" not in r:
        return LimitPoints(points=r["points"])
    return LimitPoints(points=r["points"], normals=r["normals"], exact=r["exact"].astype(bool),
                       normal_exact=r["normal_exact"].astype(bool), approximate_reasons=list(r["approximate_reasons"]))


@dataclass
class Interpolation:
    """The result of interpolate().

    ``mesh``: the new control mesh (same topology, moved points); ``limit`` (n, 3): its limit
    points; ``iterations`` and ``converged``; ``max_residual`` and ``rms_residual``: per
    iteration k, the distance between the targets and the limit points of the moving
    vertices; ``tolerance``: the stopping distance used; ``limit_description``: which limit
    operator was used and how it was checked; ``fixed_note``: with fixed vertices, how far
    their limit points end from them and how well theorem 2 of Lin et al. 2015 predicted it
    (as `subdiv interpolate` prints it; empty when every vertex moves).
    """
    mesh: Mesh
    limit: np.ndarray
    iterations: int
    converged: bool
    max_residual: np.ndarray
    rms_residual: np.ndarray
    tolerance: float
    limit_description: str
    fixed_note: str = ""


def _moving_mask(select, n):
    if select is None or (isinstance(select, str) and select == "all"):
        return None
    if isinstance(select, str):
        raise Error(f"select={select!r}: give 'all', a list of vertex ids or a boolean mask")
    a = np.asarray(select)
    if a.size == 0:
        raise Error("select: no vertex selected; select at least one vertex to move")
    if a.dtype == bool:
        if a.shape != (n,):
            raise Error(f"select: a boolean mask needs one flag per vertex ({n}), got shape {a.shape}")
        mask = a.astype(np.int32)
    else:
        if a.dtype.kind not in "iu":
            raise Error(f"select: expected vertex ids (integers) or a boolean mask, got dtype {a.dtype}")
        a = a.reshape(-1)
        if a.size and (a.min() < 0 or a.max() >= n):
            bad = a.min() if a.min() < 0 else a.max()
            raise Error(f"select: vertex {bad} does not exist; the mesh has {n} vertices (0-based ids)")
        mask = np.zeros(n, dtype=np.int32)
        mask[a] = 1
    if not mask.any():
        raise Error("select: no vertex selected; select at least one vertex to move")
    return mask


def interpolate(mesh, scheme="catmull-clark", *, select=None, tolerance=None, max_iterations=1000, params=None,
                boundary="edges-and-corners", threads=0):
    """Progressive interpolation: move control points until the limit surface passes
    through the mesh's vertices (as ``subdiv interpolate``).

    Parameters
    ----------
    select : None, 'all', list of vertex ids, or boolean mask
        The vertices to interpolate; the others stay where they are (local interpolation).
    tolerance : float, optional
        Stop once every selected vertex's limit point is this close (default 1e-10 times
        the bounding-box diagonal).
    max_iterations : int
        Iteration cap; the result says whether it converged.
    scheme : Scheme, str or os.PathLike
        A surface scheme or sequence such as "catmull-clark-shape:1,catmull-clark", or a
        curve scheme for polylines.
    params : dict, optional
        Parameter values, as in refine(); Lin et al. 2015's shape parameter is
        ``params={"lambda": 0.5}`` with "catmull-clark-shape:1,catmull-clark".

    Returns an Interpolation. Raises subdivkit.Error when the scheme has no checked limit
    operator or the iteration diverges.
    """
    check_mesh(mesh, "interpolate")
    moving = _moving_mask(select, mesh.n_points)
    r = _subdivkit._interpolate(mesh, scheme, params, moving, -1.0 if tolerance is None else float(tolerance),
                                check_whole(max_iterations, "max_iterations", "give a whole number of iterations"), boundary, check_threads(threads))
    return Interpolation(mesh=mesh.with_points(r["points"]), limit=r["limit"], iterations=r["iterations"],
                         converged=r["converged"], max_residual=r["max_residual"], rms_residual=r["rms_residual"],
                         tolerance=r["tolerance"], limit_description=r["limit_description"],
                         fixed_note=r["fixed_note"])


__all__ = ["refine", "Evaluator", "stencils", "limit_positions", "interpolate", "LimitPoints", "Interpolation", "Scheme"]
