"""Writes the weighted control nets of docs/rational.md (standard-library Python):

  circle-arcs.obj    four open polylines of three points, each a quarter of the unit circle
                     under chaikin-uniform.json (the uniform quadratic B-spline);
  sphere-octant.obj  a 5 x 5 net whose middle span is the unit sphere's first octant under
                     Doo-Sabin (the biquadratic B-spline on regular quads).

A span of the uniform quadratic B-spline with homogeneous control points H0, H1, H2 is the
rational quadratic Bezier with points (H0 + H1)/2, H1, (H1 + H2)/2. The quarter arc from
(1, 0) to (0, 1) is the Bezier (1, 0), (1, 1), (0, 1) with weights 1, cos 45°, 1 (Piegl &
Tiller 1997, The NURBS Book, section 7.5), so H1 = cos 45° (1, 1, 1) and H0 = 2 (1, 0, 1) - H1,
H2 = 2 (0, 1, 1) - H1. The sphere is the tensor product of that arc as meridian (x, z) and as
circle of revolution (a, b): (x a, x b, z), with the product weights.

    python3 examples/rational/weighted_nets.py examples/rational
"""
import math
import sys
from pathlib import Path

C = math.sqrt(0.5)
ARC = [(2 - C, -C, 2 - C), (C, C, C), (-C, 2 - C, 2 - C)]  # homogeneous (x w, y w, w)


def circle(path):
    lines = []
    with open(path, "w") as f:
        f.write("# four quarter arcs of the unit circle: v x y z w (refine with chaikin-uniform.json)\n")
        for k in range(4):
            a = k * math.pi / 2
            for hx, hy, w in ARC:
                x, y = hx / w, hy / w
                f.write(f"v {math.cos(a) * x - math.sin(a) * y!r} {math.sin(a) * x + math.cos(a) * y!r} 0 {w!r}\n")
            lines.append(f"l {3 * k + 1} {3 * k + 2} {3 * k + 3}\n")
        f.writelines(lines)


def sphere(path):
    arc = list(ARC)
    arc.insert(0, tuple(2 * p - q for p, q in zip(ARC[0], ARC[1])))  # margins: linear extension, keeps
    arc.append(tuple(2 * p - q for p, q in zip(ARC[2], ARC[1])))     # Doo-Sabin's boundary rules away
    with open(path, "w") as f:
        f.write("# the unit sphere's first octant as the middle span of a weighted 5 x 5 net (refine with doo-sabin)\n")
        for mx, mz, mw in arc:          # meridian (x w, z w, w)
            for ra, rb, rw in arc:      # circle of revolution (a w', b w', w')
                w = mw * rw
                f.write(f"v {mx * ra / w!r} {mx * rb / w!r} {mz * rw / w!r} {w!r}\n")
        for i in range(4):
            for j in range(4):
                a = 5 * i + j + 1
                f.write(f"f {a} {a + 1} {a + 6} {a + 5}\n")


if __name__ == "__main__":
    out = Path(sys.argv[1] if len(sys.argv) > 1 else ".")
    circle(out / "circle-arcs.obj")
    sphere(out / "sphere-octant.obj")
