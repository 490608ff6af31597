"""pvbatch: "SubdivKit Refine" on ParaView's own sources (a cube and a sphere with an
Elevation array) agrees with `subdiv refine` on the same input, written to a file: counts,
positions, the input's point and cell arrays and SubdivKit's (origin, valence, level,
vertex_class, parent_face, base_face), for two schemes (and a scheme file), two levels;
LimitPositions acts as --limit; the typed parameter widgets and the Parameters field act
as --param; changing Levels
2 -> 3 re-executes; AllLevels gives every level as a multiblock, LevelSpacing side by side."""

import os

from paraview.simple import Box, Clean, Elevation, GenerateIds, PythonCalculator, Sphere, TextureMaptoPlane

import pv_support as pv

pv.load_plugin(globals())

# Inputs: a closed quad cube (Box keeps a copy of each corner per face; Clean merges them) and
# a triangulated sphere, both with ParaView's Elevation point array; the cube also with a cell
# array (GenerateIds' cell ids), which must follow the faces.
cube = Elevation(Input=GenerateIds(Input=Clean(Input=Box())), LowPoint=[-0.5, -0.5, -0.5], HighPoint=[0.5, 0.5, 0.5])
sphere = Elevation(Input=Sphere(ThetaResolution=12, PhiResolution=8), LowPoint=[0, 0, -0.5], HighPoint=[0, 0, 0.5])
inputs = {"cube": (cube, pv.write_input(cube, "cube.vtp")), "sphere": (sphere, pv.write_input(sphere, "sphere.vtp"))}
butterfly_file = os.path.join(pv.SOURCE_DIR, "schemes", "butterfly.json")

cases = [("cube", "catmull-clark", "", 1), ("cube", "catmull-clark", "", 2),
         ("sphere", "loop", "", 1), ("sphere", "loop", "", 2),
         ("sphere", "", butterfly_file, 2)]  # a scheme given as a .json file
for name, scheme, scheme_file, levels in cases:
    source, path = inputs[name]
    refine = SubdivKitRefine(Input=source, Scheme=scheme or "catmull-clark", SchemeFile=scheme_file,  # noqa: F821
                             Levels=levels)
    refine.UpdatePipeline()
    got = pv.fetch(refine)
    want = pv.cli_refine(path, f"{name}-{scheme}-{levels}", "-s", scheme_file or scheme, "-l", levels)
    pv.assert_same_polydata(got, want, (name, scheme or scheme_file, levels))
    names = pv.arrays(got.GetPointData())
    assert {"Elevation", "origin", "valence", "level", "vertex_class"} <= set(names), sorted(names)
    assert got.GetPointData().GetArray("level").GetRange() == (levels, levels)
    print(f"{name} {scheme or os.path.basename(scheme_file)} level {levels}: {got.GetNumberOfPoints()} points, "
          f"{got.GetNumberOfPolys()} faces, as subdiv refine")

# Integer arrays are labels (taken from the parent, never averaged) and the active texture
# coordinates stay active, so ParaView's Texture property works on the refined mesh.
labelled = PythonCalculator(Input=TextureMaptoPlane(Input=sphere), Expression="(inputs[0].Points[:, 2] > 0) + 3",
                            ArrayName="label")
refine = SubdivKitRefine(Input=labelled, Scheme="loop", Levels=1)  # noqa: F821
refine.UpdatePipeline()
got = pv.fetch(refine)
label = got.GetPointData().GetArray("label")
assert label.GetDataTypeAsString() == "int", label.GetDataTypeAsString()
assert {label.GetValue(i) for i in range(got.GetNumberOfPoints())} == {3, 4}
assert got.GetPointData().GetTCoords() is not None
print("integer point arrays stay labels, texture coordinates stay active")

# Limit positions: the finest level on the limit surface, with the limit normals, as --limit.
for name, scheme in (("cube", "catmull-clark"), ("sphere", "loop")):
    refine = SubdivKitRefine(Input=inputs[name][0], Scheme=scheme, Levels=2, LimitPositions=1)  # noqa: F821
    refine.UpdatePipeline()
    got = pv.fetch(refine)
    want = pv.cli_refine(inputs[name][1], f"{name}-{scheme}-limit", "-s", scheme, "-l", 2, "--limit")
    pv.assert_same_polydata(got, want, (name, scheme, "limit"))
    assert got.GetPointData().GetNormals() is not None and got.GetPointData().GetNormals().GetName() == "normal"
    print(f"{name} {scheme} LimitPositions: as subdiv refine --limit (points, arrays, limit normals)")

# The typed widgets of the schemes' parameters (the panel shows the chosen scheme's) act as
# --param; the Parameters text field wins over them.
typed = [("butterfly", "butterfly_w", 0.1, "", ["-p", "w=0.1"]),
         ("loop", "loop_beta", "warren", "", ["-p", "beta=warren"]),
         ("butterfly", "butterfly_w", 0.1, "w=0.05", ["-p", "w=0.05"])]
for scheme, widget, value, text, options in typed:
    refine = SubdivKitRefine(Input=sphere, Scheme=scheme, Levels=1, Parameters=text)  # noqa: F821
    refine.SetPropertyWithName(widget, value)
    refine.UpdatePipeline()
    want = pv.cli_refine(inputs["sphere"][1], f"typed-{widget}-{text}", "-s", scheme, "-l", 1, *options)
    pv.assert_same_polydata(pv.fetch(refine), want, (widget, value, text))
    print(f"{scheme}: widget {widget}={value}{' and Parameters ' + repr(text) if text else ''}: as subdiv refine "
          f"{' '.join(options)}")

# Levels 2 -> 3 on the same proxy: the filter runs again and gives level 3's counts.
refine = SubdivKitRefine(Input=cube, Scheme="catmull-clark", Levels=2)  # noqa: F821
refine.UpdatePipeline()
before = refine.GetDataInformation().GetNumberOfCells()
refine.Levels = 3
refine.UpdatePipeline()
got = pv.fetch(refine)
want = pv.cli_refine(inputs["cube"][1], "cube-cc-3", "-s", "catmull-clark", "-l", 3)
pv.assert_same_polydata(got, want, "levels 2 -> 3")
assert got.GetNumberOfPolys() == 4 * before, (before, got.GetNumberOfPolys())
print(f"Levels 2 -> 3: re-executed, {before} -> {got.GetNumberOfPolys()} faces")

# Every level as a multiblock: block k is `subdiv refine -o X.pvd`'s level_k.vtp.
refine.AllLevels = 1
refine.UpdatePipeline()
blocks = pv.fetch(refine)
assert blocks.IsA("vtkMultiBlockDataSet") and blocks.GetNumberOfBlocks() == 4, blocks.GetClassName()
pvd = os.path.join(pv.WORK, "cube-levels.pvd")
pv.cli("refine", inputs["cube"][1], "-q", "-s", "catmull-clark", "-l", 3, "--arrays", "all", "-o", pvd)
for k in range(4):
    pv.assert_same_polydata(blocks.GetBlock(k), pv.read_vtp(os.path.join(pv.WORK, "cube-levels_levels", f"level_{k}.vtp")),
                            f"multiblock level {k}")
print("AllLevels: 4 blocks, each as subdiv refine's .pvd level")

# LevelSpacing puts the levels side by side: level k moves k x spacing x the input's diagonal along x.
refine.LevelSpacing = 1.5
refine.UpdatePipeline()
spread = pv.fetch(refine)
diagonal = pv.fetch(cube).GetLength()
for k in range(4):
    level, there = blocks.GetBlock(k), spread.GetBlock(k)
    moved = [there.GetPoint(i)[0] - level.GetPoint(i)[0] for i in range(level.GetNumberOfPoints())]
    assert max(abs(m - 1.5 * k * diagonal) for m in moved) < 1e-12, (k, moved[:3])
print("LevelSpacing 1.5: level k moved by 1.5 k diagonals along x")
print("refine_test: ok")
