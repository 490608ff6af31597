"""load_plugin(): a plugin's schemes load by name and refine like the command line's; a
plugin built for another interface is refused. Each test runs in a fresh interpreter, as
a loaded plugin stays registered for the life of the process."""
import os
import subprocess
import sys

import numpy as np
import pytest

from conftest import MESHES, cli_error, parse_obj, run_cli


def plugin(target):
    path = os.environ.get(f"SUBDIV_PLUGIN_{target}")
    if not path or not os.path.exists(path):
        pytest.skip(f"plugin {target} is not built (ctest passes its path)")
    return path


def run_python(script):
    result = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True)
    assert result.returncode == 0, result.stderr
    return result.stdout


def test_a_plugin_scheme_refines_like_the_command_line(tmp_path):
    path = plugin("subdiv_sqrt2")
    mesh = str(MESHES / "cube.obj")
    out = tmp_path / "sqrt2.obj"
    run_cli("--plugin", path, "refine", mesh, "-s", "sqrt2", "-l", 2, "-o", out, "-q")
    expected, _ = parse_obj(out)
    np.save(tmp_path / "expected.npy", expected)
    printed = run_python(f"""
import numpy as np, subdivkit as sk
info = sk.load_plugin({path!r})
assert info["name"] == "sqrt2", info
assert sk.load_plugin({path!r}) == info  # a second load returns the first
assert any(s["name"] == "sqrt2" and s["origin"] == "plugin sqrt2" for s in sk.schemes())
fine = sk.refine(sk.read_mesh({mesh!r}), "sqrt2", 2)
print(np.abs(fine.points - np.load({str(tmp_path / "expected.npy")!r})).max())
""")
    assert float(printed) <= 1e-15


def test_a_plugin_for_another_interface_is_refused_with_the_reason():
    path = plugin("test_plugin_wrong_version")
    printed = run_python(f"""
import subdivkit as sk
try:
    sk.load_plugin({path!r})
except sk.Error as e:
    print(e)
""")
    assert "interface version mismatch" in printed
    assert path in printed


def test_a_non_linear_curve_scheme_refines_polylines_like_the_command_line(tmp_path):
    """circle-four-point (Sabin & Dodgson 2004) keeps points on a circle, which no linear
    rule does: Python runs it through the same curve pipeline as `subdiv refine`."""
    path = plugin("subdiv_circle_preserving")
    angles = np.array([0.0, 0.7, 1.9, 2.6, 3.9, 5.1])
    source = tmp_path / "polygon.obj"
    source.write_text("".join(f"v {2 * np.cos(a)!r} {2 * np.sin(a)!r} 0\n" for a in angles) + "l 1 2 3 4 5 6 1\n")
    out = tmp_path / "circle.obj"
    run_cli("--plugin", path, "refine", source, "-s", "circle-four-point", "-l", 4, "-o", out, "-q")
    expected, _ = parse_obj(out)
    np.save(tmp_path / "expected.npy", expected)
    printed = run_python(f"""
import numpy as np, subdivkit as sk, warnings
sk.load_plugin({path!r})
mesh = sk.read_mesh({str(source)!r})
mesh.point_data["t"] = np.arange(mesh.n_points, dtype=float)
with warnings.catch_warnings(record=True) as said:
    warnings.simplefilter("always")
    fine = sk.refine(mesh, "circle-four-point", 4)
assert any("'t' is not carried" in str(w.message) for w in said), [str(w.message) for w in said]
radius = np.linalg.norm(fine.points[:, :2], axis=1)
print(np.abs(fine.points - np.load({str(tmp_path / "expected.npy")!r})).max(), np.abs(radius - 2).max())
""")
    difference, off_circle = (float(x) for x in printed.split())
    assert difference <= 1e-15
    assert off_circle <= 1e-12
