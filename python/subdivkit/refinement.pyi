import os
from dataclasses import dataclass
from typing import Any, Callable, Literal, Mapping, overload

import numpy as np
import numpy.typing as npt

from ._subdivkit import Scheme as Scheme
from .mesh import Mesh

_SchemeArg = Scheme | str | os.PathLike[str]
_Params = Mapping[str, float | str] | None
_Progress = Callable[[str, float | None], object] | None

BOUNDARY_MODES: tuple[str, ...]

@overload
def refine(mesh: Mesh, scheme: _SchemeArg = "catmull-clark", levels: int = 1, *, params: _Params = None,
           boundary: str = "edges-and-corners", crease_method: str = "uniform", threads: int = 0,
           all_levels: Literal[False] = False, start_level: int = 0, fvar_boundary: str = "all",
           weights: npt.ArrayLike | str | None = None, arrays: str = "none",
           progress: _Progress = None) -> Mesh: ...
@overload
def refine(mesh: Mesh, scheme: _SchemeArg = "catmull-clark", levels: int = 1, *, params: _Params = None,
           boundary: str = "edges-and-corners", crease_method: str = "uniform", threads: int = 0,
           all_levels: Literal[True], start_level: int = 0, fvar_boundary: str = "all",
           weights: npt.ArrayLike | str | None = None, arrays: str = "none",
           progress: _Progress = None) -> list[Mesh]: ...
@overload
def refine(mesh: Mesh, scheme: _SchemeArg = "catmull-clark", levels: int = 1, *, params: _Params = None,
           boundary: str = "edges-and-corners", crease_method: str = "uniform", threads: int = 0,
           all_levels: bool, start_level: int = 0, fvar_boundary: str = "all",
           weights: npt.ArrayLike | str | None = None, arrays: str = "none",
           progress: _Progress = None) -> Mesh | list[Mesh]: ...

class Evaluator:
    name: str
    scheme: str
    def __init__(self, mesh: Mesh, scheme: _SchemeArg = "catmull-clark", levels: int = 1, *, params: _Params = None,
                 boundary: str = "edges-and-corners", crease_method: str = "uniform", threads: int = 0,
                 start_level: int = 0) -> None: ...
    @property
    def levels(self) -> int: ...
    @property
    def n_base_points(self) -> int: ...
    @property
    def n_points(self) -> int: ...
    @property
    def n_faces(self) -> int: ...
    @property
    def face_indices(self) -> npt.NDArray[np.int32]: ...
    @property
    def face_offsets(self) -> npt.NDArray[np.int32]: ...
    @property
    def face_sizes(self) -> npt.NDArray[np.int32]: ...
    @property
    def faces(self) -> npt.NDArray[np.int32]: ...
    def face_list(self) -> list[npt.NDArray[np.int32]]: ...
    @property
    def creases(self) -> npt.NDArray[np.int32]: ...
    @property
    def crease_sharpness(self) -> npt.NDArray[np.float64]: ...
    @property
    def corners(self) -> npt.NDArray[np.int32]: ...
    @property
    def corner_sharpness(self) -> npt.NDArray[np.float64]: ...
    def evaluate(self, points: npt.ArrayLike) -> npt.NDArray[np.float64]: ...
    def mesh(self, points: npt.ArrayLike | None = None) -> Mesh: ...

# scipy.sparse.csr_matrix (SciPy has no type information in Debian 12): Any.
@overload
def stencils(mesh: Mesh, scheme: _SchemeArg = "catmull-clark", levels: int = 1, *, composed: Literal[False] = False,
             params: _Params = None, boundary: str = "edges-and-corners", crease_method: str = "uniform",
             threads: int = 0, start_level: int = 0) -> list[Any]: ...
@overload
def stencils(mesh: Mesh, scheme: _SchemeArg = "catmull-clark", levels: int = 1, *, composed: Literal[True],
             params: _Params = None, boundary: str = "edges-and-corners", crease_method: str = "uniform",
             threads: int = 0, start_level: int = 0) -> Any: ...

@dataclass
class LimitPoints:
    points: npt.NDArray[np.float64]
    normals: npt.NDArray[np.float64] | None = None
    exact: npt.NDArray[np.bool_] | None = None
    normal_exact: npt.NDArray[np.bool_] | None = None
    approximate_reasons: list[str] = ...

def limit_positions(mesh: Mesh, scheme: _SchemeArg = "catmull-clark", *, params: _Params = None,
                    boundary: str = "edges-and-corners", crease_method: str = "uniform",
                    start_level: int = 0) -> LimitPoints: ...

@dataclass
class Interpolation:
    mesh: Mesh
    limit: npt.NDArray[np.float64]
    iterations: int
    converged: bool
    max_residual: npt.NDArray[np.float64]
    rms_residual: npt.NDArray[np.float64]
    tolerance: float
    limit_description: str
    fixed_note: str = ...

def interpolate(mesh: Mesh, scheme: _SchemeArg = "catmull-clark", *, select: str | npt.ArrayLike | None = None,
                tolerance: float | None = None, max_iterations: int = 1000, params: _Params = None,
                boundary: str = "edges-and-corners", threads: int = 0) -> Interpolation: ...

__all__ = ["refine", "Evaluator", "stencils", "limit_positions", "interpolate", "LimitPoints", "Interpolation", "Scheme"]
