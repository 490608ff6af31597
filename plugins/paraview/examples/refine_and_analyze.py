"""The pvpython example of docs/paraview.md (ctest runs it as paraview_example):

    PV_PLUGIN_PATH=<the folder of SubdivKit.so> pvpython plugins/paraview/examples/refine_and_analyze.py

Refines ParaView's sphere with Loop and a cube with Catmull-Clark and feature-angle creases,
compares two levels, changes a parameter, and analyses Loop's spectrum."""

import os

from paraview import servermanager as sm
from paraview.simple import *  # noqa: F403 (SubdivKitRefine and SubdivKitAnalyze come with the plugin)

if "SubdivKitRefine" not in globals():  # not loaded at start through PV_PLUGIN_PATH
    LoadPlugin(os.environ["SUBDIV_PARAVIEW_PLUGIN"], remote=False, ns=globals())  # noqa: F405

# A sphere with ParaView's Elevation array, refined three times with Loop: the array comes along.
sphere = Elevation(Input=Sphere(), LowPoint=[0, 0, -0.5], HighPoint=[0, 0, 0.5])  # noqa: F405
loop = SubdivKitRefine(Input=sphere, Scheme="loop", Levels=3)  # noqa: F405
loop.UpdatePipeline()
info = loop.GetDataInformation()
print(f"loop, 3 levels: {info.GetNumberOfPoints()} points, {info.GetNumberOfCells()} cells")

# Butterfly's tension parameter w, as `subdiv refine --param w=0`: an interpolating scheme
# keeps the input's points, whatever w.
butterfly = SubdivKitRefine(Input=sphere, Scheme="butterfly", Levels=2, Parameters="w=0")  # noqa: F405
coarse, fine = sm.Fetch(sphere), sm.Fetch(butterfly)
moved = max(abs(a - b) for i in range(coarse.GetNumberOfPoints()) for a, b in zip(coarse.GetPoint(i), fine.GetPoint(i)))
print(f"butterfly w=0: the input's points move by at most {moved:.1e}")

# A cube whose 90-degree edges are creases (feature angle), every level as a multiblock.
cube = SubdivKitRefine(Input=Clean(Input=Box()), Scheme="catmull-clark", Levels=3,  # noqa: F405
                       UseFeatureAngle=1, FeatureAngle=40, AllLevels=1)
blocks = sm.Fetch(cube)
print("catmull-clark levels:", [blocks.GetBlock(k).GetNumberOfPolys() for k in range(blocks.GetNumberOfBlocks())],
      "faces")

# Loop's spectrum at valences 3..12: port 1 is a table, one row per valence.
analyze = SubdivKitAnalyze(Scheme="loop", Valences=[3, 12])  # noqa: F405
spectrum = sm.Fetch(analyze, idx=1)
valence, lambda1 = spectrum.GetColumnByName("valence"), spectrum.GetColumnByName("lambda_1")
print("loop lambda_1:", ", ".join(f"n={valence.GetValue(r)}: {lambda1.GetValue(r):.4f}"
                                  for r in range(spectrum.GetNumberOfRows())))
