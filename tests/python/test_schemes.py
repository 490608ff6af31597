"""Schemes from names, files, dicts and JSON text; parameters as keyword arguments."""
import json

import numpy as np
import pytest

import subdivkit as sk
from conftest import MESHES, SCHEMES


def test_the_shipped_catmull_clark_as_a_dict_refines_exactly_like_the_file():
    as_dict = json.loads((SCHEMES / "catmull-clark.json").read_text())
    inline = sk.Scheme.from_dict(as_dict)
    shipped = sk.Scheme.load("catmull-clark")
    assert inline.name == shipped.name == "catmull-clark"
    for mesh_name in ["cube.obj", "cube-creased.obj", "plane-with-hole.obj"]:
        mesh = sk.read_mesh(MESHES / mesh_name)
        assert np.array_equal(sk.refine(mesh, inline, 3).points, sk.refine(mesh, shipped, 3).points)
        a, b = sk.stencils(mesh, inline, 2, composed=True), sk.stencils(mesh, shipped, 2, composed=True)
        assert (a != b).nnz == 0


def test_json_text_and_dict_give_the_same_scheme():
    text = (SCHEMES / "loop.json").read_text()
    mesh = sk.read_mesh(MESHES / "octahedron.obj")
    from_text = sk.refine(mesh, sk.Scheme.from_json(text), 2).points
    from_dict = sk.refine(mesh, sk.Scheme.from_dict(json.loads(text)), 2).points
    assert np.array_equal(from_text, from_dict)
    assert np.array_equal(from_text, sk.refine(mesh, "loop", 2).points)


def test_a_changed_rule_changes_the_result():
    d = json.loads((SCHEMES / "catmull-clark.json").read_text())
    d["name"] = "stiff-catmull-clark"
    d["rules"]["vertex"] = [{"at": "self", "w": "1"}]  # old vertices stay: interpolating corners
    cube = sk.read_mesh(MESHES / "cube.obj")
    fine = sk.refine(cube, sk.Scheme.from_dict(d), 1)
    for p in cube.points:
        assert np.any(np.all(fine.points == p, axis=1)), f"{p} moved"
    assert not all(np.any(np.all(sk.refine(cube, "catmull-clark", 1).points == p, axis=1)) for p in cube.points)


def test_parameters_are_keyword_arguments():
    warren = sk.Scheme.load("loop", beta="warren")
    assert warren.parameters["beta"] == "warren"
    assert sk.Scheme.load("loop").parameters["beta"] == "loop"
    w = sk.Scheme.load("four-point", w=0.05)
    assert w.parameters["w"] == 0.05
    assert w.with_params(w=0.0625).parameters["w"] == 0.0625
    mesh = sk.read_mesh(MESHES / "octahedron.obj")
    assert not np.array_equal(sk.refine(mesh, warren, 2).points, sk.refine(mesh, "loop", 2).points)
    info = {p["name"]: p for p in sk.Scheme.load("butterfly").parameter_info}
    assert info["w"]["value"] == 0.0625


def test_schemes_lists_surface_and_curve_schemes():
    listing = {s["name"]: s for s in sk.schemes()}
    assert listing["catmull-clark"]["kind"] == "surface"
    assert listing["chaikin"]["kind"] == "curve"
    assert listing["loop"]["origin"] == "built-in"
    for s in listing.values():
        assert sk.Scheme.load(s["name"]).kind == s["kind"]


def test_scheme_properties():
    s = sk.Scheme.load("chaikin")
    assert (s.kind, s.arity) == ("curve", 2)
    assert s.path.endswith("chaikin.json")
    assert "Chaikin" in s.description
    assert "chaikin" in repr(s)
