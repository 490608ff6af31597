#!/usr/bin/env python3
"""Define a new subdivision scheme inline, refine with it, compare it with Loop, and plot
its spectrum.

The new scheme is Loop with a "stiffness" t: each old vertex moves only (1 - t) of the way
Loop moves it (vertex weight beta_n scaled by 1 - t). t = 0 is Loop. The analysis shows
what t does: the subdominant eigenvalue lambda_1 = 3/8 + cos(2 pi/n)/4 comes from the edge
rule and does not change, but the vertex rule's eigenvalue 1 - n beta_n (1 - t) grows with
t, passes lambda_1^2 (curvature at extraordinary vertices degrades) and, at large t,
lambda_1 itself (no tangent plane: not C1).

Run from the repository root after building (see docs/python.md):

    PYTHONPATH=build/python /usr/bin/python3 examples/python/new_scheme.py [out.png]
"""
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")  # no display needed
import matplotlib.pyplot as plt
import numpy as np

import subdivkit as sk

ROOT = Path(__file__).resolve().parents[2]

STIFF_LOOP = {
    "name": "stiff-loop",
    "description": "Loop with old vertices moving (1 - t) of Loop's way",
    "split": "triangle",
    "faces": "triangles",
    "curve": "cubic-bspline",
    "parameters": {
        "t": {"default": 0.5, "min": 0, "max": 1, "description": "stiffness: 0 is Loop, 1 keeps old vertices"},
    },
    "definitions": {
        "beta_n": "(1 - t) * (5/8 - (3/8 + cos(2*pi/n)/4)^2) / n",
    },
    "rules": {
        "edge": [{"sum": "ends", "w": "3/8"}, {"sum": "opposite", "w": "1/8"}],
        "vertex": [{"at": "self", "w": "1 - n*beta_n"}, {"sum": "ring", "w": "beta_n"}],
    },
}


def surface_analysis(scheme: sk.Scheme, valences: range) -> sk.SurfaceAnalysis:
    """analyze() of a surface scheme (analyze() gives a CurveAnalysis for curve schemes)."""
    analysis = sk.analyze(scheme, valences)
    assert isinstance(analysis, sk.SurfaceAnalysis)
    return analysis


def main(png: str) -> None:
    loop = sk.Scheme.load("loop")
    octahedron = sk.read_mesh(ROOT / "examples" / "meshes" / "octahedron.obj")

    # 1. Refine with both schemes; the topology is the same, so points compare one to one.
    reference = sk.refine(octahedron, loop, 4)
    print(f"octahedron, 4 levels: {reference.n_points} points, {reference.n_faces} faces")
    for t in (0.0, 0.25, 0.5):
        stiff = sk.Scheme.from_dict(STIFF_LOOP, t=t)
        fine = sk.refine(octahedron, stiff, 4)
        radius = np.linalg.norm(fine.points, axis=1)
        print(f"  stiff-loop t={t:<4}: max distance to Loop {np.abs(fine.points - reference.points).max():.4f}, "
              f"radius {radius.min():.4f}..{radius.max():.4f}")

    # 2. The same step as a matrix: S @ P is the refinement, for any positions.
    S = sk.stencils(octahedron, sk.Scheme.from_dict(STIFF_LOOP, t=0.5), 4, composed=True)
    print(f"composed matrix {S.shape}, {S.nnz} non-zeros; rows sum to 1: "
          f"{np.allclose(np.asarray(S.sum(axis=1)).ravel(), 1)}")

    # 3. Eigen-analysis at extraordinary vertices of valence 3..12.
    valences = range(3, 13)
    analyses = {"loop": surface_analysis(loop, valences)}
    for t in (0.25, 0.5):
        analyses[f"stiff-loop t={t}"] = surface_analysis(sk.Scheme.from_dict(STIFF_LOOP, t=t), valences)
    for name, a in analyses.items():
        print(f"{name:>17}: C1 at valences {list(a.valences[a.c1])}")

    # 4. Plot: the leading eigenvalue moduli per valence, lambda_1^2 as a line.
    fig, axes = plt.subplots(1, len(analyses), figsize=(4.2 * len(analyses), 3.8), sharey=True)
    for ax, (name, a) in zip(axes, analyses.items()):
        moduli = a.spectrum(6)
        for j in range(1, moduli.shape[1]):
            ax.plot(a.valences, moduli[:, j], "o", ms=4, color="C0" if j <= 2 else "0.55",
                    label="$|\\lambda_1|, |\\lambda_2|$" if j == 1 else ("$|\\lambda_j|, j \\geq 3$" if j == 3 else None))
        ax.plot(a.valences, a.subdominant ** 2, "-", color="C3", label="$\\lambda_1^2$")
        for n in a.valences[~a.c1]:
            ax.axvspan(n - 0.5, n + 0.5, color="C1", alpha=0.15, lw=0)
        ax.set_title(name)
        ax.set_xlabel("valence n")
        ax.set_xticks(list(a.valences))
        ax.set_ylim(0, 1.02)
        ax.grid(alpha=0.3)
    axes[0].set_ylabel("eigenvalue modulus")
    axes[0].legend(loc="lower right", fontsize=8)
    fig.suptitle("Spectra of Loop and an inline 'stiff-loop' scheme (shaded: not C1)")
    fig.tight_layout()
    fig.savefig(png, dpi=110)
    print(f"wrote {png}")


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "python-spectrum.png")
