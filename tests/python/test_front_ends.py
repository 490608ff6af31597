"""The command line and the Python module are two translations of one pipeline
(framework/pipeline): for the same request they give the same levels — points, faces, the
user's point, cell and face-varying arrays, hole faces left out — on meshes with boundaries
and holes, creases and corners, a non-manifold edge, UV seams, point and cell data. The CLI's
output is written to a file and read back; the ParaView filter is compared with the CLI in
tests/paraview/refine_test.py."""
import importlib.util

import numpy as np
import pytest

import subdivkit as sk
from conftest import MESHES, cli_error, run_cli


def with_data(mesh):
    """`mesh` with a float point array (a smooth function of position, 2 columns), an integer
    point label and a cell array, so that each kind of array goes through both front-ends."""
    p = mesh.points
    point_data = {"field": np.column_stack([p[:, 0] * p[:, 1] + p[:, 2], np.sin(p[:, 0])]),
                  "label": np.arange(mesh.n_points, dtype=np.int32) % 3}
    cell_data = {"face_id": np.arange(mesh.n_faces, dtype=float)}
    out = sk.Mesh(mesh.points, face_offsets=mesh.face_offsets, faces=mesh.face_indices, creases=mesh.creases,
                  crease_sharpness=mesh.crease_sharpness, corners=mesh.corners, corner_sharpness=mesh.corner_sharpness,
                  point_data=point_data, cell_data=cell_data)
    return out


HAS_VTK = importlib.util.find_spec("vtkmodules") is not None
DESCRIBED_ARRAYS = {"point": ("origin", "valence", "level", "vertex_class"), "cell": ("parent_face", "base_face")}


def vtp_arrays(path):
    """The point and cell arrays of a .vtp as VTK reads them (subdivkit.read_mesh takes
    SubdivKit's own arrays as the file's description and leaves them out); cell arrays of
    the polygons only (a .vtp holds crease edges as line cells before them)."""
    from vtkmodules.util.numpy_support import vtk_to_numpy
    from vtkmodules.vtkIOXML import vtkXMLPolyDataReader
    reader = vtkXMLPolyDataReader()
    reader.SetFileName(str(path))
    reader.Update()
    data = reader.GetOutput()
    lines = data.GetNumberOfLines() + data.GetNumberOfVerts()

    def arrays(attributes, skip):
        return {attributes.GetArrayName(i): vtk_to_numpy(attributes.GetArray(i)).astype(float).ravel()[skip:]
                for i in range(attributes.GetNumberOfArrays())}
    return {"point": arrays(data.GetPointData(), 0), "cell": arrays(data.GetCellData(), lines)}

CASES = [  # mesh, scheme, levels, CLI options, Python keywords
    ("plane-with-hole.obj", "catmull-clark", 2, ["--boundary", "edges"], {"boundary": "edges"}),
    ("plane-with-hole.obj", "catmull-clark", 1, ["--boundary", "none"], {"boundary": "none"}),  # hole faces
    ("cube-creased.obj", "catmull-clark", 2, ["--crease-method", "chaikin"], {"crease_method": "chaikin"}),
    ("flap-fan.obj", "catmull-clark", 2, [], {}),  # a non-manifold edge
    ("octahedron.obj", "loop", 2, [], {}),
    ("octahedron.obj", "sqrt3", 3, [], {}),  # boundary-free; trisection steps alternate
    ("cube.obj", "doo-sabin", 2, [], {}),
]


@pytest.mark.parametrize("mesh_name,scheme,levels,cli_options,keywords", CASES)
def test_cli_and_python_give_the_same_level_with_its_arrays(tmp_path, mesh_name, scheme, levels, cli_options,
                                                             keywords):
    mesh = with_data(sk.read_mesh(str(MESHES / mesh_name)))
    source = tmp_path / "in.vtp"
    sk.write_mesh(str(source), mesh)
    out = tmp_path / "out.vtp"
    run_cli("refine", source, "-s", scheme, "-l", levels, "--arrays", "all", "-o", out, "-q", *cli_options)
    cli = sk.read_mesh(str(out))
    python = sk.refine(mesh, scheme, levels, arrays="all", **keywords)

    assert python.points.shape == cli.points.shape
    assert np.abs(python.points - cli.points).max() <= 1e-14
    assert [list(f) for f in python.face_list()] == [list(f) for f in cli.face_list()]
    for name in ("field", "label"):
        assert np.abs(np.asarray(python.point_data[name], float).reshape(cli.point_data[name].shape)
                      - cli.point_data[name]).max() <= 1e-14, name
    assert np.array_equal(np.asarray(python.cell_data["face_id"]).ravel(), np.asarray(cli.cell_data["face_id"]).ravel())
    if HAS_VTK:  # the level's description (README's table of SubdivKit's arrays), the same in both
        written = vtp_arrays(out)
        for kind, mine in (("point", python.point_data), ("cell", python.cell_data)):
            for name in DESCRIBED_ARRAYS[kind]:
                assert np.array_equal(np.asarray(mine[name], float).ravel(), written[kind][name]), (kind, name)


@pytest.mark.parametrize("mesh_name,scheme,mode", [("textured-tube.obj", "catmull-clark", "corners-only"),
                                                   ("textured-tube.obj", "catmull-clark", "all"),
                                                   ("textured-tube-triangles-creased.obj", "loop", "none")])
def test_cli_and_python_carry_the_same_face_varying_data(tmp_path, mesh_name, scheme, mode):
    path = str(MESHES / mesh_name)
    out = tmp_path / "out.obj"  # OBJ keeps face-varying data as vt with its own indices
    run_cli("refine", path, "-s", scheme, "-l", 2, "--fvar-boundary", mode, "-o", out, "-q")
    cli = sk.read_mesh(str(out))
    python = sk.refine(sk.read_mesh(path), scheme, 2, fvar_boundary=mode)
    assert np.abs(python.points - cli.points).max() <= 1e-14
    (name, (values, indices)), = python.face_varying.items()
    cli_values, cli_indices = cli.face_varying[name]
    # Same UV at every face corner (OBJ may number the values differently).
    assert np.abs(np.asarray(values)[np.asarray(indices)] - np.asarray(cli_values)[np.asarray(cli_indices)]).max() <= 1e-14


def test_unused_vertices_are_dropped_by_both_front_ends_with_a_warning(tmp_path):
    cube = sk.read_mesh(str(MESHES / "cube.obj"))
    lonely = sk.Mesh(np.vstack([cube.points, [[5.0, 5.0, 5.0]]]), face_offsets=cube.face_offsets, faces=cube.face_indices)
    source = tmp_path / "lonely.obj"
    sk.write_mesh(str(source), lonely)
    result = run_cli("refine", source, "-l", 1, "-o", tmp_path / "out.obj")
    assert "warning" in result.stderr and "1 vert" in result.stderr
    with pytest.warns(UserWarning, match="1 vert"):
        fine = sk.refine(lonely, "catmull-clark", 1)
    assert fine.n_points == 26  # the cube's 8 + 12 + 6, without the unused vertex


def test_option_errors_speak_each_front_ends_language():
    cube = sk.read_mesh(str(MESHES / "cube.obj"))
    # The pipeline refuses the start level; Python names its keyword, not the CLI's option.
    with pytest.raises(sk.Error, match="start_level[ =]200: give 0 to 100") as python_error:
        sk.refine(cube, "catmull-clark", 1, start_level=200)
    assert "--" not in str(python_error.value)
    # Evaluator, stencils and limit_positions take the same range (a start level near 2^31
    # overflowed the step count of sqrt3's alternating boundary rule).
    octahedron = sk.read_mesh(str(MESHES / "octahedron.obj"))
    for call in (lambda: sk.Evaluator(octahedron, "sqrt3", 2, start_level=2**31 - 1),
                 lambda: sk.stencils(octahedron, "sqrt3", 2, start_level=101),
                 lambda: sk.limit_positions(octahedron, "loop", start_level=2**31 - 1)):
        with pytest.raises(sk.Error, match=r"^start_level=\d+: give 0 to 100$"):
            call()
    assert sk.Evaluator(octahedron, "sqrt3", 2, start_level=100).n_faces == 72
    # A level-count mismatch of a sequence: the CLI names its options.
    message = cli_error("refine", MESHES / "cube.obj", "-s", "catmull-clark:1,loop:1", "-l", 3, "-o", "x.obj")
    assert "--scheme 'catmull-clark:1,loop:1' runs 2 level(s), but --levels asks for 3" in message


@pytest.mark.parametrize("scheme,levels", [("chaikin", 3), ("four-point", 2), ("cubic-bspline", 2)])
def test_cli_and_python_refine_polylines_with_their_arrays_alike(tmp_path, scheme, levels):
    """Polylines go through one curve pipeline (framework/pipeline/curve_pipeline.h): the same
    points, polylines and point arrays — rational weights included — from both front-ends."""
    source = sk.read_mesh(str(MESHES.parent / "curves" / "open-zigzag.obj"))
    p = source.points
    lines = sk.Mesh(p, lines=source.line_indices, line_offsets=source.line_offsets,
                    point_data={"field": np.column_stack([p[:, 0] * p[:, 1], np.cos(p[:, 0])]),
                                "weight": 1.0 + 0.5 * np.abs(np.sin(np.arange(source.n_points)))})
    path = tmp_path / "in.vtp"
    sk.write_mesh(str(path), lines)
    out = tmp_path / "out.vtp"
    run_cli("refine", path, "-s", scheme, "-l", levels, "-o", out, "-q")
    cli = sk.read_mesh(str(out))
    python = sk.refine(lines, scheme, levels)

    assert python.n_lines == cli.n_lines == 1
    assert [list(line) for line in python.line_list()] == [list(line) for line in cli.line_list()]
    assert np.abs(python.points - cli.points).max() <= 1e-14
    for name in ("field", "weight"):
        assert np.abs(np.asarray(python.point_data[name]).reshape(cli.point_data[name].shape)
                      - cli.point_data[name]).max() <= 1e-14, name
    # The weights are not all 1: the curve is the rational one, not the plain refinement.
    plain = sk.refine(sk.Mesh(p, lines=source.line_indices, line_offsets=source.line_offsets), scheme, levels)
    assert np.abs(plain.points - python.points).max() > 1e-4
