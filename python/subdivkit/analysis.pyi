from dataclasses import dataclass
from typing import Any, Iterable

import numpy as np
import numpy.typing as npt

from ._subdivkit import Scheme

@dataclass
class SurfaceAnalysis:
    scheme: str
    valences: npt.NDArray[np.int_]
    subdominant: npt.NDArray[np.float64]
    lambda2: npt.NDArray[np.float64]
    lambda3: npt.NDArray[np.float64]
    c1: npt.NDArray[np.bool_]
    verdicts: list[str]
    eigenvalues: list[npt.NDArray[np.complex128]]
    matrices: list[npt.NDArray[np.float64]]
    limit_masks: list[npt.NDArray[np.float64]]
    tangent_masks: list[npt.NDArray[np.float64]]
    details: list[dict[str, Any]]
    def spectrum(self, count: int = 8) -> npt.NDArray[np.float64]: ...

@dataclass
class CurveAnalysis:
    scheme: str
    arity: int
    mask: npt.NDArray[np.float64]
    mask_first: int
    symbol: npt.NDArray[np.float64]
    symbol_lowest: int
    convergent: bool
    smoothness: int
    eigenvalues: npt.NDArray[np.complex128]
    subdominant: complex
    matrix: npt.NDArray[np.float64]
    limit_mask: npt.NDArray[np.float64]
    tangent_mask: npt.NDArray[np.float64]
    summary: str
    details: dict[str, Any]

def analyze(scheme: Scheme | str, valences: Iterable[int] | npt.ArrayLike = ..., *, boundary: bool = False,
            crease: bool = False, corner: bool = False, boundary_interpolation: str = "edges-and-corners",
            level: int = 0, max_ring: int = 5,
            characteristic_map: bool = True) -> SurfaceAnalysis | CurveAnalysis: ...
