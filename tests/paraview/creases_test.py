"""pvbatch: creases of "SubdivKit Refine" from a cell array and from the feature angle
agree with `subdiv refine --features FILE.json` and `--feature-angle` on the same cube:
 - a cell array on line cells: each segment's value is its sharpness (semi-sharp 2.5 and
   infinitely sharp 10);
 - a cell array on faces (a part id): edges between different parts are infinitely sharp;
 - UseFeatureAngle: edges whose faces meet at more than the angle are infinitely sharp."""

import os
import sys

import pv_support as pv

sys.path.insert(0, os.path.join(pv.SOURCE_DIR, "plugins", "paraview", "examples"))
from cube_with_lines import FACES, cube_with_lines  # noqa: E402 (the examples' cube)

pv.load_plugin(globals())

LINES = [((4, 5, 6), 2.5), ((0, 1), 10.0)]  # a semi-sharp polyline over the top, an infinitely sharp edge
# Cell arrays "crease" (the lines' sharpness, 0 on faces) and "part" (1 on the top face, 0 elsewhere).
cube = cube_with_lines([ids for ids, _ in LINES],
                       {"crease": [s for _, s in LINES] + [0.0] * len(FACES),
                        "part": [0.0] * len(LINES) + [1.0 if f == 1 else 0.0 for f in range(len(FACES))]})
cube.UpdatePipeline()
path = pv.write_input(cube, "creased-cube.vtp")

line_creases = {"creases": [{"edge": [a, b], "sharpness": s} for ids, s in LINES for a, b in zip(ids, ids[1:])]}
top_edges = list(zip(FACES[1], FACES[1][1:] + FACES[1][:1]))
part_creases = {"creases": [{"edge": list(e), "sharpness": "infinite"} for e in top_edges]}
cases = [("crease array on lines", {"CreaseArray": "crease"}, ["--features", pv.json_file("lines.json", line_creases)]),
         ("part array on faces", {"CreaseArray": "part"}, ["--features", pv.json_file("parts.json", part_creases)]),
         ("feature angle 40", {"UseFeatureAngle": 1, "FeatureAngle": 40}, ["--feature-angle", 40])]
for what, properties, options in cases:
    refine = SubdivKitRefine(Input=cube, Scheme="catmull-clark", Levels=3, **properties)  # noqa: F821
    refine.UpdatePipeline()
    got = pv.fetch(refine)
    want = pv.cli_refine(path, what.replace(" ", "-"), "-s", "catmull-clark", "-l", 3, *options)
    pv.assert_same_polydata(got, want, what)
    creased = got.GetNumberOfCells() - got.GetNumberOfPolys()  # crease edges are line cells
    assert creased > 0, what
    print(f"{what}: as subdiv refine {' '.join(map(str, options[:1]))} ({creased} crease edges at level 3)")

# Without a crease array the same cube is smooth: the arrays made the difference.
plain = SubdivKitRefine(Input=cube, Scheme="catmull-clark", Levels=3)  # noqa: F821
plain.UpdatePipeline()
assert pv.fetch(plain).GetNumberOfCells() == pv.fetch(plain).GetNumberOfPolys()
print("creases_test: ok")
