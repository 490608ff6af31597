"""pvbatch, with the build's subdivkit module: the three front-ends of one pipeline
(framework/pipeline) on the same inputs. For each input .vtp — a mesh with a hole and the
boundary modes, creases with Chaikin's decay, a non-manifold edge, texture coordinates, a
triangle mesh for Loop and sqrt3, a quad cube for Doo-Sabin — each carrying a float point
array, an integer point label and a cell array:
 - the command line: `subdiv refine IN.vtp --arrays all -o CLI.vtp`;
 - Python: subdivkit.refine(read_mesh(IN.vtp), arrays="all"), written with write_mesh;
 - ParaView: the "SubdivKit Refine" filter on ParaView's reader of IN.vtp;
give the same level: points, faces, crease edges, the user's arrays and SubdivKit's level
description (origin, valence, level, vertex_class, parent_face, base_face, sharpness,
cell_kind, corner_sharpness)."""

import os

import numpy as np
from paraview.simple import OpenDataFile

import pv_support as pv
import subdivkit as sk

pv.load_plugin(globals())
MESHES = os.path.join(pv.SOURCE_DIR, "examples", "meshes")
BOUNDARY = {"edges-and-corners": 0, "edges": 1, "none": 2}  # the filter's enumeration
CREASE_METHOD = {"uniform": 0, "chaikin": 1}

CASES = [  # mesh, scheme, levels, boundary, crease method
    ("plane-with-hole.obj", "catmull-clark", 2, "edges", "uniform"),
    ("textured-tube.obj", "catmull-clark", 2, "none", "uniform"),  # faces at the boundary become holes
    ("cube-creased.obj", "catmull-clark", 2, "edges-and-corners", "chaikin"),
    ("flap-fan.obj", "catmull-clark", 2, "edges-and-corners", "uniform"),  # a non-manifold edge
    ("textured-tube.obj", "catmull-clark", 2, "edges-and-corners", "uniform"),  # UVs, split at seams in a .vtp
    ("octahedron.obj", "loop", 2, "edges-and-corners", "uniform"),
    ("octahedron.obj", "sqrt3", 3, "edges-and-corners", "uniform"),
    ("cube.obj", "doo-sabin", 2, "edges-and-corners", "uniform"),
]


def input_vtp(mesh_name):
    """The example mesh as a .vtp with a float point array (2 columns, a smooth function of
    position), an integer point label and a float cell array: what all three front-ends read."""
    mesh = sk.read_mesh(os.path.join(MESHES, mesh_name))
    p = mesh.points
    point_data = dict(mesh.point_data)
    point_data.update({"field": np.column_stack([p[:, 0] * p[:, 1] + p[:, 2], np.sin(p[:, 0])]),
                       "label": np.arange(mesh.n_points, dtype=np.int32) % 3})
    cell_data = dict(mesh.cell_data)
    cell_data["face_id"] = np.arange(mesh.n_faces, dtype=float)
    path = os.path.join(pv.WORK, mesh_name.replace(".obj", ".vtp"))
    sk.write_mesh(path, sk.Mesh(mesh.points, face_offsets=mesh.face_offsets, faces=mesh.face_indices,
                                creases=mesh.creases, crease_sharpness=mesh.crease_sharpness, corners=mesh.corners,
                                corner_sharpness=mesh.corner_sharpness, face_varying=mesh.face_varying,
                                point_data=point_data, cell_data=cell_data, point_roles=mesh.point_roles))
    return path


for mesh_name, scheme, levels, boundary, crease_method in CASES:
    what = f"{mesh_name} {scheme} level {levels} --boundary {boundary} --crease-method {crease_method}"
    source = input_vtp(mesh_name)
    name = f"{mesh_name}-{scheme}-{levels}-{boundary}"

    cli = pv.cli_refine(source, name + "-cli", "-s", scheme, "-l", levels, "--boundary", boundary,
                        "--crease-method", crease_method)

    python_path = os.path.join(pv.WORK, name + "-python.vtp")
    refined = sk.refine(sk.read_mesh(source), scheme, levels, boundary=boundary, crease_method=crease_method,
                        arrays="all")
    sk.write_mesh(python_path, refined)
    python = pv.read_vtp(python_path)

    refine = SubdivKitRefine(Input=OpenDataFile(source), Scheme=scheme, Levels=levels,  # noqa: F821
                             BoundaryInterpolation=BOUNDARY[boundary], CreaseMethod=CREASE_METHOD[crease_method])
    refine.UpdatePipeline()
    filtered = pv.fetch(refine)

    assert cli.GetNumberOfPolys() > 0, what
    assert {"field", "label", "origin", "vertex_class"} <= set(pv.arrays(cli.GetPointData())), what
    assert {"face_id", "base_face"} <= set(pv.arrays(cli.GetCellData())), what
    pv.assert_same_polydata(python, cli, ("python", what))
    pv.assert_same_polydata(filtered, cli, ("paraview", what))
    print(f"{what}: {cli.GetNumberOfPoints()} points, {cli.GetNumberOfPolys()} faces, "
          f"{cli.GetNumberOfCells() - cli.GetNumberOfPolys()} crease edges, the same from all three front-ends")
