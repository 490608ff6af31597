import os
from typing import Any, Mapping, Sequence

import numpy as np
import numpy.typing as npt

_PathLike = str | os.PathLike[str]
_Cells = npt.ArrayLike | Sequence[Sequence[int]]
_Sharpness = float | npt.ArrayLike | None
_Arrays = Mapping[str, npt.ArrayLike]

INFINITELY_SHARP: float
ROLES: tuple[str, ...]

class Mesh:
    name: str
    points: npt.NDArray[np.float64]
    face_indices: npt.NDArray[np.int32]
    face_offsets: npt.NDArray[np.int32]
    line_indices: npt.NDArray[np.int32]
    line_offsets: npt.NDArray[np.int32]
    creases: npt.NDArray[np.int32]
    crease_sharpness: npt.NDArray[np.float64]
    corners: npt.NDArray[np.int32]
    corner_sharpness: npt.NDArray[np.float64]
    point_data: dict[str, npt.NDArray[Any]]
    cell_data: dict[str, npt.NDArray[Any]]
    face_varying: dict[str, tuple[npt.NDArray[np.float64], npt.NDArray[np.int32]]]
    point_roles: dict[str, str]
    cell_roles: dict[str, str]
    def __init__(
        self,
        points: npt.ArrayLike,
        faces: _Cells | None = None,
        *,
        face_offsets: npt.ArrayLike | None = None,
        lines: _Cells | None = None,
        line_offsets: npt.ArrayLike | None = None,
        creases: npt.ArrayLike | None = None,
        crease_sharpness: _Sharpness = None,
        corners: npt.ArrayLike | None = None,
        corner_sharpness: _Sharpness = None,
        point_data: _Arrays | None = None,
        cell_data: _Arrays | None = None,
        face_varying: Mapping[str, tuple[npt.ArrayLike, npt.ArrayLike]] | None = None,
        point_roles: Mapping[str, str] | None = None,
        cell_roles: Mapping[str, str] | None = None,
        name: str = "mesh",
    ) -> None: ...
    @property
    def n_points(self) -> int: ...
    @property
    def n_faces(self) -> int: ...
    @property
    def n_lines(self) -> int: ...
    @property
    def face_sizes(self) -> npt.NDArray[np.int32]: ...
    @property
    def faces(self) -> npt.NDArray[np.int32]: ...
    def face_list(self) -> list[npt.NDArray[np.int32]]: ...
    def line_list(self) -> list[npt.NDArray[np.int32]]: ...
    def with_points(self, points: npt.ArrayLike) -> Mesh: ...

def read_mesh(path: _PathLike) -> Mesh: ...
def write_mesh(path: _PathLike, mesh: Mesh, point_data: _Arrays | None = None, cell_data: _Arrays | None = None) -> None: ...
