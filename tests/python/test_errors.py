"""Bad input raises subdivkit.Error (a ValueError) with the command line's message, and
never takes the interpreter down."""
import json
import re
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


def test_triangle_scheme_on_quads_message_is_the_command_lines_in_pythons_words(tmp_path):
    path = str(MESHES / "cube.obj")
    expected = cli_error("refine", path, "-s", "loop", "-o", tmp_path / "x.obj")
    assert "`subdiv schemes` lists them" in expected
    with pytest.raises(sk.Error) as e:
        sk.refine(sk.read_mesh(path), "loop", 1)
    assert str(e.value) == expected.replace("`subdiv schemes`", "subdivkit.schemes()")


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


@pytest.mark.parametrize("call", [lambda m: sk.refine(m, "catmull-clark", 1, params={"gamma": 1}),
                                  lambda m: sk.limit_positions(m, "catmull-clark", params={"gamma": 1}),
                                  lambda m: sk.stencils(m, "catmull-clark", 1, params={"gamma": 1})])
def test_a_bad_params_entry_is_named_as_params_not_as_a_keyword_or_option(call):
    # refine(params={...}) takes a dict, not keywords: the message says where the value came from.
    with pytest.raises(sk.Error) as e:
        call(sk.read_mesh(str(MESHES / "cube.obj")))
    assert "parameter 'gamma' (from params gamma=1)" in str(e.value)
    assert "--" not in str(e.value) and "keyword" not in str(e.value)


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
        sk.analyze("catmull-clark", valences=[1])
    with pytest.raises(sk.Error, match="parameter"):
        sk.Scheme.load("four-point", w=True)
    with pytest.raises(sk.Error, match="no vertex selected"):
        sk.interpolate(cube, select=[])
    with pytest.raises(sk.Error, match="curve scheme refines polylines only"):
        sk.refine(cube, "chaikin", 1)
    # str(None) would be looked up as a scheme named "None"; a path object is a path.
    for not_a_scheme in (None, 42, ["loop"]):
        with pytest.raises(sk.Error, match="scheme: expected a subdivkit.Scheme, a name or a path"):
            sk.refine(cube, not_a_scheme, 1)
        with pytest.raises(sk.Error, match="scheme: expected a subdivkit.Scheme, a name or a path"):
            sk.LimitSurface(cube, not_a_scheme)
    assert len(sk.refine(cube, SCHEMES / "catmull-clark.json", 1).face_offsets) == 24 + 1


@pytest.mark.parametrize("call, name", [
    (lambda cube: sk.refine(cube, "catmull-clark", 1, threads=1.5), "threads=1.5"),
    (lambda cube: sk.refine(cube, "catmull-clark", 1, start_level="1"), "start_level='1'"),
    (lambda cube: sk.stencils(cube, "catmull-clark", 1, threads="2"), "threads='2'"),
    (lambda cube: sk.LimitSurface(cube, "catmull-clark").tessellate(2.5), "samples=2.5"),
    (lambda cube: sk.LimitSurface(cube, "catmull-clark").tessellate("8"), "samples='8'"),
    (lambda cube: sk.analyze("loop", [3.5]), "valences"),
    (lambda cube: sk.analyze("loop", [3], level=1.0), "level=1.0"),
    (lambda cube: sk.analyze("loop", [3], max_ring=True), "max_ring=True"),
])
def test_counts_must_be_whole_numbers_not_rounded(call, name):
    # int() would run 2.5 as 2 and take "8" as 8: a silently different request.
    with pytest.raises(sk.Error, match=re.escape(name) + ".*give"):
        call(sk.read_mesh(MESHES / "cube.obj"))


@pytest.mark.parametrize("call, name", [
    (lambda cube: sk.refine(cube, "catmull-clark", 10**10), "levels=10000000000"),
    (lambda cube: sk.refine(cube, "catmull-clark", 1, threads=2**31), "threads=2147483648"),
    (lambda cube: sk.LimitSurface(cube, "catmull-clark").evaluate([0], [[0.5, 0.5]], threads=10**12),
     "threads=1000000000000"),
    (lambda cube: sk.LimitSurface(cube, "catmull-clark").tessellate(-2**40), "samples=-1099511627776"),
    (lambda cube: sk.refine_adaptive(cube, "catmull-clark", 1, threads=2**40), "threads=1099511627776"),
    (lambda cube: sk.stencils(cube, "catmull-clark", 2**40), "levels=1099511627776"),
    (lambda cube: sk.analyze("loop", [4, 10**12]), "valences=1000000000000"),
])
def test_counts_beyond_a_c_int_are_refused_by_name(call, name):
    # pybind11 raised a TypeError listing the C++ signatures for a Python int beyond 32 bits.
    with pytest.raises(sk.Error, match=re.escape(name) + ": beyond a 32-bit int; give"):
        call(sk.read_mesh(MESHES / "cube.obj"))


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


def test_library_classes_refuse_new_without_a_factory():
    # pybind11 would make an object whose C++ value was never constructed; its methods read garbage.
    for cls in (sk.Scheme, sk._subdivkit._Evaluator, sk._subdivkit._LimitSurface):
        with pytest.raises(TypeError, match="not made with"):
            cls.__new__(cls)
        with pytest.raises(TypeError):
            cls()
    # The factories still make working objects.
    assert sk.Scheme.load("loop").name == "loop"
    assert sk.Evaluator(sk.read_mesh(str(MESHES / "cube.obj")), "catmull-clark", 1).n_points == 26


def test_mesh_attributes_are_checked_on_assignment_as_in_the_constructor():
    mesh = sk.read_mesh(str(MESHES / "cube.obj"))
    with pytest.raises(sk.Error, match="expected integer indices"):
        mesh.face_indices = mesh.face_indices.astype(np.float64) + 0.7  # would truncate
    with pytest.raises(sk.Error, match="out of range"):
        mesh.face_indices = np.array([0, 2**40], dtype=np.int64)  # would wrap
    with pytest.raises(sk.Error, match=r"shape \(n, 3\)"):
        mesh.points = np.zeros((8, 2))
    with pytest.raises(sk.Error, match="vertex pairs"):
        mesh.creases = np.array([1, 2, 3])
    with pytest.raises(sk.Error, match="one value per entry"):
        mesh.crease_sharpness = [1.0, 2.0]  # the cube has no creases
    # What is accepted is converted as the constructor converts it.
    mesh.points = mesh.points.astype(np.float32)
    assert mesh.points.dtype == np.float64 and mesh.points.flags["C_CONTIGUOUS"]
    mesh.corners = [0, 6]
    assert mesh.corners.dtype == np.int32 and mesh.corner_sharpness.shape == (0,)
    mesh.corner_sharpness = 3.0
    assert np.array_equal(mesh.corner_sharpness, [3.0, 3.0])
    assert sk.refine(mesh, "catmull-clark", 1).n_faces == 24


def test_non_finite_face_varying_values_and_results_are_refused():
    mesh = sk.read_mesh(str(MESHES / "cube.obj"))
    uv = np.zeros((8, 2))
    uv[3, 1] = np.nan
    mesh.face_varying["uv"] = (uv, np.arange(24, dtype=np.int32) % 8)
    with pytest.raises(sk.Error, match="face-varying 'uv': value 3 is nan"):
        sk.refine(mesh, "catmull-clark", 1)
    # Finite input that overflows under butterfly's negative weights: refused as the CLI refuses it.
    big = sk.Mesh(np.array([[0, 0, 0], [1.7e308, 0, 0], [1.7e308, 1.7e308, 0], [0, 1.7e308, 0]]), [[0, 1, 2], [0, 2, 3]])
    with pytest.raises(sk.Error, match="non-finite coordinate.*scale the mesh down"):
        sk.refine(big, "butterfly", 2)


# Issue 33: a message or a repr never carries a control byte of the user's text raw (an ESC
# sequence would drive the terminal). Class names are user text too: type() makes any.
HOSTILE = "e\x1b[2J\x00x"


def _assert_no_control_bytes(text):
    assert "\x1b" not in text and "\x00" not in text, f"raw control byte in {text!r}"


def test_wrong_argument_types_are_named_escaped():
    hostile_type = type("e\x1b[2J", (), {})()  # type names cannot hold a NUL
    calls = [lambda: sk.refine(hostile_type, "catmull-clark"),
             lambda: sk.write_mesh("out.obj", hostile_type),
             lambda: sk.evaluate(hostile_type, "catmull-clark", [0], [[0.5, 0.5]]),
             lambda: sk.refine_adaptive(hostile_type, "catmull-clark"),
             lambda: sk.analyze(hostile_type)]
    for call in calls:
        with pytest.raises(sk.Error) as e:
            call()
        _assert_no_control_bytes(str(e.value))
        assert "e\\x1b[2J" in str(e.value)


def test_reprs_and_labels_escape_the_mesh_name(cube_path):
    cube = sk.read_mesh(cube_path)
    mesh = sk.Mesh(cube.points, cube.faces, name=HOSTILE)
    _assert_no_control_bytes(repr(mesh))
    _assert_no_control_bytes(repr(sk.Evaluator(mesh, "catmull-clark", 1)))
    with pytest.raises(sk.Error) as e:
        sk.Mesh([[0.0, 0.0]], [[0, 0, 0]], name=HOSTILE)
    _assert_no_control_bytes(str(e.value))


def test_a_data_array_without_a_name_is_refused_before_refinement(tmp_path):
    """An array named '' would be refined and then refused by every writer (a .vtp array needs
    a name): refused where it is given, with no file written."""
    cube = sk.read_mesh(MESHES / "cube.obj")
    nameless = sk.Mesh(cube.points, cube.face_indices, face_offsets=cube.face_offsets,
                       point_data={"": np.zeros(cube.n_points)})
    with pytest.raises(sk.Error, match=r"^point data: an array has the empty name ''; give it a name"):
        sk.refine(nameless, "catmull-clark", 1)
    with pytest.raises(sk.Error, match=r"^point data: an array has the empty name ''"):
        sk.write_mesh(tmp_path / "out.vtp", nameless)
    assert not (tmp_path / "out.vtp").exists()


def test_ragged_lists_name_the_argument_and_the_shape_to_give():
    """Nested lists whose rows differ in length make no NumPy array: numpy's bare ValueError
    ("setting an array element with a sequence") named neither the argument nor the fix."""
    cube = sk.read_mesh(MESHES / "cube.obj")
    surface = sk.LimitSurface(cube, "catmull-clark")
    cases = [
        (lambda: surface.evaluate([0, 1], [[0.5, 0.5], [0.5]]), "uv", "(n, 2) array"),
        (lambda: surface.evaluate([[0], [1, 2]], [[0.5, 0.5], [0.5, 0.5]]), "faces", "(n,) array"),
        (lambda: sk.evaluate(cube, "catmull-clark", [0, 1], [[0.5, 0.5], [0.5]]), "uv", "(n, 2) array"),
        (lambda: surface.evaluate([0], [[0.5, 0.5]], points=[[0, 0, 0]] * 7 + [[0, 0]]), "points",
         "one row of values per control point"),
        (lambda: sk.Mesh([[0, 0, 0], [1, 0, 0], [0, 1]], [[0, 1, 2]]), "mesh.points", "(n, 3) array"),
        (lambda: sk.Mesh(np.eye(3), [[0, 1, 2]], creases=[[0, 1], [1]]), "creases", "(m, 2) array"),
        (lambda: sk.refine(sk.Mesh(np.eye(3), [[0, 1, 2]], point_data={"t": [[1, 2], [3], [4, 5]]}), "loop", 1),
         "point data 't'", "3 rows of equal length"),
    ]
    for call, name, fix in cases:
        with pytest.raises(sk.Error) as e:
            call()
        assert str(e.value).startswith(f"{name}: the rows have different lengths"), str(e.value)
        assert fix in str(e.value)
