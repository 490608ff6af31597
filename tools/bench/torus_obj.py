# A closed quad torus of NU x NV faces as OBJ, for docs/scale.md's measurements:
#   python3 tools/bench/torus_obj.py 1000 1000 torus1m.obj
import math, sys
nu, nv = int(sys.argv[1]), int(sys.argv[2])
R, r = 3.0, 1.0
with open(sys.argv[3], "w") as out:
    for j in range(nv):
        for i in range(nu):
            u, v = 2 * math.pi * i / nu, 2 * math.pi * j / nv
            out.write(f"v {(R + r * math.cos(v)) * math.cos(u):.9f} {(R + r * math.cos(v)) * math.sin(u):.9f} {r * math.sin(v):.9f}\n")
    for j in range(nv):
        for i in range(nu):
            a = j * nu + i + 1
            b = j * nu + (i + 1) % nu + 1
            c = ((j + 1) % nv) * nu + (i + 1) % nu + 1
            d = ((j + 1) % nv) * nu + i + 1
            out.write(f"f {a} {b} {c} {d}\n")
