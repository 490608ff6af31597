"""pvbatch: "SubdivKit Analyze" gives the spectrum `subdiv analyze --json` reports (the
moduli of the leading eigenvalues, lambda_1 squared, the C1 verdict) for Catmull-Clark at
valence 5, for Loop over a range of valences, and at boundary and crease vertices
(`Vertices`, as `--boundary` and `--crease`); its characteristic maps are the ones
`subdiv analyze --vtk` writes (the same number of faces per valence)."""

import json
import os
import re

import pv_support as pv

pv.load_plugin(globals())


KINDS = ["interior", "boundary", "crease"]  # the property Vertices: 0, 1, 2


def cli_spectrum(scheme, first, last, kind):
    """`subdiv analyze SCHEME --valence FIRST..LAST [--boundary|--crease] --json F`: per
    valence, its analysis of that kind, and the folder of the characteristic maps."""
    path = os.path.join(pv.WORK, f"{scheme}-{kind}-{first}-{last}.json")
    vtk_dir = os.path.join(pv.WORK, f"{scheme}-{kind}-maps")
    flags = [] if kind == "interior" else [f"--{kind}"]
    pv.cli("analyze", scheme, "--valence", f"{first}..{last}", *flags, "--json", path, "--vtk", vtk_dir)
    with open(path) as f:
        report = json.load(f)
    key = "analyses" if kind == "interior" else f"{kind}_analyses"
    return {int(re.search(r"valence (\d+)", a["configuration"]).group(1)): a for a in report[key]}, vtk_dir


def check(scheme, first, last, shown=8, kind="interior"):
    analyze = SubdivKitAnalyze(Scheme=scheme, Valences=[first, last], Eigenvalues=shown,  # noqa: F821
                               Vertices=KINDS.index(kind))
    analyze.UpdatePipeline()
    table = pv.fetch(analyze, 1)
    maps = pv.fetch(analyze, 0)
    want, vtk_dir = cli_spectrum(scheme, first, last, kind)
    assert table.GetNumberOfRows() == last - first + 1, table.GetNumberOfRows()
    column = {table.GetColumnName(c): table.GetColumn(c) for c in range(table.GetNumberOfColumns())}
    faces = 0
    for row in range(table.GetNumberOfRows()):
        n = column["valence"].GetValue(row)
        a = want[n]
        moduli = sorted((abs(complex(*z)) if isinstance(z, list) else abs(z) for z in a["eigenvalues"]), reverse=True)
        for k in range(min(shown, len(moduli))):
            got = column[f"lambda_{k}"].GetValue(row)
            assert abs(got - moduli[k]) <= 1e-12, (scheme, n, k, got, moduli[k])
        assert abs(column["lambda_1^2"].GetValue(row) - a["lambda1"] ** 2) <= 1e-12, (scheme, n)
        assert column["c1"].GetValue(row) == int(a["c1"]), (scheme, n)
        prefix = scheme if kind == "interior" else f"{scheme}_{kind}"
        map_file = os.path.join(vtk_dir, f"{prefix}_characteristic_n{n}.vtp")
        faces += pv.read_vtp(map_file).GetNumberOfPolys() if os.path.exists(map_file) else 0
    assert maps.GetNumberOfPolys() == faces, (maps.GetNumberOfPolys(), faces)
    print(f"{scheme} {kind} valences {first}..{last}: lambda_0..lambda_{shown - 1}, lambda_1^2, c1 as subdiv analyze; "
          f"{faces} characteristic-map faces")
    return column


column = check("catmull-clark", 5, 5)
print("  catmull-clark n=5:", ", ".join(f"{column[f'lambda_{k}'].GetValue(0):.6f}" for k in range(4)))
check("loop", 3, 8)
# Boundary and crease vertices: Catmull-Clark's crease valence 2k is judged as two boundary
# valences k + 1 (docs/analysis.md), so its rows must match the CLI's crease analyses, and the
# dual scheme is analysed at the face its sector becomes.
check("catmull-clark", 2, 5, kind="boundary")
check("catmull-clark", 4, 6, kind="crease")
check("doo-sabin", 3, 5, kind="boundary")
check("doo-sabin", 4, 5, kind="crease")
print("analyze_test: ok")
