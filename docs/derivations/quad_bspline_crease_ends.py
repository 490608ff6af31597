#!/usr/bin/env python3
"""The crease-end rules of schemes/quad-bspline.json (even d), in exact fractions.

A crease M0 = c, M1, M2, ... that ends at a corner c follows, for even degree d = 2m, the
clamped uniform B-spline of degree d whose derivatives 2..m vanish at c: its control polygon
is c, Q1, ..., Q(m-1), M1, M2, ... with Qi = c + i(i+1)/(m(m+1)) (M1 - c) (docs/features.md,
"Creases in dual schemes"). One level of refinement inserts every knot interval's midpoint
(Boehm 1980, "Inserting new knots into B-spline curves") and leaves the points Q1..Q(m-1) out
again. The scheme makes it in steps: the dual split gives the case d = 2 (Chaikin's cuts, the
end segment's midpoint next to the corner), and pass i maps the refined crease of degree 2i
to that of degree 2i + 2. For every distance D from the corner this script solves for the
pass's weights on the nearest crease points (offsets from the vertex, negative towards the
corner) and prints them; rows equal to (1/4, 1/2, 1/4) need no end rule.

    python3 docs/derivations/quad_bspline_crease_ends.py 6     # needs sympy
"""
import sys
from fractions import Fraction as F

import sympy as sp


def comb(pairs):
    out = {}
    for w, v in pairs:
        for key, c in v.items():
            out[key] = out.get(key, 0) + w * c
    return {k: c for k, c in out.items() if c != 0}


def insert_knot(knots, ctrl, p, t):
    k = 0
    while not (knots[k] <= t < knots[k + 1]):
        k += 1
    q = []
    for i in range(len(ctrl) + 1):
        if i + p <= k:
            q.append(ctrl[i])
        elif i > k:
            q.append(ctrl[i - 1])
        else:
            a = (t - knots[i]) / (knots[i + p] - knots[i])
            q.append(comb([(1 - a, ctrl[i - 1]), (a, ctrl[i])]))
    knots.insert(k + 1, t)
    return q


def refined(n, d):
    """Rows (as {index of M: weight}) of one level of the crease M0..M(n-1) between two corners."""
    m = d // 2
    M = [{i: F(1)} for i in range(n)]

    def implied(c, q):
        return [comb([(1 - F(i * (i + 1), m * (m + 1)), c), (F(i * (i + 1), m * (m + 1)), q)]) for i in range(1, m)]

    Q = [M[0]] + implied(M[0], M[1]) + M[1:-1] + implied(M[-1], M[-2])[::-1] + [M[-1]]
    K = len(Q) - d
    knots = [F(0)] * (d + 1) + [F(i) for i in range(1, K)] + [F(K)] * (d + 1)
    for t in [F(2 * i + 1, 2) for i in range(K)]:
        Q = insert_knot(knots, Q, d, t)
    assert Q[1:m] == implied(Q[0], Q[m]), "the end condition is kept by knot insertion"
    return [Q[0]] + Q[m:len(Q) - m] + [Q[-1]]


def solve_row(src, target, k, offsets, n):
    idx = [k + o for o in offsets]
    if min(idx) < 0 or max(idx) >= len(src):
        return None
    A = sp.Matrix([[src[i].get(v, 0) for i in idx] for v in range(n)])
    b = sp.Matrix([target.get(v, 0) for v in range(n)])
    try:
        sol, params = A.gauss_jordan_solve(b)
    except ValueError:
        return None
    return dict(zip(offsets, sol.subs({p: 0 for p in params})))


def pass_rows(src, target, n, rows):
    """For each distance k, the narrowest window (most centred first) that gives the row."""
    out = []
    for k in range(1, rows):
        for width in range(1, 9):
            found = [solve_row(src, target[k], k, list(range(lo, lo + width)), n)
                     for lo in sorted(range(-width + 1, 1), key=lambda lo: abs(lo + (width - 1) / 2)) if lo >= -k]
            found = [f for f in found if f]
            if found:
                out.append({o: w for o, w in found[0].items() if w != 0})
                break
    return out


if __name__ == "__main__":
    d = int(sys.argv[1]) if len(sys.argv) > 1 else 6
    n, rows = 30, 16
    src = refined(n, 2)
    uniform = {-1: sp.Rational(1, 4), 0: sp.Rational(1, 2), 1: sp.Rational(1, 4)}
    for degree in range(4, d + 1, 2):
        target = refined(n, degree)
        print(f"pass to degree {degree}: crease-ends (distance: {{step: weight}})")
        for k, row in enumerate(pass_rows(src, target, n, rows), start=1):
            if row != uniform:
                print(f"  {k}: " + ", ".join(f"{o}: {w}" for o, w in sorted(row.items())))
        src = target
