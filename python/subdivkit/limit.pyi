import os
from dataclasses import dataclass
from typing import Any, Callable, Mapping

import numpy as np
import numpy.typing as npt

from ._subdivkit import Scheme as Scheme
from .mesh import Mesh

_SchemeArg = Scheme | str | os.PathLike[str]
_Params = Mapping[str, float | str] | None

@dataclass
class LimitEvaluation:
    points: npt.NDArray[np.float64]
    du: npt.NDArray[np.float64] | None = None
    dv: npt.NDArray[np.float64] | None = None
    duu: npt.NDArray[np.float64] | None = None
    duv: npt.NDArray[np.float64] | None = None
    dvv: npt.NDArray[np.float64] | None = None

@dataclass
class LimitStencils:
    points: Any
    du: Any = None
    dv: Any = None
    duu: Any = None
    duv: Any = None
    dvv: Any = None
    has_first: npt.NDArray[np.bool_] | None = None
    has_second: npt.NDArray[np.bool_] | None = None

class LimitSurface:
    name: str
    scheme: str
    def __init__(self, mesh: Mesh, scheme: _SchemeArg = "catmull-clark", *, params: _Params = None,
                 boundary: str = "edges-and-corners", crease_method: str = "uniform",
                 feature_angle: float = -1.0, fvar_boundary: str = "all") -> None: ...
    @property
    def triangles(self) -> bool: ...
    @property
    def n_points(self) -> int: ...
    @property
    def n_faces(self) -> int: ...
    @property
    def face_varying(self) -> list[str]: ...
    def evaluate_face_varying(self, name: str, faces: npt.ArrayLike, uv: npt.ArrayLike, derivatives: int = 1, *,
                              threads: int = 0) -> LimitEvaluation: ...
    def evaluate(self, faces: npt.ArrayLike, uv: npt.ArrayLike, derivatives: int = 1, *,
                 points: npt.ArrayLike | None = None, threads: int = 0) -> LimitEvaluation: ...
    def stencils(self, faces: npt.ArrayLike, uv: npt.ArrayLike, derivatives: int = 1, *,
                 threads: int = 0) -> LimitStencils: ...
    def tessellate(self, samples: int = 4, *, threads: int = 0,
                   progress: Callable[[str, float | None], object] | None = None) -> Mesh: ...
    def approximate_bezier(self, samples: int = 4, *, threads: int = 0) -> Mesh: ...
    def approximate_gregory(self, samples: int = 4, *, threads: int = 0) -> Mesh: ...

def evaluate(mesh: Mesh, scheme: _SchemeArg = "catmull-clark", faces: npt.ArrayLike = (), uv: npt.ArrayLike = (),
             derivatives: int = 1, *, params: _Params = None, boundary: str = "edges-and-corners",
             crease_method: str = "uniform", threads: int = 0) -> LimitEvaluation: ...
