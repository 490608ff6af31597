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
corner) and prints them; rows equal to (1/4, 1/2, 1/4) need no end rule. A crease of N
edges between two corners is the spline with the end condition at both ends; where the
rules by distance alone do not give it (short creases: the two ends' rows overlap), the
script solves those rows within the crease and prints them with the crease's length on the
pass's level ("length": 2N - 1; such an entry takes precedence over the entry for its distance). N = 1 (one edge between two corners) has no
point between its corners on any level: the crease stays the segment, which is the curve.

Every row is solved on the narrowest window of crease points that gives it (up to WIDEST
points; a distance no window gives stops the script), and the rules are then checked by
applying them, with (1/4, 1/2, 1/4) elsewhere, to every crease of 2 .. `longest` edges
between corners, the longest well past the largest distance with a rule. The rules must fit
the scheme language's limits (framework/rules/rule.h): distances and |steps| up to 24, crease
lengths up to 49 on the pass's level. Passes 1 .. 6 (d = 4 .. 14) fit: pass 5 has rules at
distances 1 .. 16 over windows of up to 10 points and length entries up to 31, pass 6 at
distances 1 .. 19 over windows of 12 points and lengths up to 37. Pass 7 (d = 16) finds no
window of up to WIDEST points for distance 15 (the script stops there), so the scheme stops at
d = 14.

    python3 docs/derivations/quad_bspline_crease_ends.py 6     # prints passes 1, 2; needs sympy
    python3 docs/derivations/quad_bspline_crease_ends.py 14 --write schemes/quad-bspline.json
      # rewrites the scheme's even passes ("when": "even && passes >= i") with these rules
"""
import re
import sys
from fractions import Fraction as F

import sympy as sp

WIDEST = 12  # the widest window of crease points a row may read
REACH, LONGEST_LENGTH = 24, 49  # framework/rules/rule.h: kMaxCreaseReach, kMaxCreaseLength


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


def end_derivatives(knots, p, count):
    """Rows of the derivatives 0..count at the start of a clamped B-spline of degree p, as
    weights on its control points 0..count (the derivative of a B-spline is a B-spline of
    degree p - 1 with control points p (P(i+1) - P(i)) / (t(i+p+1) - t(i+1)); at a clamped
    start it equals its first control point)."""
    rows = [[F(int(i == j)) for j in range(count + 1)] for i in range(count + 1)]
    out = [rows[0]]
    for _ in range(count):
        rows = [[p * (rows[i + 1][j] - rows[i][j]) / (knots[i + p + 1] - knots[i + 1]) for j in range(count + 1)]
                for i in range(len(rows) - 1)]
        knots, p = knots[1:-1], p - 1
        out.append(rows[0])
    return out


def end_points(knots, d, c, q):
    """The control points 1..m-1 after corner c, with q the m-th, that make the derivatives
    2..m vanish at c (m = d/2), on these knots: {index of M: weight} each."""
    m = d // 2
    if m < 2:
        return []
    rows = end_derivatives(knots, d, m)[2:]
    A = sp.Matrix([[r[j] for j in range(1, m)] for r in rows])
    out = []
    for i, coef in enumerate(A.LUsolve(sp.Matrix([-r[0] for r in rows])), start=1):
        cq = A.LUsolve(sp.Matrix([-r[m] for r in rows]))[i - 1]
        out.append(comb([(coef, c), (cq, q)]))
    return out


def refined(n, d):
    """Rows (as {index of M: weight}) of one level of the crease M0..M(n-1) between two corners:
    the control polygon c, Q1..Q(m-1), M1..M(n-2), Q'(m-1)..Q'1, c' of the clamped uniform
    degree-d B-spline whose derivatives 2..m vanish at both corners (the Qs follow from that),
    with every knot interval's midpoint inserted, then without the Qs."""
    m = d // 2
    M = [{i: F(1)} for i in range(n)]
    K = n - 2  # knot intervals: n + 2(m - 1) control points, degree 2m
    knots = [F(0)] * (d + 1) + [F(i) for i in range(1, K)] + [F(K)] * (d + 1)
    mirrored = [K - t for t in reversed(knots)]
    Q = [M[0]] + end_points(knots, d, M[0], M[1]) + M[1:-1] + end_points(mirrored, d, M[-1], M[-2])[::-1] + [M[-1]]
    for t in [F(2 * i + 1, 2) for i in range(K)]:
        Q = insert_knot(knots, Q, d, t)
    mirrored = [2 * K - t for t in reversed(knots)]
    assert Q[1:m] == end_points(knots, d, Q[0], Q[m]), "the end condition is kept by knot insertion"
    assert Q[len(Q) - m:-1] == end_points(mirrored, d, Q[-1], Q[-1 - m])[::-1], "at both ends"
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
        for width in range(1, WIDEST + 1):
            found = [solve_row(src, target[k], k, list(range(lo, lo + width)), n)
                     for lo in sorted(range(-width + 1, 1), key=lambda lo: abs(lo + (width - 1) / 2)) if lo >= -k]
            found = [f for f in found if f]
            if found:
                out.append({o: w for o, w in found[0].items() if w != 0})
                break
        else:
            raise SystemExit(f"no window of up to {WIDEST} crease points gives the row at distance {k}")
    return out


def uniform_row():
    return {-1: sp.Rational(1, 4), 0: sp.Rational(1, 2), 1: sp.Rational(1, 4)}


def apply_rule(src, k, length, rule):
    """Rule `rule` (offsets towards the nearer corner negative) at point k of a crease of
    `length` edges, as {index of M: weight}; None where a step leaves the crease."""
    toward_end = length - k < k  # the nearer corner is point `length`: mirror the steps
    out = {}
    for o, w in rule.items():
        i = k - o if toward_end else k + o
        if i < 0 or i > length:
            return None
        for key, c in src[i].items():
            out[key] = out.get(key, 0) + w * c
    return {key: c for key, c in out.items() if c != 0}


def short_crease_rows(src, target, n, rules):
    """The rows of a crease of len(src) - 1 edges between two corners, up to its middle (the
    others mirror them), that the rules by distance alone do not give: solved within the crease."""
    length = len(src) - 1
    solved = pass_rows(src, target, n, length // 2 + 1)
    out = {}
    for k in range(1, length // 2 + 1):
        want = {key: c for key, c in target[k].items() if c != 0}
        if apply_rule(src, k, length, rules.get(k, uniform_row())) != want:
            assert solved[k - 1], f"no row for distance {k} of a crease of {length} edges"
            assert apply_rule(src, k, length, solved[k - 1]) == want
            out[k] = solved[k - 1]
    return out


def json_term(o, w):
    if o == 0:
        return f'{{"at": "self", "w": "{w}"}}'
    return f'{{"at": "crease-point", "step": {o}, "w": "{w}"}}'


def json_entry(distance, row, length=None):
    terms = ", ".join(json_term(o, w) for o, w in sorted(row.items()))
    key = f'"distance": {distance}' + (f', "length": {length}' if length else "")
    return f'{{{key}, "rule": [{terms}]}}'


def pass_entries(degree):
    """Pass (degree - 2)/2's crease-ends entries (JSON text, one per entry) and the crease length
    (edges before the split) from which the rules by distance alone are exact."""
    # Rows by distance, solved on a crease long enough that its far end is out of every window.
    rows = 2 * degree
    longest = rows + 2
    n = longest + 2
    src, target = refined(n, degree - 2), refined(n, degree)
    rules = {k: row for k, row in enumerate(pass_rows(src, target, n, rows), start=1) if row != uniform_row()}
    entries = [json_entry(k, row) for k, row in sorted(rules.items())]
    rows_written = list(rules.values())
    # Creases of N edges between two corners on the level a pass refines become creases of
    # 2N - 1 edges after the dual split (the pass's own level): the pass sees odd lengths.
    exact_from = None
    for N in range(2, longest + 1):
        length = 2 * N - 1
        own = short_crease_rows(refined(N + 1, degree - 2), refined(N + 1, degree), N + 1, rules)
        if not own:
            exact_from = exact_from or N
            continue
        assert exact_from is None, f"N = {N} needs its own rules after N = {exact_from} did not"
        entries += [json_entry(k, row, length) for k, row in sorted(own.items())]
        rows_written += own.values()
    assert exact_from is not None and exact_from + 4 <= longest, "the rules by distance must hold on long creases"
    assert max(rules) < longest - 1, "the longest crease checked must reach past every distance with a rule"
    assert max(rules) <= REACH, f"pass to degree {degree}: distance {max(rules)} is past the language's {REACH}"
    steps = [abs(o) for row in rows_written for o in row]
    assert max(steps) <= REACH, f"pass to degree {degree}: step {max(steps)} is past the language's {REACH}"
    assert 2 * exact_from - 3 <= LONGEST_LENGTH, f"pass to degree {degree}: lengths past {LONGEST_LENGTH}"
    return entries, exact_from, longest


PASS_STEP = """    {{"when": "even && passes >= {i}", "smooth": {{"vertex": {{
      "smooth": [{{"sum": "face-centroids", "w": "1/n"}}],
      "crease": [{{"at": "self", "w": "1/2"}}, {{"sum": "crease-neighbours", "w": "1/4"}}],
      "crease-ends": [
{entries}
      ]
    }}}}}},
"""


def write_scheme(path, passes):
    """Replace the even passes of the scheme file (its steps from the first
    `"when": "even && passes >= 1"` to the end of the last such step) with `passes`, and let
    the uniform passes after them (`"repeat": "max(passes - K, 0)"`) start after the last."""
    lines = open(path).read().split("\n")
    first = next(i for i, line in enumerate(lines) if '"when": "even && passes >= 1"' in line)
    last = max(i for i, line in enumerate(lines) if '"when": "even && passes >= ' in line)
    end = next(i for i in range(last, len(lines)) if lines[i].startswith("    }}}"))
    text = "".join(PASS_STEP.format(i=i, entries=",\n".join("        " + e for e in entries))
                   for i, entries in enumerate(passes, start=1))
    lines[first:end + 1] = text.rstrip("\n").split("\n")
    lines = [re.sub(r'"repeat": "max\(passes - \d+, 0\)"', f'"repeat": "max(passes - {len(passes)}, 0)"', line)
             for line in lines]
    open(path, "w").write("\n".join(lines))


if __name__ == "__main__":
    d = int(sys.argv[1]) if len(sys.argv) > 1 else 6
    passes = []
    for degree in range(4, d + 1, 2):
        entries, exact_from, longest = pass_entries(degree)
        passes.append(entries)
        print(f"pass to degree {degree}: crease-ends, by distance from the nearer corner")
        print(",\n".join("  " + e for e in entries))
        print(f"  (rules by distance alone are exact from N = {exact_from} crease edges on the level "
              f"before the split, checked up to N = {longest})")
    if len(sys.argv) > 3 and sys.argv[2] == "--write":
        write_scheme(sys.argv[3], passes)
        print(f"wrote passes 1 .. {len(passes)} into {sys.argv[3]}")
