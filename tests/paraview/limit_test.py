"""pvbatch: "SubdivKit Limit" agrees with `subdiv evaluate` on the same input: the sampled
limit surface (--samples N) of a quad cube with Catmull-Clark and of a triangulated sphere
with Loop, and the adaptive mesh with its points on the limit (--adaptive L --limit); the
sampled cube is closed (every edge in two faces) with unit normals; an odd Samples on
triangles under Catmull-Clark gives SubdivKit's message, naming the property, and an
empty output."""

import math

from paraview.simple import Box, Clean, Sphere

import pv_support as pv

pv.load_plugin(globals())

cube = Clean(Input=Box())
sphere = Sphere(ThetaResolution=12, PhiResolution=8)
inputs = {"cube": (cube, pv.write_input(cube, "cube.vtp")), "sphere": (sphere, pv.write_input(sphere, "sphere.vtp"))}


def cli_evaluate(path, name, *options):
    out = f"{pv.WORK}/{name}.vtp"
    pv.cli("evaluate", path, "-o", out, *options)
    return pv.read_vtp(out)


cases = [("cube", "catmull-clark", {"Mode": 0, "Samples": 4}, ["--samples", 4]),
         ("sphere", "loop", {"Mode": 0, "Samples": 3}, ["--samples", 3]),
         ("cube", "catmull-clark", {"Mode": 1, "AdaptiveLevels": 3, "LimitPositions": 1}, ["--adaptive", 3, "--limit"]),
         ("cube", "catmull-clark", {"Mode": 1, "AdaptiveLevels": 3, "LimitPositions": 1, "Transitions": 1},
          ["--adaptive", 3, "--limit", "--transitions", "triangles"])]
for name, scheme, properties, options in cases:
    source, path = inputs[name]
    limit = SubdivKitLimit(Input=source, Scheme=scheme, **properties)  # noqa: F821
    limit.UpdatePipeline()
    got = pv.fetch(limit)
    want = cli_evaluate(path, f"{name}-{scheme}-{properties['Mode']}", "-s", scheme, *options)
    assert got.GetNumberOfPolys() > 0, (name, scheme)
    pv.assert_same_polydata(got, want, (name, scheme, properties))
    print(f"{name} {scheme} {' '.join(map(str, options))}: {got.GetNumberOfPoints()} points, "
          f"{got.GetNumberOfPolys()} faces, as subdiv evaluate")

# The sampled cube: closed (each edge in exactly two faces) and its normals of unit length.
limit = SubdivKitLimit(Input=cube, Scheme="catmull-clark", Samples=4)  # noqa: F821
limit.UpdatePipeline()
got = pv.fetch(limit)
edges = {}
polys = got.GetPolys()
offsets, connectivity = polys.GetOffsetsArray(), polys.GetConnectivityArray()
for f in range(polys.GetNumberOfCells()):
    ids = [connectivity.GetValue(k) for k in range(offsets.GetValue(f), offsets.GetValue(f + 1))]
    for a, b in zip(ids, ids[1:] + ids[:1]):
        edges[frozenset((a, b))] = edges.get(frozenset((a, b)), 0) + 1
assert got.GetNumberOfPolys() == 6 * 16 and set(edges.values()) == {2}, (got.GetNumberOfPolys(), set(edges.values()))
normals = got.GetPointData().GetNormals()
assert normals is not None and normals.GetNumberOfTuples() == got.GetNumberOfPoints()
assert all(abs(math.sqrt(sum(normals.GetComponent(i, c) ** 2 for c in range(3))) - 1) < 1e-12
           for i in range(got.GetNumberOfPoints()))
print("the sampled cube is closed, its normals of unit length")

# An odd Samples on triangles under a quad scheme (their sub-faces take Samples/2 segments):
# SubdivKit's message naming the property, and an empty output.
with pv.CapturedMessages() as messages:
    refused = SubdivKitLimit(Input=sphere, Scheme="catmull-clark", Samples=3)  # noqa: F821
    refused.UpdatePipeline()
assert pv.fetch(refused).GetNumberOfPoints() == 0
assert "Samples 3: face 0 has 3 corners" in messages.text and "use an even N" in messages.text, messages.text
print("Samples 3 on triangles with catmull-clark: refused with SubdivKit's message")
