# Types of the subdivkit package (PEP 561: py.typed beside this file). The modules' own
# .pyi files hold the signatures; NumPy arrays are numpy.typing.NDArray with their dtype.
from typing import Any

from ._subdivkit import Error as Error, Scheme as Scheme, __version__ as __version__, load_plugin as load_plugin
from ._subdivkit import schemes as schemes
from .adaptive import AdaptiveInfo as AdaptiveInfo, refine_adaptive as refine_adaptive
from .analysis import CurveAnalysis as CurveAnalysis, SurfaceAnalysis as SurfaceAnalysis, analyze as analyze
from .conversions import from_open3d as from_open3d, from_trimesh as from_trimesh, from_vtk as from_vtk
from .conversions import to_open3d as to_open3d, to_trimesh as to_trimesh, to_vtk as to_vtk
from .limit import LimitEvaluation as LimitEvaluation, LimitStencils as LimitStencils
from .limit import LimitSurface as LimitSurface, evaluate as evaluate
from .mesh import Mesh as Mesh, read_mesh as read_mesh, write_mesh as write_mesh
from .parameterize import parameterize as parameterize
from .refinement import Evaluator as Evaluator, Interpolation as Interpolation, LimitPoints as LimitPoints
from .refinement import interpolate as interpolate, limit_positions as limit_positions, refine as refine
from .refinement import stencils as stencils

def paraview_plugin_path() -> str: ...
def load_paraview_plugin(ns: dict[str, Any] | None = None) -> Any: ...

__all__ = [
    "Error", "Scheme", "schemes", "load_plugin", "__version__", "paraview_plugin_path", "load_paraview_plugin",
    "Mesh", "read_mesh", "write_mesh", "parameterize",
    "refine", "Evaluator", "stencils", "limit_positions", "interpolate", "LimitPoints", "Interpolation",
    "analyze", "SurfaceAnalysis", "CurveAnalysis",
    "evaluate", "LimitSurface", "LimitEvaluation", "LimitStencils",
    "from_vtk", "to_vtk", "from_open3d", "to_open3d", "from_trimesh", "to_trimesh",
    "refine_adaptive", "AdaptiveInfo",
]
