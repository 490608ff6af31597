#!/usr/bin/env python3
"""`subdiv refine` draws its progress bar on a terminal, and nothing on a pipe or with -q:
while reading, on each level, while writing (VTK formats and OBJ, OFF, PLY, STL);
`subdiv evaluate` and `subdiv interpolate` while reading their mesh; `subdiv evaluate`
while sampling, refining adaptively and evaluating points, and `subdiv refine --adaptive`;
and within a level, after each pass of its step.

The terminal is a pseudo-terminal (Python's pty module): stderr is a tty there, as in a
shell. Usage: progress_pty_test.py SUBDIV SOURCE_DIR
"""
import os
import re
import subprocess
import sys
import tempfile
from pathlib import Path


def run_on_pty(args, env=None):
    """Exit code and what the command wrote to stderr, a pseudo-terminal."""
    master, slave = os.openpty()
    process = subprocess.Popen(args, stdout=subprocess.DEVNULL, stderr=slave, env=env)
    os.close(slave)
    out = b""
    while True:
        try:
            chunk = os.read(master, 65536)
        except OSError:  # the other side closed (Linux: EIO)
            break
        if not chunk:
            break
        out += chunk
    os.close(master)
    return process.wait(), out.decode(errors="replace")


def main():
    subdiv, source = sys.argv[1], Path(sys.argv[2])
    mesh = source / "examples" / "meshes" / "torus-quads.obj"
    failures = []
    with tempfile.TemporaryDirectory() as tmp:
        refine = [subdiv, "refine", str(mesh), "-l", "6", "-o", str(Path(tmp) / "torus.pvd")]
        code, tty = run_on_pty(refine)
        if code != 0:
            failures.append(f"refine on a pty exited {code}: {tty!r}")
        for part, what in [("\r\x1b[K", "the line redrawn in place"), ("level 6/6: 196608 faces  [", "a bar on a level"),
                           ("writing ", "the writing phase"), ("%", "a percentage")]:
            if part not in tty:
                failures.append(f"on a pty, no {what} ({part!r}) in {tty!r}")
        code, quiet = run_on_pty(refine + ["-q"])
        if code != 0 or quiet:
            failures.append(f"with -q on a pty: exit {code}, stderr {quiet!r} (expected nothing)")
        # Mesh formats: a bar while the input is read and while the output is written, moving
        # between its ends (a percentage strictly between 0 and 100), every step drawn however
        # fast the machine (SUBDIV_PROGRESS_EVERY_STEP).
        every_step = dict(os.environ, SUBDIV_PROGRESS_EVERY_STEP="1")
        big = Path(tmp) / "big.obj"
        code, _ = run_on_pty([subdiv, "refine", str(mesh), "-l", "5", "-q", "-o", str(big)])
        for ext in ["obj", "off", "ply", "stl"]:
            out = Path(tmp) / f"again.{ext}"
            code, tty = run_on_pty([subdiv, "refine", str(big), "-l", "0", "-o", str(out)], every_step)
            if code != 0:
                failures.append(f"refine {big} -o {out} on a pty exited {code}: {tty!r}")
            for part, what in [(f"reading {big}  [", "a bar while reading"), (f"writing {out}  [", "a bar while writing")]:
                if part not in tty:
                    failures.append(f"on a pty, no {what} ({part!r}) in {tty!r}")
            for phase in ["reading", "writing"]:
                shares = re.findall(phase + r" [^\r]*\] +(\d+)%", tty)
                if not any(0 < int(share) < 100 for share in shares):
                    failures.append(f".{ext}: the bar while {phase} never stood between 0 and 100% ({shares})")
        # evaluate and interpolate read their mesh with the same bar (issue 31).
        points = Path(tmp) / "points.csv"
        points.write_text("face,u,v\n0,0.5,0.5\n")
        for command in [["evaluate", str(big), "--at", str(points), "-o", str(Path(tmp) / "limit.csv")],
                        ["interpolate", str(big), "--max-iter", "0", "-o", str(Path(tmp) / "fit.obj")]]:
            code, tty = run_on_pty([subdiv, *command], every_step)
            shares = re.findall(r"reading [^\r]*\] +(\d+)%", tty)
            if code != 0 or not any(0 < int(share) < 100 for share in shares):
                failures.append(f"subdiv {command[0]}: exit {code}, no reading bar between 0 and 100% in {tty!r}")
        # evaluate writes its meshes (--samples, --adaptive) with the writing bar.
        for mode in [["--samples", "2"], ["--adaptive", "1"]]:
            out = Path(tmp) / f"sampled{mode[0]}.obj"
            code, tty = run_on_pty([subdiv, "evaluate", str(big), *mode, "-o", str(out)], every_step)
            shares = re.findall(r"writing [^\r]*\] +(\d+)%", tty)
            if code != 0 or not any(0 < int(share) < 100 for share in shares):
                failures.append(f"subdiv evaluate {mode[0]}: exit {code}, no writing bar between 0 and 100% in {tty!r}")
        # The long work between reading and writing has its own bar, moving between its ends:
        # sampling the limit, refining adaptively (each level's choice and refinement, then the
        # limit points), evaluating many points.
        many = Path(tmp) / "many.csv"
        many.write_text("face,u,v\n" + "".join(f"{f % 48},0.25,0.75\n" for f in range(20000)))
        for mode, phase in [(["--samples", "40"], "sampling the limit surface, 40 x 40 per face"),
                            (["--adaptive", "6", "--limit"], "refining adaptively to level 6"),
                            (["--at", str(many)], "evaluating 20000 points")]:
            out = Path(tmp) / ("many-limit.csv" if mode[0] == "--at" else "long.vtp")
            code, tty = run_on_pty([subdiv, "evaluate", str(mesh), *mode, "-o", str(out)], every_step)
            shares = re.findall(re.escape(phase) + r"  \[[^\r]*\] +(\d+)%", tty)
            if code != 0 or not any(0 < int(share) < 100 for share in shares):
                failures.append(f"subdiv evaluate {mode[0]}: exit {code}, no bar between 0 and 100% while "
                                f"{phase!r}: {tty!r}")
        code, tty = run_on_pty([subdiv, "refine", str(mesh), "--adaptive", "6", "--limit", "-o",
                                str(Path(tmp) / "adaptive.vtp")], every_step)
        shares = re.findall(r"refining adaptively to level 6  \[[^\r]*\] +(\d+)%", tty)
        if code != 0 or not any(0 < int(share) < 100 for share in shares):
            failures.append(f"subdiv refine --adaptive: exit {code}, no bar between 0 and 100%: {tty!r}")
        # The bar moves within a level: the quad B-spline of degree 7 has 4 passes per level
        # (a split and 3 smoothing passes), each told (engine/step_progress.h), so the last
        # level's line shows the shares after 1, 2 and 3 of its passes (and the one it started at).
        smooth = [subdiv, "refine", str(mesh), "-s", "quad-bspline", "--param", "d=7", "-l", "4", "-o",
                  str(Path(tmp) / "smooth.obj")]
        code, tty = run_on_pty(smooth, every_step)
        inside = set(re.findall(r"level 4/4: [^\r]*\] +(\d+)%", tty))
        if code != 0 or len([s for s in inside if 0 < int(s) < 100]) < 3:
            failures.append(f"quad-bspline d=7: exit {code}; the last level's bar stood at {sorted(inside)}, "
                            f"expected at least 3 shares within it: {tty!r}")
        piped = subprocess.run(refine, capture_output=True, text=True)
        if piped.returncode != 0 or "\r" in piped.stderr or "%" in piped.stderr:
            failures.append(f"with stderr a pipe: exit {piped.returncode}, stderr {piped.stderr!r} (expected no bar)")
    for f in failures:
        print(f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
