"""Texture coordinates for disc-like meshes by Tutte's embedding (docs/parameterize.md)."""

import numpy as np

from . import _subdivkit
from .mesh import Mesh


def parameterize(mesh, *, boundary="circle", corners=None, weights="uniform"):
    """Map a topological disc one-to-one onto the plane; return the mesh with UVs.

    The boundary vertices go onto a convex curve by arc length, every interior vertex to a
    convex combination of its neighbours, by one sparse solve; for a convex boundary the
    map is one-to-one, no face flipped (Tutte 1963, "How to draw a graph"; Floater 2003,
    "Mean value coordinates"). As ``subdiv parameterize``.

    Parameters
    ----------
    mesh : Mesh
        A topological disc: connected, one boundary loop, Euler characteristic 1.
        Anything else raises subdivkit.Error with the reason.
    boundary : str
        'circle' (the unit circle) or 'square' (the unit square [0, 1]^2).
    corners : array_like of 4 ints, optional
        With boundary='square': the boundary vertices at the square's corners (any order).
        Default: the four boundary vertices where the boundary turns most sharply.
    weights : str
        'uniform' (each interior vertex the average of its neighbours, Tutte) or
        'mean-value' (Floater's weights: closer to the surface's shapes).

    Returns
    -------
    Mesh
        A copy of ``mesh`` with ``face_varying["uv"]`` = (uv, face_indices): the UVs as
        face-varying data (earlier texture coordinates replaced), which refine() carries
        through the levels and write_mesh writes as OBJ ``vt``.
    """
    done = _subdivkit._parameterize(mesh, str(boundary), corners, str(weights))
    uv_names = [k for k, role in mesh.point_roles.items() if role == "texture_coordinates"] + ["uv"]
    point_data = {k: v for k, v in mesh.point_data.items() if k not in uv_names}
    point_roles = {k: v for k, v in mesh.point_roles.items() if k not in uv_names}
    face_varying = {k: v for k, v in mesh.face_varying.items() if k != "uv"}
    face_varying["uv"] = (done["uv"], np.array(mesh.face_indices, dtype=np.int32))
    return Mesh._from_arrays(mesh._arrays(), name=mesh.name, point_data=point_data, cell_data=mesh.cell_data,
                             face_varying=face_varying, point_roles=point_roles, cell_roles=mesh.cell_roles)
