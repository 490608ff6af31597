"""SubdivKit for Python: subdivision schemes as data, refined and analysed over NumPy arrays.

    import subdivkit as sk
    cube = sk.read_mesh("examples/meshes/cube.obj")
    fine = sk.refine(cube, "catmull-clark", 3)            # a Mesh: fine.points (n, 3), fine.faces (m, 4)
    S = sk.stencils(cube, "catmull-clark", 3, composed=True)
    assert abs(S @ cube.points - fine.points).max() < 1e-12
    ev = sk.Evaluator(cube, "catmull-clark", 3)           # topology once, then ev.evaluate(P) per frame
    print(sk.analyze("loop").subdominant)                  # lambda_1 per valence 3..12
    r = sk.evaluate(cube, "catmull-clark", [0], [[0.5, 0.5]], derivatives=2)  # exact limit: r.points, r.du, r.duu

    mine = sk.Scheme.from_dict({...})                       # a scheme written inline (docs/scheme-format.md)
    sk.to_vtk(fine), sk.from_open3d(o3d_mesh), sk.to_trimesh(fine)  # other libraries' meshes

Every failure the library reports (bad files, schemes, parameters, meshes) raises
subdivkit.Error, a ValueError, with the message the `subdiv` command line prints (options
named as Python's arguments).
See docs/python.md.
"""

from ._subdivkit import Error, Scheme, __version__, load_plugin, schemes
from .adaptive import AdaptiveInfo, refine_adaptive
from .analysis import CurveAnalysis, SurfaceAnalysis, analyze
from .conversions import from_open3d, from_trimesh, from_vtk, to_open3d, to_trimesh, to_vtk
from .limit import LimitEvaluation, LimitStencils, LimitSurface, evaluate
from .mesh import Mesh, read_mesh, write_mesh
from .parameterize import parameterize
from .refinement import Evaluator, Interpolation, LimitPoints, interpolate, limit_positions, refine, stencils


def paraview_plugin_path():
    """The ParaView plugin SubdivKit.so (filters "SubdivKit Refine" and "SubdivKit Analyze",
    plugins/paraview): $SUBDIV_PARAVIEW_PLUGIN, else the one beside this package (a build
    tree's, or an installed tree's in <libdir>/paraview-X.Y/plugins/SubdivKit). Raises
    Error when there is none: the plugin is built only against ParaView's development files."""
    import glob
    import os
    if os.environ.get("SUBDIV_PARAVIEW_PLUGIN"):
        return os.environ["SUBDIV_PARAVIEW_PLUGIN"]
    here = os.path.dirname(os.path.abspath(__file__))
    patterns = ("../../lib*/paraview-*/plugins/SubdivKit/SubdivKit.so",         # <build>/python/subdivkit
                "../../../../lib*/paraview-*/plugins/SubdivKit/SubdivKit.so",   # <prefix>/lib/python3/...
                "../../../../lib/*/paraview-*/plugins/SubdivKit/SubdivKit.so")  # ... with lib/<arch>
    for pattern in patterns:
        found = sorted(glob.glob(os.path.join(here, pattern)))
        if found:
            return os.path.normpath(found[-1])
    raise Error("no ParaView plugin SubdivKit.so beside this subdivkit package: build SubdivKit beside ParaView "
                "(paraview-dev; scripts/install-deps.sh installs it) or set SUBDIV_PARAVIEW_PLUGIN to the plugin's path")


def load_paraview_plugin(ns=None):
    """Load the ParaView plugin (paraview_plugin_path()) into the running ParaView (pvpython,
    pvbatch or the GUI's Python Shell); ``ns=globals()`` makes ``SubdivKitRefine`` and
    ``SubdivKitAnalyze`` callable there. The same as ParaView's
    ``LoadPlugin(subdivkit.paraview_plugin_path(), remote=False, ns=globals())``."""
    from paraview.simple import LoadPlugin
    return LoadPlugin(paraview_plugin_path(), remote=False, ns=ns)


__all__ = [
    "Error", "Scheme", "schemes", "load_plugin", "__version__", "paraview_plugin_path", "load_paraview_plugin",
    "Mesh", "read_mesh", "write_mesh", "parameterize",
    "refine", "Evaluator", "stencils", "limit_positions", "interpolate", "LimitPoints", "Interpolation",
    "analyze", "SurfaceAnalysis", "CurveAnalysis",
    "evaluate", "LimitSurface", "LimitEvaluation", "LimitStencils",
    "from_vtk", "to_vtk", "from_open3d", "to_open3d", "from_trimesh", "to_trimesh",
    "refine_adaptive", "AdaptiveInfo",
]
