from typing import Literal

import numpy.typing as npt

from .mesh import Mesh

def parameterize(mesh: Mesh, *, boundary: Literal["circle", "square"] = "circle",
                 corners: npt.ArrayLike | None = None,
                 weights: Literal["uniform", "mean-value"] = "uniform") -> Mesh: ...
