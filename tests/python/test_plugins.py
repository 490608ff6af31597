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
