"""The figures of docs/rational.md and docs/parameterize.md (standard-library Python; the
`subdiv` tool and the software renderer tools/render do the work, no display needed):

    python3 docs/rational/figures.py build docs/images

rational-circle.png     four weighted quadratic B-spline arcs (examples/rational/circle-arcs.obj,
                        red) refined 5 times by chaikin-uniform.json (blue): the unit circle;
rational-sphere.png     the sphere octant's weighted net (examples/rational/sphere-octant.obj)
                        refined 4 times by Doo-Sabin; its middle span, mirrored into the eight
                        octants, with the middle 3 x 3 control points of one octant (red);
parameterize-checker.png  a bumpy disc given UVs by `subdiv parameterize --weights mean-value`,
                        refined 3 times by Catmull-Clark carrying them, as an 8 x 8 checkerboard.
"""
import math
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]


def run(*args):
    subprocess.run([str(a) for a in args], check=True, stdout=subprocess.DEVNULL)


def read_obj(path):
    verts, faces, lines = [], [], []
    for line in open(path):
        t = line.split()
        if not t:
            continue
        if t[0] == "v":
            verts.append([float(x) for x in t[1:]])
        elif t[0] == "f":
            faces.append([int(x.split("/")[0]) - 1 for x in t[1:]])
        elif t[0] == "l":
            lines.append([int(x) - 1 for x in t[1:]])
    return verts, faces, lines


def write_obj(path, verts, faces=(), lines=()):
    with open(path, "w") as f:
        for v in verts:
            f.write("v " + " ".join(repr(x) for x in v[:3]) + "\n")
        for face in faces:
            f.write("f " + " ".join(str(i + 1) for i in face) + "\n")
        for line in lines:
            f.write("l " + " ".join(str(i + 1) for i in line) + "\n")


def circle(subdiv, render, out, tmp):
    refined = tmp / "circle5.obj"
    run(subdiv, "refine", ROOT / "examples/rational/circle-arcs.obj", "-s",
        ROOT / "examples/rational/chaikin-uniform.json", "-l", 5, "-o", refined)
    # The control polygons without their weights (the renderer draws x y z).
    verts, _, lines = read_obj(ROOT / "examples/rational/circle-arcs.obj")
    write_obj(tmp / "arcs.obj", verts, lines=lines)
    run(render, refined, out / "rational-circle.png", "--cage", tmp / "arcs.obj", "--azimuth", 0, "--elevation", 0,
        "--size", 420)


def sphere(subdiv, render, out, tmp):
    net = ROOT / "examples/rational/sphere-octant.obj"
    run(subdiv, "refine", net, "-s", "doo-sabin", "-l", 4, "-o", tmp / "octant4.obj")
    # The same faces on the parameter plane (linear precision): where each face sits.
    verts, faces, _ = read_obj(net)
    write_obj(tmp / "plane.obj", [[i, j, 0.0] for i in range(5) for j in range(5)], faces)
    run(subdiv, "refine", tmp / "plane.obj", "-s", "doo-sabin", "-l", 4, "-o", tmp / "plane4.obj")
    points, faces, _ = read_obj(tmp / "octant4.obj")
    uv, _, _ = read_obj(tmp / "plane4.obj")
    span = [f for f in faces if all(1.5 - 1e-9 <= sum(uv[v][k] for v in f) / len(f) <= 2.5 + 1e-9 for k in (0, 1))]
    used = sorted({v for f in span for v in f})
    index = {v: i for i, v in enumerate(used)}
    octant = [points[v][:3] for v in used]
    verts, faces_all = [], []
    for sx in (1, -1):
        for sy in (1, -1):
            for sz in (1, -1):
                base = len(verts)
                verts += [[sx * p[0], sy * p[1], sz * p[2]] for p in octant]
                flip = sx * sy * sz < 0  # a mirror image turns the faces over
                for f in span:
                    g = [base + index[v] for v in f]
                    faces_all.append(g[::-1] if flip else g)
    write_obj(tmp / "sphere.obj", verts, faces_all)
    net_verts, net_faces, _ = read_obj(net)
    middle = [net_verts[5 * i + j][:3] for i in range(1, 4) for j in range(1, 4)]
    cage_faces = [[3 * i + j, 3 * i + j + 1, 3 * (i + 1) + j + 1, 3 * (i + 1) + j] for i in range(2) for j in range(2)]
    write_obj(tmp / "middle-net.obj", middle, cage_faces)
    run(render, tmp / "sphere.obj", out / "rational-sphere.png", "--cage", tmp / "middle-net.obj", "--azimuth", 35,
        "--elevation", 25, "--size", 480)


def checker(subdiv, render, out, tmp):
    n = 10
    verts, faces = [], []
    for j in range(n + 1):
        for i in range(n + 1):
            x, y = i / n - 0.5, j / n - 0.5
            r2 = x * x + y * y
            verts.append([x * (1 + 0.3 * y), y, 0.6 * math.exp(-6 * r2) + 0.15 * math.sin(4 * x)])
    for j in range(n):
        for i in range(n):
            a = j * (n + 1) + i
            faces.append([a, a + 1, a + n + 2, a + n + 1])
    write_obj(tmp / "bump.obj", verts, faces)
    run(subdiv, "parameterize", tmp / "bump.obj", "--weights", "mean-value", "-o", tmp / "bump-uv.obj")
    run(subdiv, "refine", tmp / "bump-uv.obj", "-s", "catmull-clark", "-l", 3, "-o", tmp / "bump3.obj")
    run(render, tmp / "bump3.obj", out / "parameterize-checker.png", "--checker", 8, "--azimuth", 25,
        "--elevation", 40, "--size", 480)


if __name__ == "__main__":
    build = Path(sys.argv[1] if len(sys.argv) > 1 else ROOT / "build")
    out = Path(sys.argv[2] if len(sys.argv) > 2 else ROOT / "docs/images")
    subdiv, render = build / "tools/subdiv/subdiv", build / "tools/render/subdiv-render"
    with tempfile.TemporaryDirectory() as d:
        circle(subdiv, render, out, Path(d))
        sphere(subdiv, render, out, Path(d))
        checker(subdiv, render, out, Path(d))
