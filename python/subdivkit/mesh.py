"""The Mesh class and mesh files.

A Mesh holds NumPy arrays in the layout the C++ library uses, so that passing one to
refine() or writing it converts nothing:

* ``points``: (n, 3) float64, C-contiguous;
* faces as CSR: ``face_indices`` (all corners, int32) and ``face_offsets`` (m + 1 int32,
  face f is ``face_indices[face_offsets[f]:face_offsets[f + 1]]``); ``faces`` is the same
  data as an (m, k) view when every face has k corners;
* polylines the same way (``line_indices``, ``line_offsets``);
* creases: ``creases`` (c, 2) vertex pairs with ``crease_sharpness`` (c,); corners:
  ``corners`` (k,) vertex ids with ``corner_sharpness`` (k,). Sharpness follows OpenSubdiv:
  0 smooth, 10 or more infinitely sharp;
* ``point_data`` and ``cell_data``: dicts of arrays with one row per point or per face,
  carried through refine() and written to .vtp files. Float arrays are interpolated like
  the points; integer arrays (any integer or bool dtype; they come back as int32) are
  labels: a new point takes its vertex's value, or the one its element's vertices share
  (the smallest where they differ), never an average;
* ``point_roles`` and ``cell_roles``: dicts name -> role for the arrays that are more than
  data, as the C++ library's ``ArrayRole``: "normals" (not refined: refine() leaves them
  out with a warning), "texture_coordinates" (the active TCoords in .vtp, ``vt`` in OBJ),
  "color" (the active scalars in .vtp, ``red green blue`` in PLY). read_mesh fills them
  from the file, refine() and write_mesh keep them;
* ``face_varying``: a dict name -> (values, indices) of face-varying data, e.g. UVs with
  seams (OBJ ``vt``, read as "uv"): values (m, k) float64 and one int32 value index per
  face corner (in ``face_indices`` order). refine() carries it as OpenSubdiv does (its
  ``fvar_boundary`` argument); write_mesh writes "uv" as OBJ ``vt``, and .vtp/.ply with a
  point per side of a seam.

Arrays given in another layout (float32 or integer points, Fortran order, strided views)
are converted once, here; arrays that cannot mean what is asked (float face indices,
negative indices, wrong shapes) are refused with a subdivkit.Error that says why.
"""

import os

import numpy as np

from . import _subdivkit
from ._subdivkit import Error

_INT32_MAX = np.iinfo(np.int32).max
INFINITELY_SHARP = 10.0
ROLES = ("data", "normals", "texture_coordinates", "color")


def _as_array(values, what, expected):
    """np.asarray(values), or an Error naming the argument where numpy cannot make one array
    of the nested lists (rows of different lengths), instead of numpy's bare ValueError."""
    try:
        return np.asarray(values)
    except ValueError as e:
        raise Error(f"{what}: the rows have different lengths, so they make no array ({e}); "
                    f"give {expected}") from None


def _as_points(points, what="points"):
    a = _as_array(points, what, "an (n, 3) array: one row (x, y, z) per point")
    if a.dtype.kind not in "fiu":
        raise Error(f"{what}: expected numbers, got an array of dtype {a.dtype}")
    if a.ndim != 2 or a.shape[1] != 3:
        raise Error(f"{what}: expected shape (n, 3), got {a.shape}")
    return np.ascontiguousarray(a, dtype=np.float64)


def _as_indices(values, what, shape_hint="a 1-d array"):
    a = np.asarray(values)
    if a.size == 0:
        return np.zeros(0, dtype=np.int32)
    if a.dtype.kind not in "iu":
        raise Error(f"{what}: expected integer indices, got dtype {a.dtype}"
                    + ("; convert whole numbers with .astype(int)" if a.dtype.kind == "f" else ""))
    if a.ndim != 1:
        raise Error(f"{what}: expected {shape_hint}, got shape {a.shape}")
    if a.min() < 0 or a.max() > _INT32_MAX:
        bad = a.min() if a.min() < 0 else a.max()
        raise Error(f"{what}: index {bad} is out of range (0-based indices that fit in 32 bits)")
    return np.ascontiguousarray(a, dtype=np.int32)


def _as_sharpness(values, count, what):
    if values is None:
        values = INFINITELY_SHARP
    a = _as_array(values, what, f"one number per entry ({count})")
    if a.dtype.kind not in "fiu":
        raise Error(f"{what}: expected numbers, got dtype {a.dtype}")
    if a.ndim == 0:
        a = np.full(count, float(a))
    if a.shape != (count,):
        raise Error(f"{what}: expected one value per entry ({count}), got shape {a.shape}")
    return np.ascontiguousarray(a, dtype=np.float64)


def _as_cells(cells, offsets, what, offsets_name):
    """Polygons or polylines as CSR (indices, offsets) from any of the accepted forms."""
    if cells is None:
        if offsets is not None:
            raise Error(f"{offsets_name} given without {what}")
        return np.zeros(0, dtype=np.int32), np.zeros(1, dtype=np.int32)
    if offsets is not None:  # flat indices + offsets
        indices = _as_indices(cells, what, "flat indices with offsets")
        offsets = _as_indices(offsets, offsets_name)
        if offsets.size == 0 or offsets[0] != 0 or offsets[-1] != indices.size or np.any(np.diff(offsets) < 0):
            raise Error(f"{offsets_name}: expected a rising sequence from 0 to {indices.size} "
                        f"(the number of indices)")
        return indices, offsets
    a = cells if isinstance(cells, np.ndarray) else None
    if a is None:
        try:
            a = np.asarray(cells)
        except ValueError:  # ragged nested lists in newer NumPy
            a = np.asarray(cells, dtype=object)
    if a.dtype != object and a.ndim == 2:  # (m, k): uniform
        m, k = a.shape
        return _as_indices(a.reshape(-1), what), np.arange(m + 1, dtype=np.int32) * np.int32(k)
    if a.dtype != object and a.ndim != 1:
        raise Error(f"{what}: expected an (m, k) array or a list of index lists, got shape {a.shape}")
    rows = [np.asarray(c).reshape(-1) for c in cells]
    sizes = np.array([r.size for r in rows], dtype=np.int64)
    offsets = np.zeros(len(rows) + 1, dtype=np.int32)
    np.cumsum(sizes, out=offsets[1:])
    flat = np.concatenate(rows) if rows else np.zeros(0, dtype=np.int32)
    return _as_indices(flat, what), offsets


def _as_pairs(creases):
    pairs = np.zeros((0, 2), dtype=np.int32) if creases is None else _as_array(
        creases, "creases", "an (m, 2) array of vertex pairs")
    if pairs.size == 0:
        pairs = np.zeros((0, 2), dtype=np.int32)
    if pairs.ndim != 2 or pairs.shape[1] != 2:
        raise Error(f"creases: expected (c, 2) vertex pairs, got shape {pairs.shape}")
    return _as_indices(pairs.reshape(-1), "creases").reshape(-1, 2)


def _quoted(text):
    """User text between single quotes for a message, control bytes and a NUL escaped
    (framework/util/quoted_text.h: the library's messages quote names the same way)."""
    return _subdivkit._quoted(str(text).encode("utf-8", "surrogatepass"))


def _escaped(text):
    """User text for a message, without quotes (a mesh's name before a colon)."""
    return _subdivkit._escaped(str(text).encode("utf-8", "surrogatepass"))


def _type_name(value):
    """The type of a wrong argument for a message; a class made with type() can have any name."""
    return _escaped(type(value).__name__)


def _checked_array(name, check, doc):
    """A Mesh array stored as ``_name``, checked and converted by ``check(mesh, value)`` on assignment."""
    private = "_" + name

    def get(mesh):
        return getattr(mesh, private)

    def put(mesh, value):
        setattr(mesh, private, check(mesh, value))

    return property(get, put, doc=doc)


_ARRAYS = ("points", "face_indices", "face_offsets", "line_indices", "line_offsets", "creases", "crease_sharpness",
           "corners", "corner_sharpness")


class Mesh:
    """A polygon mesh (and/or polylines) with creases, corners and per-point/per-face data.

    Parameters
    ----------
    points : array-like, shape (n, 3)
        Vertex positions; converted to C-contiguous float64 if needed.
    faces : array-like, optional
        An (m, k) integer array (every face a k-gon), a list of index lists (any sizes),
        or flat indices when ``face_offsets`` is given. Faces are CCW seen from outside.
    face_offsets : array-like, optional
        CSR offsets (m + 1 values, from 0 to len(faces)) for flat ``faces``.
    lines, line_offsets : optional
        Polylines, in the same forms as faces (for curve schemes). A polyline whose last
        index repeats its first is a closed polygon.
    creases : array-like, shape (c, 2), optional
        Vertex pairs of creased edges.
    crease_sharpness : float or array-like (c,), optional
        Sharpness per crease (default 10: infinitely sharp).
    corners : array-like (k,), optional
        Vertex ids tagged as corners.
    corner_sharpness : float or array-like (k,), optional
        Sharpness per corner (default 10).
    point_data, cell_data : dict, optional
        Arrays with one row per point / per face, carried through refine(); integer
        arrays are labels (taken, not averaged).
    point_roles, cell_roles : dict, optional
        name -> "normals", "texture_coordinates", "color" or "data" for those arrays,
        e.g. {"normal": "normals"}.
    face_varying : dict, optional
        name -> (values (m, k), corner indices), e.g. {"uv": (uv, uv_index)}.
    name : str
        How error messages name this mesh (read_mesh sets the file name).
    """

    def __init__(self, points, faces=None, *, face_offsets=None, lines=None, line_offsets=None, creases=None,
                 crease_sharpness=None, corners=None, corner_sharpness=None, point_data=None, cell_data=None,
                 face_varying=None, point_roles=None, cell_roles=None, name="mesh"):
        self.name = str(name)
        self._points = _as_points(points, f"{_escaped(self.name)}.points")
        self._face_indices, self._face_offsets = _as_cells(faces, face_offsets, "faces", "face_offsets")
        self._line_indices, self._line_offsets = _as_cells(lines, line_offsets, "lines", "line_offsets")
        self._creases = _as_pairs(creases)
        self._crease_sharpness = _as_sharpness(crease_sharpness, len(self._creases), "crease_sharpness")
        self._corners = _as_indices(np.zeros(0, dtype=np.int32) if corners is None else corners, "corners")
        self._corner_sharpness = _as_sharpness(corner_sharpness, len(self._corners), "corner_sharpness")
        self.point_data = dict(point_data or {})
        self.cell_data = dict(cell_data or {})
        self.face_varying = dict(face_varying or {})
        self.point_roles = dict(point_roles or {})
        self.cell_roles = dict(cell_roles or {})

    @classmethod
    def _from_arrays(cls, arrays, name="mesh", point_data=None, cell_data=None, face_varying=None, point_roles=None,
                     cell_roles=None):
        """A Mesh around arrays the extension made (already in the right layout: no copies)."""
        mesh = cls.__new__(cls)
        mesh.name = name
        for key in _ARRAYS:
            setattr(mesh, "_" + key, arrays[key])
        mesh.point_data = dict(point_data or {})
        mesh.cell_data = dict(cell_data or {})
        mesh.face_varying = dict(face_varying or {})
        mesh.point_roles = dict(point_roles or {})
        mesh.cell_roles = dict(cell_roles or {})
        return mesh

    # The arrays, checked and converted on assignment as the constructor does (a float index
    # array is refused, not truncated; an index past 32 bits is refused, not wrapped). Whether
    # they agree with each other (offsets against indices, one sharpness per crease) is
    # checked where the mesh is used, since related arrays are assigned one at a time.
    points = _checked_array("points", lambda m, v: _as_points(v, f"{m.name}.points"),
                            "Vertex positions, (n, 3) float64.")
    face_indices = _checked_array("face_indices",
                                  lambda m, v: _as_indices(v, "face_indices", "flat indices with offsets"),
                                  "The faces' vertex indices, flat int32 (CSR with face_offsets).")
    face_offsets = _checked_array("face_offsets", lambda m, v: _as_indices(v, "face_offsets"),
                                  "Where each face starts in face_indices, int32 (n_faces + 1 values).")
    line_indices = _checked_array("line_indices",
                                  lambda m, v: _as_indices(v, "line_indices", "flat indices with offsets"),
                                  "The polylines' vertex indices, flat int32 (CSR with line_offsets).")
    line_offsets = _checked_array("line_offsets", lambda m, v: _as_indices(v, "line_offsets"),
                                  "Where each polyline starts in line_indices, int32 (n_lines + 1 values).")
    creases = _checked_array("creases", lambda m, v: _as_pairs(v), "Vertex pairs of creased edges, (c, 2) int32.")
    crease_sharpness = _checked_array("crease_sharpness",
                                      lambda m, v: _as_sharpness(v, len(m.creases), "crease_sharpness"),
                                      "Sharpness per crease, (c,) float64 (10: infinitely sharp).")
    corners = _checked_array("corners", lambda m, v: _as_indices(v, "corners"), "Vertex ids tagged as corners, int32.")
    corner_sharpness = _checked_array("corner_sharpness",
                                      lambda m, v: _as_sharpness(v, len(m.corners), "corner_sharpness"),
                                      "Sharpness per corner, (k,) float64 (10: infinitely sharp).")

    def _arrays(self):
        """The arrays as _from_arrays takes them (no copies)."""
        return {key: getattr(self, key) for key in _ARRAYS}

    @property
    def n_points(self):
        """Number of vertices."""
        return len(self.points)

    @property
    def n_faces(self):
        """Number of faces."""
        return len(self.face_offsets) - 1

    @property
    def n_lines(self):
        """Number of polylines."""
        return len(self.line_offsets) - 1

    @property
    def face_sizes(self):
        """Corners per face, (m,) int32."""
        return np.diff(self.face_offsets)

    @property
    def faces(self):
        """The faces as an (m, k) int32 view of ``face_indices`` (no copy) when all are k-gons.

        Raises subdivkit.Error for meshes with mixed face sizes; use ``face_indices`` and
        ``face_offsets`` (or ``face_list()``) for those.
        """
        sizes = self.face_sizes
        if len(sizes) == 0:
            return self.face_indices.reshape(0, 0)
        if np.any(sizes != sizes[0]):
            raise Error(f"{_escaped(self.name)}: faces have {len(np.unique(sizes))} different sizes "
                        f"({', '.join(map(str, np.unique(sizes)[:5]))}); an (m, k) array needs one size: "
                        "use face_indices and face_offsets, or face_list()")
        return self.face_indices.reshape(-1, int(sizes[0]))

    def face_list(self):
        """The faces as a list of index arrays (views into ``face_indices``)."""
        return np.split(self.face_indices, self.face_offsets[1:-1])

    def line_list(self):
        """The polylines as a list of index arrays (views into ``line_indices``)."""
        return np.split(self.line_indices, self.line_offsets[1:-1])

    def with_points(self, points):
        """The same topology, tags and data with new positions (for instance after ``S @ P``)."""
        mesh = Mesh._from_arrays(self._arrays(), name=self.name,
                                 point_data=self.point_data, cell_data=self.cell_data, face_varying=self.face_varying,
                                 point_roles=self.point_roles, cell_roles=self.cell_roles)
        mesh.points = points
        if len(mesh.points) != self.n_points:
            raise Error(f"with_points: {len(mesh.points)} points for a mesh of {self.n_points}")
        return mesh

    def __repr__(self):
        parts = [f"{self.n_points} points", f"{self.n_faces} faces"]
        if self.n_lines:
            parts.append(f"{self.n_lines} polylines")
        if len(self.creases):
            parts.append(f"{len(self.creases)} creases")
        if len(self.corners):
            parts.append(f"{len(self.corners)} corners")
        for label, data in (("point data", self.point_data), ("cell data", self.cell_data)):
            if data:
                parts.append(f"{label} {sorted(data)}")
        return f"<subdivkit.Mesh {_quoted(self.name)}: {', '.join(parts)}>"


def _role(roles, key, what):
    role = str((roles or {}).get(key, "data"))
    if role not in ROLES:
        raise Error(f"{what} {_quoted(key)}: role {role!r} is not one of {', '.join(ROLES)}")
    return role


def _data_arrays(data, roles, rows, what):
    """A data dict as (name, 2-d float64 array, integer, role) tuples for the extension, checked.

    Integer and bool arrays travel as float64 (the library's DataArray holds doubles) marked
    integer; their values must fit an int32, as in a .vtp's vtkIntArray.
    """
    arrays = []
    for key, values in (data or {}).items():
        if not str(key):  # a .vtp array without a name cannot be written, nor told apart when read
            raise Error(f"{what}: an array has the empty name ''; give it a name")
        a = _as_array(values, f"{what} {_quoted(key)}", f"{rows} rows of equal length")
        if a.dtype.kind not in "fiub":
            raise Error(f"{what} {_quoted(key)}: expected numbers, got dtype {a.dtype}")
        if a.ndim not in (1, 2) or a.shape[0] != rows:
            raise Error(f"{what} {_quoted(key)}: expected {rows} rows, got shape {a.shape}")
        integer = a.dtype.kind in "iub"
        if integer and a.size and (a.min() < np.iinfo(np.int32).min or a.max() > _INT32_MAX):
            raise Error(f"{what} {_quoted(key)}: integer values must fit in 32 bits (labels); "
                        f"convert the array to float to interpolate it")
        columns = a.shape[1] if a.ndim == 2 else 1  # also with no rows (a level whose faces are all holes)
        arrays.append((str(key), np.ascontiguousarray(a.reshape(rows, columns), dtype=np.float64), integer,
                       _role(roles, key, what)))
    return arrays


def _face_varying_triples(mesh):
    """The mesh's face-varying dict as (name, (m, k) float64 values, int32 indices) triples, checked."""
    triples = []
    for key, pair in (mesh.face_varying or {}).items():
        if not isinstance(pair, (tuple, list)) or len(pair) != 2:
            raise Error(f"face_varying {_quoted(key)}: expected a pair (values, indices)")
        values = np.asarray(pair[0])
        if values.dtype.kind not in "fiu":
            raise Error(f"face_varying {_quoted(key)}: expected numbers, got dtype {values.dtype}")
        values = np.ascontiguousarray(values.reshape(len(values), -1), dtype=np.float64)
        indices = _as_indices(pair[1], f"face_varying {_quoted(key)} indices")
        triples.append((str(key), values, indices))
    return triples


def _data_shapes_like(refined, original):
    """Refined data arrays back in the shapes they came in: 1-d stays 1-d; arrays the
    refinement added (SubdivKit's descriptions of the level) are 1-d when one column."""
    def shaped(key):
        a = refined[key]
        one_column = np.ndim(original[key]) == 1 if key in original else a.ndim == 2 and a.shape[1] == 1
        return a.reshape(-1) if one_column else a
    return {key: shaped(key) for key in refined}


def read_mesh(path):
    """Read a mesh file: .obj (with 'l' polylines and 't crease'/'t corner' tags), .off, .ply,
    .stl, .om, .vtp or .vtk, chosen by the extension.

    Returns a Mesh named after the file, with the file's point and cell arrays in
    ``point_data`` and ``cell_data`` (.vtp/.vtk arrays, PLY properties, OFF colours,
    normals and texture coordinates; integer arrays as int32), their roles in
    ``point_roles`` and ``cell_roles`` (the active normals, texture coordinates and colours
    of a .vtp, PLY's ``nx ny nz``, ``s t`` and ``red green blue``), and OBJ's ``vt`` in
    ``face_varying["uv"]``. Raises subdivkit.Error with the command line's message (naming
    the file and line) for missing files, unknown formats and bad content.
    """
    path = os.fspath(path)
    arrays = _subdivkit._read_mesh(path)
    return Mesh._from_arrays(arrays, name=path, point_data=arrays["point_data"], cell_data=arrays["cell_data"],
                             face_varying=arrays["face_varying"], point_roles=arrays["point_roles"],
                             cell_roles=arrays["cell_roles"])


def write_mesh(path, mesh, point_data=None, cell_data=None):
    """Write a Mesh by extension: .obj (exact doubles, polylines, crease and corner tags),
    .off, .ply, .stl, or .vtp / .pvd for ParaView.

    ``point_data`` and ``cell_data`` default to the mesh's own dicts, their roles are the
    mesh's ``point_roles`` and ``cell_roles``; .vtp, .pvd and .ply hold them all, integer
    arrays as integers; OFF holds normals, colours and texture coordinates, OBJ per-point
    texture coordinates (as ``vt``); what a format cannot hold is left out with a warning
    naming it. The file is written atomically: it
    is either complete or left as it was. Raises subdivkit.Error before creating anything
    for an unknown extension, a missing directory or an invalid mesh.
    """
    if not isinstance(mesh, Mesh):
        raise Error(f"write_mesh: expected a subdivkit.Mesh, got {_type_name(mesh)}")
    point_data = mesh.point_data if point_data is None else point_data
    cell_data = mesh.cell_data if cell_data is None else cell_data
    _subdivkit._write_mesh(os.fspath(path), mesh,
                           _data_arrays(point_data, mesh.point_roles, mesh.n_points, "point data"),
                           _data_arrays(cell_data, mesh.cell_roles, mesh.n_faces, "cell data"),
                           _face_varying_triples(mesh))
