"""SubdivKit for Python: subdivision schemes as data, refined and analysed over NumPy arrays.

    import subdivkit as sk
    cube = sk.read_mesh("examples/meshes/cube.obj")
    fine = sk.refine(cube, "catmull-clark", 3)            # a Mesh: fine.points (n, 3), fine.faces (m, 4)
    S = sk.stencils(cube, "catmull-clark", 3, composed=True)
    assert abs(S @ cube.points - fine.points).max() < 1e-12
    print(sk.analyze("loop").subdominant)                  # lambda_1 per valence 3..12

    mine = sk.Scheme.from_dict({...})                       # a scheme written inline (docs/scheme-format.md)

Every failure the library reports (bad files, schemes, parameters, meshes) raises
subdivkit.Error, a ValueError, with the message the `subdiv` command line prints.
See docs/python.md.
"""

from ._subdivkit import Error, Scheme, __version__, load_plugin, schemes
from .analysis import CurveAnalysis, SurfaceAnalysis, analyze
from .mesh import Mesh, read_mesh, write_mesh
from .refinement import Interpolation, LimitPoints, interpolate, limit_positions, refine, stencils

__all__ = [
    "Error", "Scheme", "schemes", "load_plugin", "__version__",
    "Mesh", "read_mesh", "write_mesh",
    "refine", "stencils", "limit_positions", "interpolate", "LimitPoints", "Interpolation",
    "analyze", "SurfaceAnalysis", "CurveAnalysis",
]
