#!/usr/bin/env python3
"""Flat-shaded PNG pictures of OBJ meshes with a z-buffer, standard library only
(docs/interpolation.md's figure; no ParaView or VTK needed to rebuild it).

usage: render_png.py OUT.png PANEL [PANEL ...]
PANEL: surface=S.obj[,control=C.obj][,points=P.obj:ids][,fixed=P.obj:ids]
  surface  the refined mesh, Lambert-shaded
  control  a control mesh drawn as a dark wireframe over the surface
  points   red dots at vertices of P.obj (ids 0-based, '+'-separated, or 'all')
  fixed    blue dots likewise
Panels sit side by side, all in the same orthographic view (azimuth 35, elevation 30).
"""
import math
import struct
import sys
import zlib

SIZE, SCALE, SS = 320, 50.0, 2  # panel size in pixels, pixels per unit, supersampling
AZ, EL = math.radians(35), math.radians(30)
LIGHT = (0.35, -0.45, 0.82)


def read_obj(path):
    verts, faces = [], []
    with open(path) as f:
        for line in f:
            w = line.split()
            if w and w[0] == "v":
                verts.append(tuple(float(x) for x in w[1:4]))
            elif w and w[0] == "f":
                faces.append([int(x.split("/")[0]) - 1 for x in w[1:]])
    return verts, faces


def view(p):
    x, y, z = p
    xr = x * math.cos(AZ) - y * math.sin(AZ)
    yr = x * math.sin(AZ) + y * math.cos(AZ)
    sy = z * math.cos(EL) - yr * math.sin(EL)
    depth = z * math.sin(EL) + yr * math.cos(EL)  # larger is nearer the viewer
    n = SIZE * SS
    return n / 2 + SCALE * SS * xr, n / 2 - SCALE * SS * sy, -depth


class Canvas:
    def __init__(self):
        self.n = SIZE * SS
        self.rgb = [[(255, 255, 255)] * self.n for _ in range(self.n)]
        self.z = [[-1e30] * self.n for _ in range(self.n)]

    def triangle(self, a, b, c, colour):
        xs, ys = (a[0], b[0], c[0]), (a[1], b[1], c[1])
        x0, x1 = max(0, int(min(xs))), min(self.n - 1, int(max(xs)) + 1)
        y0, y1 = max(0, int(min(ys))), min(self.n - 1, int(max(ys)) + 1)
        area = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
        if abs(area) < 1e-12:
            return
        for y in range(y0, y1 + 1):
            py = y + 0.5
            row, zrow = self.rgb[y], self.z[y]
            for x in range(x0, x1 + 1):
                px = x + 0.5
                w0 = ((b[0] - px) * (c[1] - py) - (b[1] - py) * (c[0] - px)) / area
                w1 = ((c[0] - px) * (a[1] - py) - (c[1] - py) * (a[0] - px)) / area
                w2 = 1 - w0 - w1
                if w0 < 0 or w1 < 0 or w2 < 0:
                    continue
                depth = -(w0 * a[2] + w1 * b[2] + w2 * c[2])
                if depth > zrow[x]:
                    zrow[x], row[x] = depth, colour

    def line(self, a, b, colour, bias=0.08):
        steps = int(max(abs(b[0] - a[0]), abs(b[1] - a[1]))) + 1
        for i in range(steps + 1):
            t = i / steps
            x, y = int(a[0] + t * (b[0] - a[0])), int(a[1] + t * (b[1] - a[1]))
            d = -(a[2] + t * (b[2] - a[2]))
            for dx in range(SS):
                if 0 <= x + dx < self.n and 0 <= y < self.n and d + bias * 3 >= self.z[y][x + dx] - 1.5:
                    self.rgb[y][x + dx] = colour

    def dot(self, p, colour, r):
        for y in range(int(p[1] - r) - 1, int(p[1] + r) + 2):
            for x in range(int(p[0] - r) - 1, int(p[0] + r) + 2):
                if 0 <= x < self.n and 0 <= y < self.n:
                    d2 = (x + 0.5 - p[0]) ** 2 + (y + 0.5 - p[1]) ** 2
                    if d2 <= r * r:
                        self.rgb[y][x] = colour if d2 <= (r - SS) ** 2 else (255, 255, 255)

    def downsampled(self):
        out = []
        for y in range(SIZE):
            row = []
            for x in range(SIZE):
                acc = [0, 0, 0]
                for sy in range(SS):
                    for sx in range(SS):
                        p = self.rgb[y * SS + sy][x * SS + sx]
                        acc[0] += p[0]
                        acc[1] += p[1]
                        acc[2] += p[2]
                row.append(tuple(int(v / (SS * SS)) for v in acc))
            out.append(row)
        return out


def draw(spec):
    cv = Canvas()
    verts, faces = read_obj(spec["surface"])
    ln = math.sqrt(sum(c * c for c in LIGHT))
    light = [c / ln for c in LIGHT]
    screen = [view(p) for p in verts]
    for f in faces:
        p = [verts[i] for i in f]
        u = [p[1][k] - p[0][k] for k in range(3)]
        v = [p[2][k] - p[0][k] for k in range(3)]
        n = (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])
        nl = math.sqrt(sum(c * c for c in n)) or 1.0
        shade = max(0.0, sum(n[k] / nl * light[k] for k in range(3)))
        g = 60 + 180 * shade
        colour = (int(g * 0.86), int(g * 0.9), int(g))
        for k in range(1, len(f) - 1):
            cv.triangle(screen[f[0]], screen[f[k]], screen[f[k + 1]], colour)
    if "control" in spec:
        cverts, cfaces = read_obj(spec["control"])
        cs = [view(p) for p in cverts]
        edges = {(min(f[k], f[(k + 1) % len(f)]), max(f[k], f[(k + 1) % len(f)])) for f in cfaces for k in range(len(f))}
        for a, b in sorted(edges):
            cv.line(cs[a], cs[b], (70, 70, 80), bias=10)
    for key, colour in (("fixed", (40, 90, 210)), ("points", (215, 30, 30))):
        if key in spec:
            path, ids = spec[key].rsplit(":", 1)
            pv, _ = read_obj(path)
            for i in (range(len(pv)) if ids == "all" else [int(i) for i in ids.split("+")]):
                cv.dot(view(pv[i]), colour, 3.4 * SS)
    return cv.downsampled()


def write_png(path, rows):
    h, w = len(rows), len(rows[0])
    raw = b"".join(b"\x00" + bytes(c for px in row for c in px) for row in rows)
    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)
    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 2, 0, 0, 0)) +
                chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    panels = [draw(dict(part.split("=", 1) for part in arg.split(","))) for arg in sys.argv[2:]]
    rows = [sum((p[y] for p in panels), []) for y in range(SIZE)]
    used = [y for y, row in enumerate(rows) if any(px != (255, 255, 255) for px in row)]
    top, bottom = max(0, used[0] - 8), min(SIZE, used[-1] + 9)
    write_png(sys.argv[1], rows[top:bottom])


if __name__ == "__main__":
    main()
