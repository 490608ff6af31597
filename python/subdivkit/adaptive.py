"""Feature-adaptive refinement: subdivkit.refine_adaptive, the same as ``subdiv refine
--adaptive L`` (docs/limit.md), through the library's pipeline."""

import warnings
from dataclasses import dataclass

import numpy as np

from . import _subdivkit
from ._subdivkit import Error
from ._checks import check_mesh, check_progress, check_threads
from .mesh import Mesh, _data_arrays, _face_varying_triples


@dataclass
class AdaptiveInfo:
    """What refine_adaptive did: ``uniform_faces`` (faces of the uniform level L, for
    comparison), ``split_faces`` (faces split per level), ``corner_uv`` ((corners, 2): each
    face corner's (u, v) in its base face, in the order of ``face_indices``) and ``summary``
    (the line ``subdiv refine --adaptive`` prints)."""
    uniform_faces: int
    split_faces: list
    corner_uv: np.ndarray
    summary: str


def refine_adaptive(mesh, scheme="catmull-clark", levels=1, *, tolerance=0.0, limit=False, params=None,
                    boundary="edges-and-corners", crease_method="uniform", feature_angle=-1.0, threads=0,
                    info=False, fvar_boundary="all", progress=None, transitions="polygons"):
    """Refine only where the surface needs it, up to level ``levels``; return a Mesh.

    Faces touching an extraordinary vertex, a crease, a sharp or semi-sharp vertex or a hole,
    and faces of another shape than the split makes, are split level after level, as
    OpenSubdiv's feature-adaptive RefineAdaptive isolates them (Nießner, Loop, Meyer & DeRose
    2012); regular regions stay coarse. Each level computes only the faces it splits and a
    few rings around them, so the work grows with the number of features, not as 4^L.

    Parameters
    ----------
    mesh : Mesh
        Polygons (triangles for a triangle scheme). Non-manifold meshes (edges of three or
        more faces, vertices where fans of faces meet, neighbours running an edge the same
        way) are refined as uniform refinement refines them, their non-manifold edges and
        vertices shared by the fans; a face that repeats a vertex is refused.
    scheme : Scheme, str or os.PathLike
        A scheme with the binary quad or triangle split (Catmull-Clark, Loop, ...).
    levels : int
        The finest level, 0 to 12.
    tolerance : float
        > 0: also split every face whose bilinear (on triangles linear) patch through its
        corners' limit points is farther than this from the limit surface, measured with the
        exact evaluator at the 5 x 5 points (i/4, j/4) of the face (15 on a triangle).
    limit : bool
        Every vertex on the limit surface (the exact evaluator, docs/limit.md); otherwise a
        vertex is where the finest level that computed it puts it.
    params, boundary, crease_method, feature_angle, threads
        As for LimitSurface and refine().
    fvar_boundary : str
        How the mesh's face-varying arrays (``mesh.face_varying``, e.g. texture coordinates)
        are interpolated, as for LimitSurface: "all" (the default, bilinear in each face, as
        OpenSubdiv's), "none", "corners-only", "corners-plus1", "corners-plus2",
        "boundaries". With ``limit=True`` each corner of the result gets the array's limit
        at its (face, u, v), in ``face_varying`` (one value per corner); without it the arrays
        are refined with the faces in that mode, each corner taking its level's value on its
        face's side of a seam, as uniform refinement (refine()) gives it there (values shared
        within a UV island).
    info : bool
        Return ``(mesh, AdaptiveInfo)`` instead of the mesh.
    progress : callable, optional
        Called as ``progress(phase, done)`` on the calling thread, as for refine():
        ``done`` is None when a phase starts ("refining adaptively to level 6"), then the
        share done, 0 to 1 (each level's choice of faces and their refinement, then the limit
        points). An exception it raises stops the refinement and comes back from here.
    transitions : str
        "polygons" (the default): a coarse face next to finer ones is one polygon with the
        finer vertices along its edges as corners. "triangles": that polygon as triangles and
        quads of the same vertices, as OpenSubdiv's transition patterns (a fixed pattern for
        1, 2 adjacent, 2 opposite, 3 or 4 split edges of a quad, and 1 to 3 of a triangle;
        triangles zipped across a face whose neighbours are two or more levels finer), for
        renderers and tools that take no n-gons; the points are the same.

    The result is watertight: a coarse face next to finer ones takes the finer vertices along
    its edges as corners of its own (a transition polygon; with ``transitions="triangles"``
    its triangles and quads), so every interior edge is in exactly two faces. Its point_data: the mesh's point arrays (not integer ones), placed like
    the positions (on the limit too with ``limit``); a rational mesh (a "weight" point array)
    is refined as its homogeneous points and projected (``tolerance`` is refused then). Its cell_data: ``face_level`` (the level
    a face comes from) and
    ``base_face`` (the input face it lies in).

    >>> import subdivkit as sk
    >>> cube = sk.read_mesh("examples/meshes/cube.obj")
    >>> m = sk.refine_adaptive(cube, "catmull-clark", 5, limit=True)
    >>> m.n_faces                                   # 312, against 6144 uniform
    """
    check_mesh(mesh, "refine_adaptive")
    if isinstance(levels, bool) or not isinstance(levels, (int, np.integer)) or not 0 <= levels <= 12:
        raise Error(f"levels={levels!r}: adaptive refinement goes to level 0 to 12")
    tol = float(tolerance)
    if not tol >= 0 or not np.isfinite(tol):
        raise Error(f"tolerance={tolerance!r}: give a distance >= 0 (0: split only around features)")
    check_progress(progress, "refine_adaptive")
    r = _subdivkit._refine_adaptive(mesh, scheme, params, int(levels), tol, bool(limit), str(boundary),
                                    str(crease_method), float(feature_angle), check_threads(threads),
                                    _data_arrays(mesh.point_data, mesh.point_roles, mesh.n_points, "point data"),
                                    _face_varying_triples(mesh), str(fvar_boundary), progress, str(transitions))
    for note in r["notes"]:  # arrays left out (normals, integers)
        warnings.warn(f"refine_adaptive: {note}", UserWarning, stacklevel=2)
    out = Mesh._from_arrays(r["mesh"], name=mesh.name, point_data=r["point_data"], point_roles=r["point_roles"],
                            cell_data={"face_level": r["face_level"], "base_face": r["base_face"]},
                            face_varying=r["face_varying"])
    if info:
        return out, AdaptiveInfo(uniform_faces=int(r["uniform_faces"]), split_faces=list(r["split_faces"]),
                                 corner_uv=r["corner_uv"], summary=str(r["summary"]))
    return out
