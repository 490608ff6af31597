#!/usr/bin/env python3
"""The tables and the chart of docs/benchmarks.md from one run of scripts/benchmarks.sh.

    scripts/bench_report.py RUN_DIR [--page docs/benchmarks.md] [--chart docs/images/benchmarks.svg]

RUN_DIR holds the benchmark programs' outputs (refine.txt, update.txt, threads1.txt,
threads2.txt, threads2-busy.txt, stages-SCHEME-LEVEL.txt, refine-nostream.txt, sizes-N.txt,
meshlibs-full.txt, meshlibs-faces.txt, e2e.txt, io-write.txt, io-read.txt, big-whole.txt,
big-pieces.txt; any may be missing).
Each table of the page sits between `<!-- bench:NAME -->` and `<!-- /bench:NAME -->` and is
replaced; without --page the tables are printed. The chart is a plain SVG (no plotting
library needed): the ratio to OpenSubdiv per scheme and level, and time against mesh size.
"""
import argparse
import glob
import math
import os
import re
import sys

NAMES = {"catmull-clark": "Catmull-Clark", "loop": "Loop", "sqrt3": "√3", "doo-sabin": "Doo-Sabin",
         "modified-butterfly": "modified butterfly"}


def parse(path):
    """Header lines (starting with #) and records: the first word, then key=value fields."""
    header, records = [], []
    if not os.path.exists(path):
        return header, records
    with open(path, encoding="utf-8", errors="replace") as f:
        for line in f:
            line = line.strip().replace("\0", "")
            if not line:
                continue
            if line.startswith("#"):
                header.append(line)
                continue
            words = re.findall(r'(\S+?)=("[^"]*"|\S+)|(\S+)', line)
            rec = {"_first": line.split()[0], "_line": line}
            for key, value, bare in words:
                if key:
                    rec[key] = value.strip('"')
            records.append(rec)
    return header, records


def num(rec, key):
    try:
        return float(rec[key])
    except (KeyError, ValueError):
        return None


def ms(v):
    return "–" if v is None else (f"{v:.0f}" if v >= 100 else f"{v:.1f}")


def ratio(v):
    return "–" if v is None else f"{v:.2f}"


def load_of(header):
    for h in header:
        m = re.search(r"loadavg=([\d.]+ [\d.]+ [\d.]+)", h)
        if m:
            return m.group(1)
    return "?"


def bandwidth_of(header):
    out = {}
    for h in header:
        m = re.search(r"bandwidth at=(\w+) memset_gbs=([\d.]+) memcpy_gbs=([\d.]+)", h)
        if m:
            out[m.group(1)] = (float(m.group(2)), float(m.group(3)))
    return out


def rows(records, **want):
    return [r for r in records if all(r.get(k) == v for k, v in want.items())]


def summary(records, scheme, level):
    for r in records:
        if r["_first"] == scheme and r.get("level") == level and "refined_faces" in r:
            return r
    return {}


def cases(records):
    seen = []
    for r in records:
        key = (r["_first"], r.get("level"))
        if "level" in r and key not in seen and "refined_faces" in r:
            seen.append(key)
    return seen


def table(head, body):
    lines = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    lines += ["| " + " | ".join(str(c) for c in row) + " |" for row in body]
    return "\n".join(lines)


def refine_tables(run):
    header, recs = parse(os.path.join(run, "refine.txt"))
    if not recs:
        return {}
    body, bound, memory = [], [], []
    for scheme, level in cases(recs):
        warm = rows(recs, _first=scheme, level=level, memory="warm", clock="user", topology="default")
        cold = rows(recs, _first=scheme, level=level, memory="cold", clock="user", topology="default")
        s = summary(recs, scheme, level)
        name = f"{NAMES.get(scheme, scheme)} {level}"
        if warm:
            w = warm[0]
            body.append([name, f"{ms(num(w, 'subdivkit_ms'))} ({ms(num(w, 'osd_ms'))})", f"**{ratio(num(w, 'ratio'))}**",
                         ratio(num(w, "topo_ratio")), ratio(num(w, "geom_ratio")),
                         ratio(num(cold[0], "ratio")) if cold else "–", s.get("check", "–")])
        bound.append([name, s.get("written_mb", "–"), s.get("bound_ms", "–"), s.get("x_bound", "–"),
                      s.get("osd_x_bound", "–")])
        ours, theirs = num(s, "subdivkit_peak_mb"), num(s, "osd_peak_mb")
        memory.append([name, ms(ours), ms(theirs), ratio(ours / theirs) if ours and theirs else "–"])
    bw = bandwidth_of(header)
    bw_text = ", ".join(f"{at}: memset {w:.1f} GB/s, memcpy {c:.1f} GB/s" for at, (w, c) in bw.items())
    note = f"Load average at the start: {load_of(header)}."
    return {
        "refine": note + "\n\n" + table(["scheme, level", "SubdivKit ms (OpenSubdiv)", "total ratio",
                                         "topology ratio", "geometry ratio", "cold ratio", "check"], body),
        "bound": f"Bandwidth in the same run ({bw_text or 'not measured'}).\n\n"
        + table(["scheme, level", "bytes written (MB)", "bound (ms)", "SubdivKit, x the bound",
                 "OpenSubdiv, x the bound"], bound),
        "memory": table(["scheme, level", "SubdivKit peak MB", "OpenSubdiv peak MB", "ratio"], memory),
    }


def update_table(run):
    header, recs = parse(os.path.join(run, "update.txt"))
    body = []
    for scheme, level in cases(recs):
        w = rows(recs, _first=scheme, level=level, memory="warm", clock="user", mode="update")
        s = summary(recs, scheme, level)
        if not w:
            continue
        w = w[0]
        body.append([f"{NAMES.get(scheme, scheme)} {level}", f"{ms(num(w, 'update_ms'))} ({ms(num(w, 'osd_update_ms'))})",
                     f"**{ratio(num(w, 'update_ratio'))}**",
                     f"{ms(num(w, 'stencil_ms'))} ({ms(num(w, 'osd_stencil_ms'))})",
                     f"{ms(num(s, 'subdivkit_peak_mb'))} ({ms(num(s, 'osd_peak_mb'))})"])
    if not body:
        return {}
    return {"update": f"Load average at the start: {load_of(header)}.\n\n"
            + table(["scheme, level", "one update, ms: Evaluator (UpdateValues)", "ratio",
                     "preparation ms: Evaluator (stencil table)", "peak MB (OpenSubdiv)"], body)}


def threads_table(run):
    h1, one = parse(os.path.join(run, "threads1.txt"))
    h2, two = parse(os.path.join(run, "threads2.txt"))
    hb, busy = parse(os.path.join(run, "threads2-busy.txt"))
    body = []
    for scheme, level in cases(one):
        def total(recs):
            w = rows(recs, _first=scheme, level=level, memory="warm", clock="wall", topology="default")
            return num(w[0], "subdivkit_ms") if w else None

        def digest(recs):
            return summary(recs, scheme, level).get("digest")

        a, b, c = total(one), total(two), total(busy)
        same = "same" if digest(one) and digest(one) == digest(two) and (not busy or digest(busy) == digest(one)) \
            else "DIFFERENT"
        body.append([f"{NAMES.get(scheme, scheme)} {level}", ms(a), ms(b), f"**{a / b:.2f}x**" if a and b else "–",
                     ms(c), f"{a / c:.2f}x" if a and c else "–", same])
    if not body:
        return {}
    return {"threads": f"Load average at the start: {load_of(h1)} (1 thread), {load_of(h2)} (2 threads).\n\n"
            + table(["scheme, level", "1 thread, wall ms", "2 threads", "speed-up", "2 threads, other core busy",
                     "speed-up", "bits"], body)}


def stages_table(run):
    """subdiv-bench-stages: totals on one and two threads, and the stages that lose most on two."""
    body, load = [], "?"
    for scheme in ("catmull-clark", "loop"):
        for level in ("1", "2"):
            header, recs = parse(os.path.join(run, f"stages-{scheme}-{level}.txt"))
            totals = {r.get("threads"): r for r in recs if r["_first"] == "total"}
            if "1" not in totals or "2" not in totals:
                continue
            load = load_of(header)
            stages = [r for r in recs if r["_first"].startswith("stage=")]
            stages.sort(key=lambda r: -(num(r, "loss_ms") or 0))
            worst = ", ".join(f"{r['stage']} {num(r, 'loss_ms'):.1f} ({num(r, 'cores'):.2f} cores)"
                              for r in stages[:4] if num(r, "loss_ms") is not None)
            one, two = num(totals["1"], "wall_ms"), num(totals["2"], "wall_ms")
            body.append([f"{NAMES.get(scheme, scheme)} {level}", ms(one), ms(two),
                         f"**{one / two:.2f}x**" if one and two else "–", worst])
    if not body:
        return {}
    return {"stages": f"Load average at the start: {load}.\n\n"
            + table(["scheme, level", "1 thread, wall ms", "2 threads", "speed-up",
                     "stages losing most on 2 threads: loss ms (cores)"], body)}


def streaming_table(run):
    """refine.txt against refine-nostream.txt (SUBDIV_STREAMING_STORES=0): each one's ratios to OpenSubdiv."""
    _, on = parse(os.path.join(run, "refine.txt"))
    header, off = parse(os.path.join(run, "refine-nostream.txt"))
    body = []
    for scheme, level in cases(off):
        def warm(recs):
            w = rows(recs, _first=scheme, level=level, memory="warm", clock="user", topology="default")
            return w[0] if w else {}
        a, b = warm(on), warm(off)
        if not a or not b:
            continue
        body.append([f"{NAMES.get(scheme, scheme)} {level}", ratio(num(a, "ratio")), ratio(num(b, "ratio")),
                     ratio(num(a, "topo_ratio")), ratio(num(b, "topo_ratio")),
                     ratio(num(a, "geom_ratio")), ratio(num(b, "geom_ratio"))])
    if not body:
        return {}
    return {"streaming": f"Load average at the start: {load_of(header)} (without).\n\n"
            + table(["scheme, level", "total ratio: streaming", "without", "topology: streaming", "without",
                     "geometry: streaming", "without"], body)}


def size_points(run):
    points = {}
    for path in glob.glob(os.path.join(run, "sizes-*.txt")):
        _, recs = parse(path)
        for r in rows(recs, memory="warm", clock="user", topology="default"):
            s = summary(recs, r["_first"], r["level"])
            faces = num(s, "faces")
            if faces:
                points.setdefault(r["_first"], []).append((faces, num(r, "subdivkit_ms"), num(r, "osd_ms")))
    for v in points.values():
        v.sort()
    return points


def sizes_table(run):
    points = size_points(run)
    body = []
    for scheme, pts in points.items():
        for faces, ours, theirs in pts:
            per = f"{ours / faces * 1e6:.0f}" if ours else "–"
            body.append([NAMES.get(scheme, scheme), f"{faces:,.0f}", ms(ours), ms(theirs),
                         ratio(ours / theirs) if ours and theirs else "–", per])
    if not body:
        return {}
    return {"sizes": table(["scheme (level 1)", "base faces", "SubdivKit ms", "OpenSubdiv ms", "ratio",
                            "SubdivKit ns per base face"], body)}


def meshlibs_table(run):
    body, header = [], []
    for last in ("full", "faces"):
        h, recs = parse(os.path.join(run, f"meshlibs-{last}.txt"))
        header = header or h
        body += meshlibs_rows(recs, "complete" if last == "full" else "faces only")
    if not body:
        return {}
    return {"meshlibs": f"Load average at the start: {load_of(header)}.\n\n"
            + table(["scheme, level", "against", "SubdivKit's last level", "SubdivKit user ms (other)", "user ratio",
                     "cold ratio", "peak MB (other)", "check"], body)}


def meshlibs_rows(recs, last):
    body = []
    for r in recs:
        if "library" not in r or "user_ratio" not in r:
            continue
        body.append([f"{NAMES.get(r['_first'], r['_first'])} {r.get('level')}", r["library"], last,
                     f"{r.get('subdivkit_user_ms', '–')} ({r.get('other_user_ms', '–')})",
                     f"**{r['user_ratio']}**", r.get("cold_ratio", "–"),
                     f"{r.get('subdivkit_peak_mb', '–')} ({r.get('other_peak_mb', '–')})", r.get("check", "–")])
    return body


def e2e_table(run):
    path = os.path.join(run, "e2e.txt")
    if not os.path.exists(path):
        return {}
    body, last = [], None
    pat = re.compile(r"^(.*?)\s+wall\s+([\d.]+) s\s+user\s+([\d.]+) s\s+sys\s+([\d.]+) s\s+peak\s+([\d.]+) GB\s+"
                     r"file\s+([\d.]+) MB\s+load (.*)$")
    stages = re.compile(r"read\s+([\d.]+) s\s+refine\s+([\d.]+) s\s+write\s+([\d.]+) s\s+end to end / refine\s+([\d.]+)")
    for line in open(path, encoding="utf-8"):
        m = pat.match(line.strip())
        if m:
            last = [m.group(1), m.group(2), m.group(3), m.group(5), m.group(6), "", "", "", "", m.group(7)]
            body.append(last)
            continue
        s = stages.search(line)
        if s and last:
            last[5:9] = [s.group(1), s.group(2), s.group(3), s.group(4)]
    if not body:
        return {}
    return {"e2e": table(["options", "wall s", "user s", "peak GB", "file MB", "read s", "refine s", "write s",
                          "wall / refine", "load"], body)}


def io_tables(run):
    """subdiv-bench-io: the writers (io-write.txt) and the readers (io-read.txt)."""
    out = {}
    header, recs = parse(os.path.join(run, "io-write.txt"))
    writes = [r for r in recs if r["_first"] == "write"]
    if writes:
        body = []
        for r in writes:
            state = "clean page cache" if r["_line"].split()[1] == "clean" else "right after the first file"
            body.append([state, f"{num(r, 'vtp_gb'):.3f}",
                         f"{num(r, 'subdivkit_s'):.2f} ({num(r, 'subdivkit_user_s'):.2f} + {num(r, 'subdivkit_sys_s'):.2f})",
                         f"**{num(r, 'subdivkit_gb_per_s'):.2f}**",
                         f"{num(r, 'vtk_s'):.2f} ({num(r, 'vtk_user_s'):.2f} + {num(r, 'vtk_sys_s'):.2f})",
                         f"**{ratio(num(r, 'ratio'))}**", ratio(num(r, "user_ratio"))])
        out["io-write"] = f"Load average at the start: {load_of(header)}.\n\n" + table(
            ["writing .vtp (defaults)", "file GB", "SubdivKit s (user + sys)", "GB/s", "VTK s (user + sys)", "ratio",
             "user ratio"], body)
    header, recs = parse(os.path.join(run, "io-read.txt"))
    reads = [r for r in recs if r["_first"] == "read"]
    if reads:
        label = {"vtp": ".vtp, defaults (inline base64, LZ4)", "vtp-raw": ".vtp, raw appended, LZ4", "obj": ".obj",
                 "ply": ".ply (binary)"}
        body = []
        for r in reads:
            kind = r["_line"].split()[1]
            om = num(r, "openmesh_s") or 0
            body.append([label.get(kind, kind), f"{num(r, 'gb'):.3f}",
                         f"{num(r, 'subdivkit_s'):.2f} ({num(r, 'subdivkit_user_s'):.2f})",
                         f"{num(r, 'vtk_s'):.2f} ({num(r, 'vtk_user_s'):.2f})", f"**{ratio(num(r, 'vtk_ratio'))}**",
                         f"{om:.2f} ({num(r, 'openmesh_user_s'):.2f})" if om else "–",
                         f"**{ratio(num(r, 'openmesh_ratio'))}**" if om else "–"])
        out["io-read"] = f"Load average at the start: {load_of(header)}.\n\n" + table(
            ["reading", "file GB", "SubdivKit s (user)", "VTK s (user)", "ratio", "OpenMesh s (user)", "ratio"], body)
    return out


def big_table(run):
    """Level 3 whole and in pieces (bench-end-to-end.sh with LEVELS=3), peak against the file."""
    pat = re.compile(r"^(.*?)\s+wall\s+([\d.]+) s\s+user\s+([\d.]+) s\s+sys\s+([\d.]+) s\s+peak\s+([\d.]+) GB\s+"
                     r"file\s+([\d.]+) MB\s+load (.*)$")
    body = []
    for name, label in (("big-whole.txt", "whole, `-o OUT.vtp`"),
                        ("big-pieces.txt", "`--pieces 8 --max-memory 4G -o OUT.pvtp`")):
        path = os.path.join(run, name)
        if not os.path.exists(path):
            continue
        for line in open(path, encoding="utf-8"):
            m = pat.match(line.strip())
            if not m:
                continue
            wall, user, sys_s, peak, size = (float(m.group(i)) for i in range(2, 7))
            body.append([label, f"{wall:.1f}", f"{user:.1f} + {sys_s:.1f}", f"{peak:.2f}", f"{size / 1000:.2f}",
                         f"{peak / (size / 1000):.2f}", m.group(7)])
    if not body:
        return {}
    return {"big": table(["run", "wall s", "user + sys s", "peak GB", "output GB", "peak / output", "load"], body)}


def svg_chart(run, out):
    """Two panels: ratio to OpenSubdiv (total, geometry) per scheme and level; time against faces."""
    _, recs = parse(os.path.join(run, "refine.txt"))
    bars = []
    for scheme, level in cases(recs):
        w = rows(recs, _first=scheme, level=level, memory="warm", clock="user", topology="default")
        if w:
            bars.append((f"{NAMES.get(scheme, scheme)} L{level}", num(w[0], "ratio"), num(w[0], "geom_ratio")))
    points = size_points(run)
    W, H, pad = 960, 380, 50
    svg = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{W}" height="{H}" font-family="sans-serif" font-size="12">',
           f'<rect width="{W}" height="{H}" fill="white"/>']
    # Panel A: bars, 0..1.2
    x0, y0, pw, ph = pad, 40, W / 2 - pad - 20, H - 110
    svg.append(f'<text x="{x0}" y="22" font-size="14">SubdivKit / OpenSubdiv, one core, warm (below 1: faster)</text>')
    top = 1.2
    def ya(v):
        return y0 + ph - min(v, top) / top * ph
    for t in (0, 0.25, 0.5, 0.75, 1.0):
        svg.append(f'<line x1="{x0}" x2="{x0 + pw}" y1="{ya(t):.1f}" y2="{ya(t):.1f}" stroke="{"#444" if t == 1 else "#ddd"}"/>')
        svg.append(f'<text x="{x0 - 6}" y="{ya(t) + 4:.1f}" text-anchor="end">{t:.2f}</text>')
    if bars:
        group = pw / len(bars)
        for i, (label, total, geom) in enumerate(bars):
            gx = x0 + i * group + group * 0.15
            bw = group * 0.33
            for j, (v, colour) in enumerate(((total, "#2b6cb0"), (geom, "#dd6b20"))):
                if v is None:
                    continue
                svg.append(f'<rect x="{gx + j * bw:.1f}" y="{ya(v):.1f}" width="{bw:.1f}" height="{y0 + ph - ya(v):.1f}" fill="{colour}"/>')
                svg.append(f'<text x="{gx + j * bw + bw / 2:.1f}" y="{ya(v) - 3:.1f}" text-anchor="middle" font-size="10">{v:.2f}</text>')
            svg.append(f'<text x="{gx + bw:.1f}" y="{y0 + ph + 16}" text-anchor="middle">{label}</text>')
    svg.append(f'<rect x="{x0}" y="{H - 40}" width="12" height="12" fill="#2b6cb0"/><text x="{x0 + 16}" y="{H - 30}">total</text>')
    svg.append(f'<rect x="{x0 + 70}" y="{H - 40}" width="12" height="12" fill="#dd6b20"/><text x="{x0 + 86}" y="{H - 30}">geometry (against Interpolate)</text>')
    # Panel B: log-log time against base faces, level 1
    x1 = W / 2 + pad
    svg.append(f'<text x="{x1}" y="22" font-size="14">Level 1, warm user ms against base faces (log-log)</text>')
    all_pts = [(f, t) for pts in points.values() for f, a, b in pts for t in (a, b) if t]
    if all_pts:
        fmin, fmax = min(f for f, _ in all_pts), max(f for f, _ in all_pts)
        tmin, tmax = min(t for _, t in all_pts), max(t for _, t in all_pts)
        lf0, lf1 = math.log10(fmin) - 0.1, math.log10(fmax) + 0.1
        lt0, lt1 = math.log10(tmin) - 0.2, math.log10(tmax) + 0.2
        def xb(f):
            return x1 + (math.log10(f) - lf0) / (lf1 - lf0) * pw
        def yb(t):
            return y0 + ph - (math.log10(t) - lt0) / (lt1 - lt0) * ph
        for e in range(math.ceil(lf0), math.floor(lf1) + 1):
            svg.append(f'<line x1="{xb(10 ** e):.1f}" x2="{xb(10 ** e):.1f}" y1="{y0}" y2="{y0 + ph}" stroke="#ddd"/>')
            svg.append(f'<text x="{xb(10 ** e):.1f}" y="{y0 + ph + 16}" text-anchor="middle">{10 ** e:,.0f}</text>')
        for e in range(math.ceil(lt0), math.floor(lt1) + 1):
            svg.append(f'<line x1="{x1}" x2="{x1 + pw}" y1="{yb(10 ** e):.1f}" y2="{yb(10 ** e):.1f}" stroke="#ddd"/>')
            svg.append(f'<text x="{x1 - 6}" y="{yb(10 ** e) + 4:.1f}" text-anchor="end">{10 ** e:g}</text>')
        styles = {"catmull-clark": ("#2b6cb0", "#90cdf4"), "loop": ("#c05621", "#fbd38d")}
        for row, (scheme, pts) in enumerate(points.items()):
            ours_c, theirs_c = styles.get(scheme, ("#333", "#999"))
            for k, colour, who in ((1, ours_c, "SubdivKit"), (2, theirs_c, "OpenSubdiv")):
                lx, ly = x1 + (k - 1) * 200, H - 22 + row * 14
                line = [(xb(p[0]), yb(p[k])) for p in pts if p[k]]
                if not line:
                    continue
                svg.append('<polyline fill="none" stroke-width="2" stroke="{}" points="{}"/>'.format(
                    colour, " ".join(f"{x:.1f},{y:.1f}" for x, y in line)))
                for x, y in line:
                    svg.append(f'<circle cx="{x:.1f}" cy="{y:.1f}" r="3" fill="{colour}"/>')
                svg.append(f'<line x1="{lx}" x2="{lx + 16}" y1="{ly - 4}" y2="{ly - 4}" stroke="{colour}" stroke-width="3"/>')
                svg.append(f'<text x="{lx + 20}" y="{ly}">{who} {NAMES.get(scheme, scheme)}</text>')
        svg.append(f'<text x="{x1 + pw / 2}" y="{y0 + ph + 32}" text-anchor="middle">base faces</text>')
    svg.append("</svg>")
    os.makedirs(os.path.dirname(out) or ".", exist_ok=True)
    with open(out, "w", encoding="utf-8") as f:
        f.write("\n".join(svg) + "\n")


def fill_page(page, tables):
    text = open(page, encoding="utf-8").read()
    for name, body in tables.items():
        pattern = re.compile(rf"(<!-- bench:{name} -->\n)(?:.*?\n)?(<!-- /bench:{name} -->)", re.S)
        if not pattern.search(text):
            print(f"bench_report: {page} has no <!-- bench:{name} --> block; table left out", file=sys.stderr)
            continue
        text = pattern.sub(lambda m: m.group(1) + body + "\n" + m.group(2), text)
    with open(page, "w", encoding="utf-8") as f:
        f.write(text)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("run", help="folder with one run's outputs (scripts/benchmarks.sh)")
    ap.add_argument("--page", help="markdown page whose bench blocks are replaced")
    ap.add_argument("--chart", help="SVG chart to write")
    a = ap.parse_args()
    if not os.path.isdir(a.run):
        sys.exit(f"bench_report: {a.run} is not a folder; give the folder scripts/benchmarks.sh wrote")
    tables = {}
    for make in (refine_tables, update_table, threads_table, stages_table, streaming_table, sizes_table,
                 meshlibs_table, e2e_table, io_tables, big_table):
        tables.update(make(a.run))
    if a.page:
        fill_page(a.page, tables)
    else:
        for name, body in tables.items():
            print(f"## {name}\n\n{body}\n")
    if a.chart:
        svg_chart(a.run, a.chart)


if __name__ == "__main__":
    main()
