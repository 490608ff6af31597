import os
from dataclasses import dataclass
from typing import Callable, Literal, Mapping, overload

import numpy as np
import numpy.typing as npt

from ._subdivkit import Scheme
from .mesh import Mesh

_SchemeArg = Scheme | str | os.PathLike[str]
_Params = Mapping[str, float | str] | None

@dataclass
class AdaptiveInfo:
    uniform_faces: int
    split_faces: list[int]
    corner_uv: npt.NDArray[np.float64]
    summary: str

@overload
def refine_adaptive(mesh: Mesh, scheme: _SchemeArg = "catmull-clark", levels: int = 1, *, tolerance: float = 0.0,
                    limit: bool = False, params: _Params = None, boundary: str = "edges-and-corners",
                    crease_method: str = "uniform", feature_angle: float = -1.0, threads: int = 0,
                    info: Literal[False] = False, fvar_boundary: str = "all",
                    progress: Callable[[str, float | None], object] | None = None,
                    transitions: Literal["polygons", "triangles"] = "polygons") -> Mesh: ...
@overload
def refine_adaptive(mesh: Mesh, scheme: _SchemeArg = "catmull-clark", levels: int = 1, *, tolerance: float = 0.0,
                    limit: bool = False, params: _Params = None, boundary: str = "edges-and-corners",
                    crease_method: str = "uniform", feature_angle: float = -1.0, threads: int = 0,
                    info: Literal[True], fvar_boundary: str = "all",
                    progress: Callable[[str, float | None], object] | None = None,
                    transitions: Literal["polygons", "triangles"] = "polygons") -> tuple[Mesh, AdaptiveInfo]: ...
