"""Holes: with boundary="none" OpenSubdiv makes every face around a boundary vertex a hole;
the refined mesh leaves hole faces out, and their cell values with them."""
import numpy as np

import subdivkit as sk


def grid(n):
    points = [[i, j, 0.1 * i * j] for j in range(n + 1) for i in range(n + 1)]
    faces = [[j * (n + 1) + i, j * (n + 1) + i + 1, (j + 1) * (n + 1) + i + 1, (j + 1) * (n + 1) + i]
             for j in range(n) for i in range(n)]
    return points, faces


def test_boundary_none_leaves_out_the_faces_around_the_boundary_and_their_cell_values():
    points, faces = grid(4)
    mesh = sk.Mesh(points, faces, cell_data={"id": np.arange(16, dtype=float)})
    fine = sk.refine(mesh, "catmull-clark", 1, boundary="none")
    # Only the 4 inner quads touch no boundary vertex; each has 4 children.
    assert len(fine.face_offsets) - 1 == 16
    assert len(fine.cell_data["id"]) == 16
    inner = {5, 6, 9, 10}
    assert set(np.unique(fine.cell_data["id"]).astype(int)) == inner
    everything = sk.refine(mesh, "catmull-clark", 1, boundary="edges")
    assert len(everything.face_offsets) - 1 == 64
