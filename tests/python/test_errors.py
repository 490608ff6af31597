"""Bad input raises subdivkit.Error (a ValueError) with the command line's message, and
never takes the interpreter down."""
import json
import subprocess
import sys

import numpy as np
import pytest

import subdivkit as sk
from conftest import MESHES, SCHEMES, cli_error


def test_error_is_a_value_error():
    assert issubclass(sk.Error, ValueError)
    assert sk.Error.__module__ == "subdivkit"


def test_unknown_scheme_message_is_the_command_lines(tmp_path):
    expected = cli_error("refine", MESHES / "cube.obj", "-s", "no-such-scheme", "-o", tmp_path / "x.obj")
    with pytest.raises(sk.Error) as e:
        sk.Scheme.load("no-such-scheme")
    assert str(e.value) == expected
    with pytest.raises(sk.Error) as e:
        sk.refine(sk.read_mesh(MESHES / "cube.obj"), "no-such-scheme", 1)
    assert str(e.value) == expected


def test_missing_mesh_file_message_is_the_command_lines(tmp_path):
    missing = str(tmp_path / "missing.obj")
    expected = cli_error("refine", missing, "-o", tmp_path / "x.obj")
    with pytest.raises(sk.Error) as e:
        sk.read_mesh(missing)
    assert str(e.value) == expected


def test_triangle_scheme_on_quads_message_is_the_command_lines(tmp_path):
    path = str(MESHES / "cube.obj")
    expected = cli_error("refine", path, "-s", "loop", "-o", tmp_path / "x.obj")
    with pytest.raises(sk.Error) as e:
        sk.refine(sk.read_mesh(path), "loop", 1)
    assert str(e.value) == expected


@pytest.mark.parametrize("scheme,param,value", [("four-point", "w", "abc"), ("four-point", "w", 3),
                                                ("loop", "beta", "nope"), ("loop", "gamma", 1)])
def test_bad_parameter_messages_are_the_command_lines(scheme, param, value):
    # The same message, naming Python's argument and listing function where the command line
    # names its option and command (the library's placeholders, framework/util/option_spelling.h).
    expected = cli_error("analyze", scheme, "-p", f"{param}={value}")
    expected = expected.replace("from --param ", "from keyword argument ").replace("`subdiv schemes`",
                                                                                    "subdivkit.schemes()")
    with pytest.raises(sk.Error) as e:
        sk.Scheme.load(scheme, **{param: value})
    assert str(e.value) == expected
    assert "--" not in str(e.value)


def test_bad_scheme_file_and_text_messages_are_the_command_lines(tmp_path):
    bad = json.loads((SCHEMES / "catmull-clark.json").read_text())
    bad["rules"]["edge"][0]["sum"] = "no-such-role"
    path = tmp_path / "bad.json"
    path.write_text(json.dumps(bad, indent=2))
    expected = cli_error("analyze", path)
    assert "no-such-role" in expected
    with pytest.raises(sk.Error) as e:
        sk.Scheme.load(str(path))
    assert str(e.value) == expected
    with pytest.raises(sk.Error) as e:
        sk.Scheme.from_dict(bad)
    assert "no-such-role" in str(e.value) and "<dict>" in str(e.value)


def test_malformed_json_text_is_an_error():
    with pytest.raises(sk.Error, match="<json>"):
        sk.Scheme.from_json("{ not json")
    with pytest.raises(sk.Error, match="cannot be written as JSON"):
        sk.Scheme.from_dict({"name": object()})


def test_bad_meshes_are_refused_with_the_reason():
    square = [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]]
    with pytest.raises(sk.Error, match="out of range|does not exist|has 4 vertices"):
        sk.refine(sk.Mesh(square, [[0, 1, 2, 7]]), "catmull-clark", 1)
    with pytest.raises(sk.Error, match="non-finite"):
        sk.refine(sk.Mesh([[0, 0, np.nan], [1, 0, 0], [1, 1, 0], [0, 1, 0]], [[0, 1, 2, 3]]), "catmull-clark", 1)
    # Three faces on one edge: refined as OpenSubdiv does by primal schemes, and by sqrt3
    # with the edge kept as a crease (three triangles per face).
    points = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, -1, 0], [0, 0, 1]]
    flaps = sk.Mesh(points, [[0, 1, 2], [1, 0, 3], [0, 1, 4]])
    assert len(sk.refine(flaps, "loop", 1).faces) == 12
    assert len(sk.refine(flaps, "sqrt3", 1).faces) == 9
    with pytest.raises(sk.Error, match="no faces"):
        sk.refine(sk.Mesh(square), "catmull-clark", 1)
    with pytest.raises(sk.Error, match="crease"):
        sk.refine(sk.Mesh(square, [[0, 1, 2, 3]], creases=[[0, 2]]), "catmull-clark", 1)


def test_bad_options_are_refused():
    cube = sk.read_mesh(MESHES / "cube.obj")
    with pytest.raises(sk.Error, match="boundary='corners'"):
        sk.refine(cube, "catmull-clark", 1, boundary="corners")
    with pytest.raises(sk.Error, match="crease_method"):
        sk.refine(cube, "catmull-clark", 1, crease_method="sharp")
    with pytest.raises(sk.Error, match="levels=-1"):
        sk.refine(cube, "catmull-clark", -1)
    with pytest.raises(sk.Error, match="levels"):
        sk.refine(cube, "catmull-clark", 1.5)
    with pytest.raises(sk.Error, match="subdivkit.Mesh"):
        sk.refine(cube.points, "catmull-clark", 1)
    with pytest.raises(sk.Error, match="valences"):
        sk.analyze("catmull-clark", valences=[2])
    with pytest.raises(sk.Error, match="parameter"):
        sk.Scheme.load("four-point", w=True)
    with pytest.raises(sk.Error, match="no vertex selected"):
        sk.interpolate(cube, select=[])
    with pytest.raises(sk.Error, match="curve scheme refines polylines only"):
        sk.refine(cube, "chaikin", 1)


def test_missing_and_foreign_plugins_are_refused():
    with pytest.raises(sk.Error, match="refused"):
        sk.load_plugin("/no/such/plugin.so")
    with pytest.raises(sk.Error, match="not a SubdivKit plugin|cannot|refused"):
        sk.load_plugin(sys.executable)


def test_the_interpreter_survives_a_run_of_bad_input(tmp_path):
    # In a fresh interpreter, so that a crash would show as a signal exit code.
    script = """
import numpy as np, subdivkit as sk
bad = [lambda: sk.refine(sk.Mesh(np.zeros((3, 3)), [[0, 1, 5]]), 'loop', 1),
       lambda: sk.refine(sk.Mesh(np.zeros((3, 3)), [[0, 1, 2]]), 'loop', 1),
       lambda: sk.Mesh(np.zeros((3, 3)), [[0, 1, 2]], face_offsets=[0, 5]),
       lambda: sk.stencils(sk.Mesh(np.zeros((4, 3)), [[0, 1, 2, 3]]), 'loop', 30),
       lambda: sk.write_mesh('/no/such/dir/x.obj', sk.Mesh(np.eye(3), [[0, 1, 2]])),
       lambda: sk.Scheme.from_dict({}),
       lambda: sk.Scheme.from_dict({'name': 'x', 'split': 'quad', 'rules': {}}),
       lambda: sk.interpolate(sk.Mesh(np.eye(3), [[0, 1, 2]]), 'catmull-clark', select=[7])]
for f in bad:
    try:
        f()
    except sk.Error:
        pass
print('survived')
"""
    result = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True)
    assert result.returncode == 0, result.stderr
    assert result.stdout.strip() == "survived"
