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


def paraview_plugin_path():
    """The ParaView plugin file (the "SubdivKit Refine" filter): load it in ParaView with
    Tools > Manage Plugins > Load New, or call load_paraview_plugin() from ParaView's Python."""
    import os
    return os.path.join(os.path.dirname(__file__), "paraview_plugin.py")


def load_paraview_plugin(ns=None):
    """Load the ParaView plugin into the running ParaView (pvpython, pvbatch or the GUI's
    Python Shell); ``ns=globals()`` makes ``SubdivKitRefine`` callable there.

    Debian 12's ParaView 5.11 cannot load any Python plugin as shipped (its loader imports
    ``inspect.getargspec``, which Python 3.11 removed); this function puts the function back
    first, so use it rather than Tools > Manage Plugins on such a system."""
    import inspect
    if not hasattr(inspect, "getargspec"):
        inspect.getargspec = inspect.getfullargspec  # ParaView only reads .args
    from paraview.simple import LoadPlugin
    return LoadPlugin(paraview_plugin_path(), ns=ns)


__all__ = [
    "Error", "Scheme", "schemes", "load_plugin", "__version__", "paraview_plugin_path", "load_paraview_plugin",
    "Mesh", "read_mesh", "write_mesh",
    "refine", "stencils", "limit_positions", "interpolate", "LimitPoints", "Interpolation",
    "analyze", "SurfaceAnalysis", "CurveAnalysis",
]
